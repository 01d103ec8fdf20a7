#include "web/wasm/web_convert.h"

#include "scenefile/convert.h"
#include "scenefile/format.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/sfconvert/conversion_options.h"
#include "web/wasm/json_text.h"
#include "web/wasm/module_threads.h"

namespace web {

WebConversion convertText(std::string_view text, const std::string& name, const std::string& to,
                          const std::string& materialLibrary) {
  WebConversion conversion;
  conversion.diagnostics = "[]";
  const scene::FormatInfo* format = scene::findFormatByName(to);
  if (!format || !format->write) return conversion;
  conversion.binary = format->binary;
  tools::SfconvertOptions flags;  // sfconvert's defaults: no flag given
  flags.to = to;
  scene::ReadResult result = scene::parseScene(text, name, moduleReadOptions());
  // Only an .obj's side file is asked for: the page's .gltf embeds its buffer.
  std::string sideFile = format->format == scene::Format::Obj ? materialLibrary : "";
  if (result.ok()) {
    std::optional<scene::ConvertedFiles> converted = scene::convertSceneToFiles(
        result.scene, format->format,
        tools::conversionOptionsFor(flags, sideFile.empty(), sideFile), result.diagnostics);
    if (converted) {
      conversion.output = std::move(converted->main);
      conversion.materialLibrary = std::move(converted->sidecar);
    }
  }
  conversion.diagnostics = jsonText(tools::diagnosticsToJson(result.diagnostics));
  return conversion;
}

}  // namespace web
