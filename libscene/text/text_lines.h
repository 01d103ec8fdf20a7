// The lexical layer both formats share: lines (LF or CRLF, an optional UTF-8
// byte-order mark at the start) split into blank-separated tokens.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "scenefile/diagnostic.h"

namespace scene {

struct Token {
  std::string_view text;
  std::uint32_t column = 0;  // 1-based byte column

  SourceSpan span(std::uint32_t line) const {
    return SourceSpan{line, column, static_cast<std::uint32_t>(text.size())};
  }
};

// Walks a text line by line. A line keeps at most kMaxTokens tokens (no valid
// line has more than five) but counts all of them, so that a hostile line of
// a billion tokens costs no memory.
class LineCursor {
 public:
  static constexpr std::size_t kMaxTokens = 16;

  // `firstLine`: the number of the text's first line, for a text that is a
  // part of a larger one (its lines counted from 1 otherwise).
  explicit LineCursor(std::string_view text, std::uint32_t firstLine = 1);

  // Moves to the next line; false once the text is used up.
  bool next() {
    if (!nextLine()) return false;
    tokenize();
    return true;
  }

  // The same in two steps, for a reader that reads most lines from line()
  // in one pass and splits only the others into tokens: until tokenize(),
  // the line counts as blank and has no invalid byte.
  bool nextLine();
  void tokenize();

  // The text from where the next line starts, for a reader that reads a
  // line itself; then passLine(length, next) moves to that line as
  // nextLine() would, `length` its bytes without the line break and `next`
  // where the line after it starts, without looking for the line's end again.
  std::string_view rest() const { return text_.substr(offset_); }
  void passLine(std::size_t length, std::size_t next);

  std::uint32_t lineNumber() const { return lineNumber_; }
  std::string_view line() const { return line_; }
  bool blank() const { return tokenCount_ == 0; }
  // Every token on the line, the stored ones being the first kMaxTokens.
  std::size_t tokenCount() const { return tokenCount_; }
  const Token& token(std::size_t i) const { return tokens_[i]; }
  std::size_t storedTokens() const { return tokenCount_ < kMaxTokens ? tokenCount_ : kMaxTokens; }

  // The first byte that is neither printable ASCII nor a tab, if any.
  std::optional<std::uint32_t> invalidByteColumn() const { return invalidByteColumn_; }
  unsigned char invalidByte() const { return invalidByte_; }

  // Drops what stands from the invalid byte on, so that a reader can go on
  // with the start of a damaged line instead of losing the whole of it.
  void cutAtInvalidByte();

  // A span just past the last character of the line, for "expected more".
  SourceSpan endOfLine() const;
  SourceSpan tokenSpan(std::size_t i) const { return tokens_[i].span(lineNumber_); }
  // The span from the first to the last stored token.
  SourceSpan lineSpan() const;

 private:
  std::string_view text_;
  std::size_t offset_ = 0;
  std::uint32_t lineNumber_ = 0;
  std::string_view line_;
  std::array<Token, kMaxTokens> tokens_{};
  std::size_t tokenCount_ = 0;
  std::optional<std::uint32_t> invalidByteColumn_;
  unsigned char invalidByte_ = 0;
};

// Says, in words, what an invalid byte is: "NUL byte", "byte 0xC3 (not ASCII)".
std::string describeInvalidByte(unsigned char byte);

}  // namespace scene

namespace scene {

// The first word of the text that is not on a blank line or a line starting
// like a comment (# or //): what the line-based formats are recognised by.
// Nothing when the text has no such line.
std::optional<std::string_view> firstWordOutsideComments(std::string_view text);

// Lines and columns (1-based, in bytes) of byte offsets into a text, for a
// reader that knows where something is by its offset (a JSON parser's). Asked
// in increasing order, the offsets cost one pass over the text in all, by
// memchr from line end to line end.
class LineColumnCounter {
 public:
  explicit LineColumnCounter(std::string_view text) : text_(text) {}

  // The span, of no length, at byte `byte` (the end of the text past it).
  SourceSpan at(std::size_t byte);

 private:
  std::string_view text_;
  std::size_t scanned_ = 0;    // every newline before this offset is counted
  std::size_t lineStart_ = 0;  // the offset of the line scanned_ is on
  std::uint32_t line_ = 1;
};

// Whether `text` starts with `prefix`, which is in upper case, in any case.
bool startsWithIgnoringCase(std::string_view text, std::string_view prefix);

}  // namespace scene
