/// @file
/// The source lines that diagnostics point at, kept to be quoted under the
/// message with a caret under the span, as clang and GCC do:
///
///     scene.sf:3:5: error: 'nan' is not a number [invalid-number]
///         3 | 1 0 nan
///           |     ^~~
///
/// The lines are copied out of the source when it is read, so that a caller
/// can free a large input before it prints (a converter does, before it
/// converts).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>

#include "scenefile/diagnostic.h"

namespace scene {

/// One quoted line, or the part of it around a column when the line is long.
struct SourceLine {
  std::string text;               ///< the bytes, without the line's end
  std::uint32_t firstColumn = 1;  ///< the column of text[0] in the whole line
  bool cutBefore = false;         ///< the line goes on before text
  bool cutAfter = false;          ///< and after it
};

/// The lines of one or more sources that diagnostics quote
/// (formatDiagnostics in scenefile/diagnostic_format.h).
class SourceExcerpts {
 public:
  /// Copies from `text`, the source named `file`, the lines that the
  /// diagnostics of `list` about that file, their notes and fix-its point at.
  /// A line of bytes rather than text (a .glb, garbage) is left out: no
  /// quote of it would help. A byte-order mark is not quoted either, since
  /// the readers' columns count from after it.
  void capture(std::string_view file, std::string_view text, const DiagnosticList& list);

  /// The line of `file` holding `span`, or nothing when it was not captured.
  const SourceLine* find(std::string_view file, const SourceSpan& span) const;

 private:
  // By file, line and the column whose window was copied.
  std::map<std::pair<std::string, std::pair<std::uint32_t, std::uint32_t>>, SourceLine> lines_;
};

}  // namespace scene
