#include "web/wasm/web_render.h"

#include <emscripten/heap.h>
#include <malloc.h>

#include <algorithm>
#include <new>
#include <nlohmann/json.hpp>

#include "renderer/default_scene.h"
#include "renderer/render.h"
#include "scenefile/convert.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/document_check.h"
#include "web/wasm/json_text.h"
#include "web/wasm/module_threads.h"

namespace web {
namespace {

using nlohmann::json;

// --adaptive's threshold for `adaptive: true`: the one sfrender --help
// suggests to start with, and sfbuild's last level's.
constexpr double kDefaultAdaptiveThreshold = 0.03;

// What the module's memory can still give: what it may grow by, and what
// its heap holds free. The render's memory check (render_memory.h) weighs
// a render against this, as sfrender weighs it against the machine's.
std::uint64_t availableMemory() {
  std::uint64_t grown = emscripten_get_heap_size();
  std::uint64_t most = emscripten_get_heap_max();
  struct mallinfo heap = mallinfo();
  return (most > grown ? most - grown : 0) + static_cast<std::uint64_t>(heap.fordblks);
}

// Reads the options of the web API, which are sfrender's flags as JSON
// but for adaptive (false, true or the threshold), into `a`.
sfls::Refusal readOptions(const std::string& optionsJson, sfls::RenderArguments& a) {
  json options = json::parse(optionsJson, nullptr, false);
  if (options.is_discarded() || !(options.is_object() || options.is_null())) {
    return "the options are not a JSON object such as {\"width\": 800}";
  }
  if (options.is_null()) return std::nullopt;
  std::optional<bool> adaptive;
  if (auto found = options.find("adaptive"); found != options.end() && found->is_boolean()) {
    adaptive = found->get<bool>();
    options.erase(found);
  }
  if (options.contains("output")) return "unknown option 'output'";
  if (sfls::Refusal refusal = sfls::readRenderArguments(options, a)) return refusal;
  if (adaptive) a.settings.adaptiveThreshold = *adaptive ? kDefaultAdaptiveThreshold : 0.0;
  return std::nullopt;
}

// The threads a band uses: those asked for, at most the module's.
int bandThreads(int asked) {
  return asked > 0 ? std::min(asked, moduleThreads()) : moduleThreads();
}

}  // namespace

RenderSession::RenderSession(std::string_view text, const std::string& name,
                             const std::string& optionsJson) {
  scene::ReadOptions read = moduleReadOptions();
  sfls::Refusal refusal = readOptions(optionsJson, arguments_);
  tools::DocumentCheck check = tools::checkDocument(text, name, {}, read);
  result_ = std::move(check.result);
  if (!result_.ok()) {
    error_ = sfls::firstRenderError(result_.diagnostics);
    return;
  }
  if (refusal) {
    error_ = *refusal;
    return;
  }
  arguments_.settings.threads = bandThreads(arguments_.settings.threads);
  settings_ = sfls::renderSettingsFor(arguments_, result_.scene);
  if (sfls::Refusal tooMuch = sfls::renderResourceRefusal(settings_, result_.scene,
                                                          settings_.threads, availableMemory())) {
    error_ = *tooMuch;
    return;
  }
  try {
    // The tree's kind by the whole image's samples, as sfrender chooses it.
    compiled_ = std::make_unique<render::RenderScene>(result_.scene, settings_.threads, true,
                                                      render::fullImageSampleCount(settings_));
  } catch (const std::bad_alloc&) {
    error_ = "the render ran out of memory";
  }
}

std::string RenderSession::statusJson() const {
  bool ok = error_.empty();
  json status = {{"ok", ok},
                 {"diagnostics", tools::diagnosticsToJson(result_.diagnostics)},
                 {"error", ok ? json(nullptr) : json(error_)},
                 {"width", settings_.width},
                 {"height", settings_.height},
                 {"spp", settings_.samplesPerPixel},
                 {"adaptive", settings_.adaptiveThreshold > 0 ? json(settings_.adaptiveThreshold)
                                                              : json(false)},
                 {"depth", settings_.maxDepth},
                 {"fov", settings_.verticalFovDegrees},
                 {"threads", settings_.threads}};
  return jsonText(status);
}

std::optional<render::RenderSettings> RenderSession::settingsWith(
    const std::string& overridesJson) {
  sfls::RenderArguments arguments = arguments_;
  if (sfls::Refusal refusal = readOptions(overridesJson, arguments)) {
    error_ = *refusal;
    return std::nullopt;
  }
  render::RenderSettings settings = sfls::renderSettingsFor(arguments, result_.scene);
  if (sfls::Refusal tooMuch = sfls::renderResourceRefusal(settings, result_.scene, settings.threads,
                                                          availableMemory())) {
    error_ = *tooMuch;
    return std::nullopt;
  }
  return settings;
}

std::optional<std::vector<unsigned char>> RenderSession::renderRows(
    int y0, int y1, const std::string& overridesJson) {
  if (!compiled_) return std::nullopt;
  std::optional<render::RenderSettings> settings = settingsWith(overridesJson);
  if (!settings) return std::nullopt;
  y0 = std::clamp(y0, 0, settings->height);
  y1 = std::clamp(y1, y0, settings->height);
  settings->region = render::PixelRegion{0, y0, settings->width, y1};
  try {
    render::Image image = render::renderImage(*compiled_, *settings);
    std::vector<unsigned char> rgb(image.rgb.size());
    render::eightBitLevels(image.rgb.data(), image.rgb.size(), rgb.data());
    std::vector<unsigned char> rgba(rgb.size() / 3 * 4, 255);
    for (std::size_t i = 0, j = 0; i < rgb.size(); i += 3, j += 4) {
      std::copy_n(&rgb[i], 3, &rgba[j]);
    }
    return rgba;
  } catch (const std::bad_alloc&) {
    error_ = "the render ran out of memory";
    compiled_.reset();
    return std::nullopt;
  }
}

namespace {

// The default scene as a scene file when that format holds it exactly,
// else as an instruction file.
std::pair<std::string, std::string> defaultSceneFile() {
  scene::Scene scene = render::defaultScene();
  scene::ConversionOptions options;
  options.noLoss = true;
  for (scene::Format format : {scene::Format::SceneFile, scene::Format::InstructionFile}) {
    scene::DiagnosticList diagnostics("default");
    if (auto converted = scene::convertSceneToFiles(scene, format, options, diagnostics)) {
      return {converted->main, format == scene::Format::SceneFile ? "default.sf" : "default.txt"};
    }
  }
  return {"", "default.sf"};
}

}  // namespace

std::string defaultSceneText() {
  return defaultSceneFile().first;
}

std::string defaultSceneName() {
  return defaultSceneFile().second;
}

}  // namespace web
