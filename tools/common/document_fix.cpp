#include "tools/common/document_fix.h"

#include <utility>
#include <vector>

#include "scenefile/fix_its.h"

namespace tools {

namespace {

// Rounds enough for a fix-it that waits for another to be applied first;
// a text still changing after them holds fix-its that undo each other.
constexpr int kMostRounds = 8;

}  // namespace

FixedDocument fixDocument(std::string_view text, DocumentCheck checked,
                          const std::string& shownName, const std::filesystem::path& folder,
                          const scene::ReadOptions& options) {
  FixedDocument fixed{std::string(text), std::move(checked), 0};
  for (int round = 0; round < kMostRounds; ++round) {
    std::vector<scene::FixIt> fixIts = scene::applicableFixIts(fixed.check.result.diagnostics);
    if (fixIts.empty()) break;
    std::string next = scene::applyFixIts(fixed.text, fixIts);
    if (next == fixed.text) break;
    fixed.text = std::move(next);
    fixed.applied += fixIts.size();
    fixed.check = checkDocument(fixed.text, shownName, folder, options);
  }
  return fixed;
}

}  // namespace tools
