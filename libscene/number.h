// Numbers as both formats write them: decimal literals read with correct
// rounding, and written as the shortest text that reads back to the same bits.
#pragma once

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

// Why `token` (which parseNumber rejected as Syntax) is not a number, in
// words for a diagnostic: "hexadecimal numbers are not allowed", ...
std::string numberSyntaxReason(std::string_view token);

// The shortest decimal text that parseNumber reads back to the same bits.
void appendNumber(std::string& out, double value);
std::string formatNumber(double value);

}  // namespace scene
