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

// The runs of lines that differ. A fix replaces words within lines, so the
// two texts keep every line at its place, and a run is where they differ at
// the same index: found in one pass, however large the text. Texts of
// different line counts are one change between their common start and end:
// correct, if not the least of diffs, with no search whose cost grows with
// the text times the changes.
std::vector<Change> changesBetween(const std::vector<std::string_view>& a,
                                   const std::vector<std::string_view>& b) {
  std::vector<Change> found;
  if (a.size() == b.size()) {
    for (std::size_t i = 0; i < a.size();) {
      if (a[i] == b[i]) {
        ++i;
        continue;
      }
      std::size_t end = i;
      while (end < a.size() && a[end] != b[end]) ++end;
      found.push_back({i, end - i, i, end - i});
      i = end;
    }
    return found;
  }
  const std::size_t shorter = std::min(a.size(), b.size());
  std::size_t prefix = 0;
  while (prefix < shorter && a[prefix] == b[prefix]) ++prefix;
  std::size_t suffix = 0;
  while (suffix < shorter - prefix && a[a.size() - 1 - suffix] == b[b.size() - 1 - suffix]) {
    ++suffix;
  }
  found.push_back({prefix, a.size() - prefix - suffix, prefix, b.size() - prefix - suffix});
  return found;
}

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
  std::vector<Change> changes = changesBetween(a, b);
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
