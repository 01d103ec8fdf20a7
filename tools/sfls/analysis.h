// What the language server knows of one version of a document once it has
// been checked: sfcheck's diagnostics, the scene read from it, its outline.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "scenefile/outline.h"
#include "scenefile/read.h"

namespace sfls {

struct Analysis {
  // The document version that was checked, and its text.
  std::int64_t version = 0;
  std::shared_ptr<const std::string> text;
  // The format recognised from the content; nothing for text in none.
  std::optional<scene::Format> format;
  // The scene and exactly sfcheck's diagnostics (tools::checkDocument).
  scene::ReadResult result;
  scene::Outline outline;
  // How long the check took, for sfls --verbose.
  double seconds = 0;
};

// sfcheck's check of `text` (tools::checkDocument), shown as `shownName`,
// with OUTPUT_FILE taken in `folder`, and its outline; `version` is the
// document's. Once options.stop is requested the check ends early with a
// partial result, and no outline.
std::shared_ptr<Analysis> analyseText(std::shared_ptr<const std::string> text, std::int64_t version,
                                      const std::string& shownName,
                                      const std::filesystem::path& folder,
                                      const scene::ReadOptions& options);

}  // namespace sfls
