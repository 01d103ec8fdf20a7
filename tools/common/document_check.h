// The check sfcheck makes of one text, for every front end that shows its
// diagnostics (sfcheck, the language server): the reader's, then where an
// instruction file's OUTPUT_FILE would write, and whether sfrender writes its
// format.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "scenefile/read.h"

namespace tools {

struct DocumentCheck {
  // The format recognised from the content; nothing for text in no format.
  std::optional<scene::Format> format;
  scene::ReadResult result;
};

// Checks `text`, shown as `shownName` in diagnostics. `folder` is where the
// text's file lies, against which OUTPUT_FILE is taken (empty: the current
// folder, as for standard input).
DocumentCheck checkDocument(std::string_view text, const std::string& shownName,
                            const std::filesystem::path& folder, const scene::ReadOptions& options);

}  // namespace tools
