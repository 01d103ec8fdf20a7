// What the canonical layouts of both line formats share: the text's byte-
// order mark and line ending kept, lines of words joined by one space.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "libscene/text/text_lines.h"

namespace scene {

class LineLayout {
 public:
  // Keeps `text`'s byte-order mark and the line ending of its first line.
  explicit LineLayout(std::string_view text);

  // The cursor's line, its words joined by one space after `indent` levels of
  // two spaces; `keywords[i]`, where not empty, replaces word i (a keyword
  // in its canonical case). False, and nothing written, for a line with more
  // words than a cursor keeps or whose last word ends in a carriage return.
  bool line(const LineCursor& cursor, std::size_t indent, std::string_view keywords[3] = nullptr);

  // A blank line, unless nothing has been written yet.
  void blankLine();

  std::string take() { return std::move(out_); }

 private:
  std::string out_;
  std::string_view newline_;
  std::size_t bom_ = 0;
};

}  // namespace scene
