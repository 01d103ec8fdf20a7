// The source lines that diagnostics point at, quoted under the message with
// a caret under the span, as clang and GCC do:
//
//   scene.sf:3:5: error: 'nan' is not a number [invalid-number]
//       3 | 1 0 nan
//         |     ^~~
//
// The lines are copied out of the source when it is read, so that a tool can
// free a large input before it prints (sfconvert does, before it converts).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scenefile/diagnostic.h"
#include "tools/common/terminal_style.h"

namespace tools {

// One quoted line, or the part of it around a column when the line is long.
struct SourceLine {
  std::string text;               // the bytes, without the line's end
  std::uint32_t firstColumn = 1;  // the column of text[0] in the whole line
  bool cutBefore = false;         // the line goes on before text
  bool cutAfter = false;          // and after it
};

class SourceExcerpts {
 public:
  // Copies from `text`, the source named `file`, the lines that the
  // diagnostics of `list` about that file, their notes and fix-its point at.
  // A line of bytes rather than text (a .glb, garbage) is left out: no
  // quote of it would help. A byte-order mark is not quoted either, since
  // the readers' columns count from after it.
  void capture(std::string_view file, std::string_view text, const scene::DiagnosticList& list);

  // The line of `file` holding `span`, or nothing when it was not captured.
  const SourceLine* find(std::string_view file, const scene::SourceSpan& span) const;

 private:
  // By file, line and the column whose window was copied.
  std::map<std::pair<std::string, std::pair<std::uint32_t, std::uint32_t>>, SourceLine> lines_;
};

// The lines that quote `line` (line number `lineNumber`) under a diagnostic:
// the source line behind a gutter, a caret line under `span`, and, when
// `fixIt` is on the same line, the replacement under what it replaces. Tabs
// expand to 8 columns and bytes that cannot be shown as they are print as
// \xNN, with the caret still under the byte it points at.
std::vector<std::string> quoteSourceLine(const SourceLine& line, const scene::SourceSpan& span,
                                         const scene::FixIt* fixIt, const TerminalStyle& style);

}  // namespace tools
