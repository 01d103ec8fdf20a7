#include "scenefile/fix_its.h"

#include <algorithm>
#include <cstring>

namespace scene {

namespace {

bool before(const SourceSpan& a, const SourceSpan& b) {
  return a.line != b.line ? a.line < b.line : a.column < b.column;
}

// Two spans on one line share a byte, or insert at the same place (whose
// order no rule decides).
bool overlap(const SourceSpan& a, const SourceSpan& b) {
  if (a.line != b.line) return false;
  if (a.column == b.column) return true;
  const SourceSpan& first = a.column < b.column ? a : b;
  const SourceSpan& second = a.column < b.column ? b : a;
  return first.column + first.length > second.column;
}

}  // namespace

std::vector<FixIt> applicableFixIts(const DiagnosticList& diagnostics) {
  std::vector<FixIt> all;
  for (const Diagnostic& d : diagnostics.items()) {
    if (d.fixIt && d.fixIt->span.known()) all.push_back(*d.fixIt);
  }
  // Stable: of two that overlap, the one reported first is kept.
  std::stable_sort(all.begin(), all.end(),
                   [](const FixIt& a, const FixIt& b) { return before(a.span, b.span); });
  std::vector<FixIt> kept;
  for (FixIt& fixIt : all) {
    bool clashes = std::any_of(kept.begin(), kept.end(),
                               [&](const FixIt& k) { return overlap(k.span, fixIt.span); });
    if (!clashes) kept.push_back(std::move(fixIt));
  }
  return kept;
}

std::string applyFixIts(std::string_view text, std::span<const FixIt> fixIts) {
  std::string out;
  out.reserve(text.size());
  // Columns count from the start of a line; a byte-order mark belongs to no
  // column, as the readers count them.
  std::size_t lineStart = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  std::size_t copied = 0;  // text[0, copied) is in `out`
  std::uint32_t line = 1;
  std::size_t next = 0;  // the next fix-it to apply
  while (next < fixIts.size() && lineStart <= text.size()) {
    const char* newline = static_cast<const char*>(
        std::memchr(text.data() + lineStart, '\n', text.size() - lineStart));
    std::size_t end = newline ? static_cast<std::size_t>(newline - text.data()) : text.size();
    std::size_t contentEnd = end > lineStart && text[end - 1] == '\r' ? end - 1 : end;
    std::size_t lineLength = contentEnd - lineStart;
    for (; next < fixIts.size() && fixIts[next].span.line <= line; ++next) {
      const SourceSpan& span = fixIts[next].span;
      if (span.line != line || span.column == 0) continue;
      std::size_t from = span.column - 1;
      if (from > lineLength || span.length > lineLength - from) continue;
      std::size_t at = lineStart + from;
      if (at < copied) continue;  // out of order or overlapping: not applied
      out.append(text.substr(copied, at - copied));
      out.append(fixIts[next].replacement);
      copied = at + span.length;
    }
    if (!newline) break;
    lineStart = end + 1;
    ++line;
  }
  out.append(text.substr(copied));
  return out;
}

}  // namespace scene
