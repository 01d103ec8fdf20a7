// Numbers as both formats write them: decimal literals read with correct
// rounding, and written as the shortest text that reads back to the same bits.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace scene {

enum class NumberStatus {
  Ok,
  Syntax,     // not a decimal literal
  Overflow,   // magnitude above the largest double
  Underflow,  // non-zero digits that round to zero
};

struct ParsedNumber {
  double value = 0.0;
  NumberStatus status = NumberStatus::Ok;
};

// Reads a whole token as `[+-]?(digits[.digits?]|.digits)([eE][+-]?digits)?`.
ParsedNumber parseNumber(std::string_view token);

// Reads the token at the start of `text`, which a space, a tab or the end of
// `text` ends, as parseNumber does, and sets `length` to its length: for a
// reader that splits a line and reads its numbers in one pass. A token that
// goes on past the literal ("1.0f") is Syntax, and `length` then says only
// where the literal stopped. `readable` (at least text.size()) is how many
// bytes from text.data() on may be read: where the text goes on a few bytes
// past a short literal, the literal is read a word at a time.
ParsedNumber parseLeadingNumber(std::string_view text, std::size_t readable, std::size_t& length);

// parseLeadingNumber for a reader that reads a line's numbers before it
// knows where the line ends: `text` runs on past the line, and a line break
// ('\n' or '\r') ends the token too.
ParsedNumber parseLeadingNumberInText(std::string_view text, std::size_t& length);

// Why `token` (which parseNumber rejected as Syntax) is not a number, in
// words for a diagnostic: "hexadecimal numbers are not allowed", ...
std::string numberSyntaxReason(std::string_view token);

// The shortest decimal text that parseNumber reads back to the same bits.
void appendNumber(std::string& out, double value);
std::string formatNumber(double value);

}  // namespace scene
