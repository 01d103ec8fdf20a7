#include "tools/sfls/analysis.h"

#include <chrono>

#include "tools/common/document_check.h"

namespace sfls {

std::shared_ptr<Analysis> analyseText(std::shared_ptr<const std::string> text, std::int64_t version,
                                      const std::string& shownName,
                                      const std::filesystem::path& folder,
                                      const scene::ReadOptions& options) {
  auto start = std::chrono::steady_clock::now();
  tools::DocumentCheck check = tools::checkDocument(*text, shownName, folder, options);
  auto analysis = std::make_shared<Analysis>();
  analysis->version = version;
  analysis->text = std::move(text);
  analysis->format = check.format;
  analysis->result = std::move(check.result);
  if (options.stop.stop_requested()) return analysis;
  if (check.format == scene::Format::SceneFile || check.format == scene::Format::InstructionFile) {
    analysis->outline = scene::outlineOf(*analysis->text, *check.format);
  }
  analysis->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return analysis;
}

}  // namespace sfls
