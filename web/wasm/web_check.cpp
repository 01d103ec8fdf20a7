#include "web/wasm/web_check.h"

#include <nlohmann/json.hpp>

#include "scenefile/format.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/document_check.h"
#include "web/wasm/json_text.h"
#include "web/wasm/module_threads.h"

namespace web {

std::string checkJson(std::string_view text, const std::string& name) {
  scene::ReadOptions options = moduleReadOptions();
  // The page's text is in no folder: an instruction file's OUTPUT_FILE is
  // taken as sfcheck takes standard input's, in the current folder.
  tools::DocumentCheck check = tools::checkDocument(text, name, {}, options);
  nlohmann::json format = nullptr;
  // sfcheck names no format for a file it refuses unread by its size.
  if (check.format && text.size() <= options.maxFileSize) {
    format = std::string(scene::formatInfo(*check.format).name);
  }
  nlohmann::json answer = {{"format", format},
                           {"diagnostics", tools::diagnosticsToJson(check.result.diagnostics)}};
  return jsonText(answer);
}

std::string formatsJson() {
  nlohmann::json rows = nlohmann::json::array();
  for (const scene::FormatInfo& row : scene::formats()) {
    nlohmann::json extensions = nlohmann::json::array();
    for (std::string_view extension : row.extensions) extensions.push_back(std::string(extension));
    rows.push_back({{"name", std::string(row.name)},
                    {"description", std::string(row.singular)},
                    {"extensions", extensions},
                    {"reads", row.read != nullptr},
                    {"writes", row.write != nullptr},
                    {"binary", row.binary}});
  }
  return jsonText(rows);
}

}  // namespace web
