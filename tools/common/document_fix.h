// Every fix-it of a text applied, for a front end that fixes a whole file
// at once (sfcheck --fix); an editor's code action applies one fix-it with
// the same library calls (scenefile/fix_its.h).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "tools/common/document_check.h"

namespace tools {

struct FixedDocument {
  // The text with the fix-its applied, and its check (checkDocument).
  std::string text;
  DocumentCheck check;
  // The fix-its applied, over every round.
  std::size_t applied = 0;
};

// Applies the fix-its of `checked` (the check of `text`), then those the
// fixed text's check has, and so on until none is left or applies: a fix-it
// dropped for overlapping another is applied in the next round, so that
// fixing a fixed file changes nothing. At most a few rounds, in case two
// fix-its undo each other.
FixedDocument fixDocument(std::string_view text, DocumentCheck checked,
                          const std::string& shownName, const std::filesystem::path& folder,
                          const scene::ReadOptions& options);

}  // namespace tools
