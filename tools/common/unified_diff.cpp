#include "tools/common/unified_diff.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tools {

namespace {

// The lines of `text`, each with its newline (the last may have none).
std::vector<std::string_view> linesOf(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    end = end == std::string_view::npos ? text.size() : end + 1;
    lines.push_back(text.substr(start, end - start));
    start = end;
  }
  return lines;
}

// Lines before[at..at+removed) become after[to..to+added).
struct Change {
  std::size_t at = 0;
  std::size_t removed = 0;
  std::size_t to = 0;
  std::size_t added = 0;
};

// How many lines in a row must agree for the texts to meet again: one is
// too few in a scene file, whose matrix rows repeat.
constexpr std::size_t kMeetingLines = 3;
// How far after a difference the texts are looked for to meet again (the
// lines removed and added together); beyond it, the rest is one change.
constexpr std::size_t kSearchLines = 2000;

class LineMatcher {
 public:
  LineMatcher(const std::vector<std::string_view>& a, const std::vector<std::string_view>& b)
      : a_(a), b_(b) {}

  std::vector<Change> changes() const {
    std::vector<Change> found;
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < a_.size() || j < b_.size()) {
      if (i < a_.size() && j < b_.size() && a_[i] == b_[j]) {
        ++i;
        ++j;
        continue;
      }
      Change change = nextMeeting(i, j);
      found.push_back(change);
      i += change.removed;
      j += change.added;
    }
    return found;
  }

 private:
  // Whether the texts agree from a_[i] and b_[j] on for kMeetingLines
  // lines, or end there together.
  bool meet(std::size_t i, std::size_t j) const {
    for (std::size_t t = 0; t < kMeetingLines; ++t, ++i, ++j) {
      if (i == a_.size() && j == b_.size()) return true;
      if (i == a_.size() || j == b_.size() || a_[i] != b_[j]) return false;
    }
    return true;
  }

  // The fewest lines removed and added (removing first) after which the
  // texts meet again.
  Change nextMeeting(std::size_t i, std::size_t j) const {
    std::size_t leftA = a_.size() - i;
    std::size_t leftB = b_.size() - j;
    std::size_t most = std::min(kSearchLines, leftA + leftB);
    for (std::size_t skipped = 1; skipped <= most; ++skipped) {
      for (std::size_t removed = std::min(skipped, leftA) + 1; removed-- > 0;) {
        std::size_t added = skipped - removed;
        if (added > leftB) break;
        if (meet(i + removed, j + added)) return {i, removed, j, added};
      }
    }
    return {i, leftA, j, leftB};
  }

  const std::vector<std::string_view>& a_;
  const std::vector<std::string_view>& b_;
};

// "@@ -START,COUNT +START,COUNT @@" as GNU diff writes it: a count of one
// left out, and an empty side starting at the line before it.
std::string rangeText(std::size_t start, std::size_t count) {
  if (count == 1) return std::to_string(start + 1);
  return std::to_string(count == 0 ? start : start + 1) + "," + std::to_string(count);
}

void appendLine(std::string& out, char mark, std::string_view line) {
  out += mark;
  out += line;
  if (line.empty() || line.back() != '\n') out += "\n\\ No newline at end of file\n";
}

}  // namespace

std::string unifiedDiff(std::string_view before, std::string_view after, std::string_view name,
                        int context) {
  std::vector<std::string_view> a = linesOf(before);
  std::vector<std::string_view> b = linesOf(after);
  std::vector<Change> changes = LineMatcher(a, b).changes();
  if (changes.empty()) return {};
  const std::size_t around = static_cast<std::size_t>(std::max(context, 0));
  std::string out = "--- a/" + std::string(name) + "\n+++ b/" + std::string(name) + "\n";
  for (std::size_t first = 0; first < changes.size();) {
    // The changes whose context joins them make one hunk.
    std::size_t last = first;
    while (last + 1 < changes.size() &&
           changes[last + 1].at - (changes[last].at + changes[last].removed) <= 2 * around) {
      ++last;
    }
    std::size_t startA = changes[first].at - std::min(around, changes[first].at);
    std::size_t startB = changes[first].to - (changes[first].at - startA);
    std::size_t endA = std::min(a.size(), changes[last].at + changes[last].removed + around);
    std::size_t endB =
        changes[last].to + changes[last].added + (endA - changes[last].at - changes[last].removed);
    out += "@@ -" + rangeText(startA, endA - startA) + " +" + rangeText(startB, endB - startB) +
           " @@\n";
    std::size_t i = startA;
    for (std::size_t c = first; c <= last; ++c) {
      for (; i < changes[c].at; ++i) appendLine(out, ' ', a[i]);
      for (std::size_t k = 0; k < changes[c].removed; ++k) appendLine(out, '-', a[i + k]);
      for (std::size_t k = 0; k < changes[c].added; ++k) appendLine(out, '+', b[changes[c].to + k]);
      i += changes[c].removed;
    }
    for (; i < endA; ++i) appendLine(out, ' ', a[i]);
    first = last + 1;
  }
  return out;
}

}  // namespace tools
