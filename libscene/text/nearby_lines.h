// The lines around one place of a text, for what an editor asks about that
// place: a few lines read from where it is, never the whole text.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "libscene/text/text_lines.h"
#include "scenefile/outline.h"

namespace scene {

// Walks the lines before a line, last first. A line is as LineCursor gives
// it: without its line ending, and line 1 without a byte-order mark.
class LinesBefore {
 public:
  // `lineStart`: the offset of line `line`'s first byte.
  LinesBefore(std::string_view text, std::size_t lineStart, std::uint32_t line)
      : text_(text), start_(lineStart), lineNumber_(line) {}

  // Moves to the line before; false at the text's start.
  bool previous();

  std::string_view line() const { return line_; }
  std::uint32_t lineNumber() const { return lineNumber_; }

 private:
  std::string_view text_;
  std::size_t start_;
  std::uint32_t lineNumber_;
  std::string_view line_;
};

// A cursor on line `line` of `text`, which starts at offset `lineStart`,
// tokenized; it goes on to the lines after it.
LineCursor cursorAt(std::string_view text, std::size_t lineStart, std::uint32_t line);

// The first three words of one line, "" where it has fewer; only the first
// `count` are looked for, so that a line's numbers are not scanned for
// words no one needs.
struct LineHead {
  std::string_view first;
  std::string_view second;
  std::string_view third;
};
LineHead lineHead(std::string_view line, int count = 3);

// The words of the cursor's line, and which of them holds `column` (a word
// holds the column just past its end too).
void placeWords(const LineCursor& cursor, std::uint32_t column, TextPlace& place);

}  // namespace scene
