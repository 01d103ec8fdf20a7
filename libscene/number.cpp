#include "libscene/number.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <system_error>

namespace scene {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Checks the grammar. On success, `leadingExponent` places the first
// significant digit, which is enough to tell overflow from underflow.
struct LiteralShape {
  bool valid = false;
  long long leadingExponent = 0;  // decimal exponent of the first significant digit
};

LiteralShape inspectLiteral(std::string_view s) {
  LiteralShape shape;
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t intStart = i;
  while (i < s.size() && isDigit(s[i])) ++i;
  std::size_t intDigits = i - intStart;
  std::size_t fracDigits = 0;
  std::size_t fracStart = i;
  if (i < s.size() && s[i] == '.') {
    ++i;
    fracStart = i;
    while (i < s.size() && isDigit(s[i])) ++i;
    fracDigits = i - fracStart;
  }
  if (intDigits == 0 && fracDigits == 0) return shape;
  long long exponent = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool negative = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
    std::size_t expStart = i;
    while (i < s.size() && isDigit(s[i])) {
      // Saturate: any exponent this large already decides the outcome.
      exponent = std::min<long long>(exponent * 10 + (s[i] - '0'), 1'000'000'000'000LL);
      ++i;
    }
    if (i == expStart) return shape;
    if (negative) exponent = -exponent;
  }
  if (i != s.size()) return shape;
  shape.valid = true;
  // Position of the first non-zero digit relative to the decimal point.
  for (std::size_t k = intStart; k < intStart + intDigits; ++k) {
    if (s[k] != '0') {
      shape.leadingExponent = exponent + static_cast<long long>(intStart + intDigits - k) - 1;
      return shape;
    }
  }
  for (std::size_t k = fracStart; k < fracStart + fracDigits; ++k) {
    if (s[k] != '0') {
      shape.leadingExponent = exponent - static_cast<long long>(k - fracStart) - 1;
      return shape;
    }
  }
  return shape;
}

}  // namespace

ParsedNumber parseNumber(std::string_view token) {
  ParsedNumber result;
  // The grammar is checked first: from_chars alone would take "inf", "nan"
  // and a sign after '+'.
  LiteralShape shape = inspectLiteral(token);
  if (!shape.valid) {
    result.status = NumberStatus::Syntax;
    return result;
  }
  std::string_view body = token;
  if (body.front() == '+') body.remove_prefix(1);  // from_chars takes no '+'
  double value = 0.0;
  auto [ptr, ec] = std::from_chars(body.data(), body.data() + body.size(), value,
                                   std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    result.status = shape.leadingExponent >= 0 ? NumberStatus::Overflow : NumberStatus::Underflow;
    return result;
  }
  if (ec != std::errc{} || ptr != body.data() + body.size()) {
    result.status = NumberStatus::Syntax;
    return result;
  }
  result.value = value;
  return result;
}

std::string numberSyntaxReason(std::string_view token) {
  std::string lower(token);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  std::string_view body = lower;
  if (!body.empty() && (body.front() == '+' || body.front() == '-')) body.remove_prefix(1);
  if (body.starts_with("nan") || body.starts_with("inf")) {
    return "infinity and not-a-number are not allowed";
  }
  if (body.starts_with("0x")) return "hexadecimal numbers are not allowed";
  if (token.find(',') != std::string_view::npos) return "use '.' as the decimal separator";
  if (inspectLiteral(token).valid) return "";
  // A valid literal followed by letters: "1.0f", "1.0abc".
  std::size_t end = 0;
  while (end < token.size() &&
         (isDigit(token[end]) || token[end] == '.' || token[end] == '+' || token[end] == '-')) {
    ++end;
  }
  if (end > 0 && end < token.size() && inspectLiteral(token.substr(0, end)).valid) {
    return "unexpected '" + std::string(token.substr(end)) + "' after the number";
  }
  return "expected a decimal number";
}

void appendNumber(std::string& out, double value) {
  char buffer[32];
  auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  (void)ec;  // 32 bytes always hold the shortest form of a double
  out.append(buffer, ptr);
}

std::string formatNumber(double value) {
  std::string out;
  appendNumber(out, value);
  return out;
}

}  // namespace scene
