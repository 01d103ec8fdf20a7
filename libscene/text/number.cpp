#include "libscene/text/number.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <system_error>

namespace scene {

namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

// What one pass over a literal learns: how far the grammar reaches, whether
// the text up to there is a whole literal, where its parts stand, and its
// digits read as one integer.
struct LiteralShape {
  bool valid = false;  // the first `length` bytes are a literal
  bool negative = false;
  std::size_t length = 0;  // where the scan stopped: the end, or a byte the grammar rejects
  std::size_t intStart = 0;
  std::size_t intDigits = 0;
  std::size_t fracStart = 0;
  std::size_t fracDigits = 0;
  long long exponent = 0;  // as written after the 'e', saturated
  // Every digit before and after the point as one integer; exact while there
  // are at most 19 of them (it wraps beyond, and is then not used).
  std::uint64_t digits = 0;
};

// Scans `s` from its start as far as the grammar allows.
LiteralShape scanLiteral(std::string_view s) {
  LiteralShape shape;
  const char* text = s.data();
  std::size_t size = s.size();
  std::size_t i = 0;
  if (i < size && (text[i] == '+' || text[i] == '-')) shape.negative = text[i++] == '-';
  std::uint64_t digits = 0;
  shape.intStart = i;
  while (i < size && isDigit(text[i])) digits = digits * 10 + (text[i++] - '0');
  shape.intDigits = i - shape.intStart;
  shape.fracStart = i;
  if (i < size && text[i] == '.') {
    shape.fracStart = ++i;
    while (i < size && isDigit(text[i])) digits = digits * 10 + (text[i++] - '0');
    shape.fracDigits = i - shape.fracStart;
  }
  shape.length = i;
  if (shape.intDigits == 0 && shape.fracDigits == 0) return shape;
  if (i < size && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool negative = false;
    if (i < size && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
    std::size_t expStart = i;
    long long exponent = 0;
    while (i < size && isDigit(text[i])) {
      // Saturate: any exponent this large already decides the outcome.
      exponent = std::min<long long>(exponent * 10 + (text[i] - '0'), 1'000'000'000'000LL);
      ++i;
    }
    shape.length = i;
    if (i == expStart) return shape;
    shape.exponent = negative ? -exponent : exponent;
  }
  shape.valid = true;
  shape.digits = digits;
  return shape;
}

// Checks the grammar of a whole token.
bool isLiteral(std::string_view s) {
  LiteralShape shape = scanLiteral(s);
  return shape.valid && shape.length == s.size();
}

// The decimal exponent of the first significant digit of a valid literal,
// which is enough to tell overflow from underflow.
long long leadingExponent(std::string_view s, const LiteralShape& shape) {
  for (std::size_t k = shape.intStart; k < shape.intStart + shape.intDigits; ++k) {
    if (s[k] != '0') {
      return shape.exponent + static_cast<long long>(shape.intStart + shape.intDigits - k) - 1;
    }
  }
  for (std::size_t k = shape.fracStart; k < shape.fracStart + shape.fracDigits; ++k) {
    if (s[k] != '0') return shape.exponent - static_cast<long long>(k - shape.fracStart) - 1;
  }
  return 0;
}

// Clinger's fast path: when the digits form an integer of at most 2^53 and
// the power of ten is at most 22, both are exact doubles, so one
// multiplication or division, rounded once by IEEE arithmetic, gives the
// correctly rounded value: the bits std::from_chars gives. It needs
// arithmetic done in double precision, which FLT_EVAL_METHOD 0 promises (the
// x87 does not).
constexpr bool kExactDoubleArithmetic = FLT_EVAL_METHOD == 0;
constexpr std::uint64_t kMaxExactInteger = std::uint64_t{1} << 53;
constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr long long kMaxExactPower = 22;

bool fastValue(const LiteralShape& shape, double& value) {
  if (!kExactDoubleArithmetic || shape.intDigits + shape.fracDigits > 19 ||
      shape.digits > kMaxExactInteger) {
    return false;
  }
  long long power = shape.exponent - static_cast<long long>(shape.fracDigits);
  if (power < -kMaxExactPower || power > kMaxExactPower) return false;
  double magnitude = static_cast<double>(shape.digits);
  magnitude =
      power < 0 ? magnitude / kExactPowersOfTen[-power] : magnitude * kExactPowersOfTen[power];
  value = shape.negative ? -magnitude : magnitude;
  return true;
}

// Eight bytes, each `byte`.
constexpr std::uint64_t everyByte(std::uint8_t byte) {
  return std::uint64_t{0x0101010101010101} * byte;
}

// The number that eight decimal digits make, one digit a byte, the first
// in the lowest byte (where a little-endian load puts it), in three steps:
// neighbouring digits are combined into pairs, pairs into fours, fours into
// the whole.
std::uint64_t eightDigitsValue(std::uint64_t digits) {
  std::uint64_t pairs = digits * 10 + (digits >> 8);
  constexpr std::uint64_t kPair = 0x000000FF000000FF;
  return ((pairs & kPair) * (100 + (1000000ULL << 32)) +
          ((pairs >> 16) & kPair) * (1 + (10000ULL << 32))) >>
         32;
}

// Whether `c` ends a number's token: a blank, and a line break where the
// text runs on past the line (parseLeadingNumberInText).
template <bool kLineBreakEnds>
bool endsToken(char c) {
  return c == ' ' || c == '\t' || (kLineBreakEnds && (c == '\n' || c == '\r'));
}

// The literal nearly every token is, read as one word: an optional sign,
// then at most eight digits and points, one point at most, ended as
// endsToken says or by the end of `text`. Nothing here branches on the
// digits, whose varying count makes a loop over the bytes mispredict a few
// times per number. Declines (false) anything else, exponents included, and
// when fewer than nine bytes may be read; the grammar scan then decides. The
// value is exact by the fast path's argument: at most eight digits, at most
// seven of them after the point.
template <bool kLineBreakEnds>
bool readShortLiteral(std::string_view text, std::size_t readable, double& value,
                      std::size_t& length) {
  if constexpr (std::endian::native != std::endian::little || !kExactDoubleArithmetic) {
    return false;
  }
  if (readable < 9) return false;
  bool negative = text.data()[0] == '-';  // readable even when `text` is empty
  std::size_t sign = negative || text.data()[0] == '+';
  std::uint64_t word;
  std::memcpy(&word, text.data() + sign, sizeof word);

  // Classify the bytes, one flag in the high bit of each. Bytes with the high
  // bit set are not ASCII and match nothing; the others are below 0x80, so
  // adding at most 0x80 to each never carries into the next byte.
  constexpr std::uint64_t kHigh = everyByte(0x80);
  constexpr std::uint64_t kLow = everyByte(0x7F);
  std::uint64_t ascii = word & kLow;
  std::uint64_t atLeastZero = ascii + everyByte(0x80 - '0');
  std::uint64_t aboveNine = ascii + everyByte(0x80 - '9' - 1);
  std::uint64_t notPoint = (ascii ^ everyByte('.')) + kLow;
  std::uint64_t digits = atLeastZero & ~aboveNine & ~word & kHigh;
  std::uint64_t points = ~notPoint & ~word & kHigh;
  std::uint64_t others = ~(digits | points) & kHigh;

  // The literal is the bytes before the first other one (all eight if none):
  // others ^ (others - 1) keeps the bits up to that byte's flag. What ends it
  // must end the token too.
  int end = std::countr_zero(others) / 8;
  points &= others ^ (others - 1);
  if ((points & (points - 1)) != 0) return false;  // "1.2.3"
  int digitCount = end - (points != 0);
  std::size_t stop = sign + static_cast<std::size_t>(end);
  bool ended = stop < text.size() ? endsToken<kLineBreakEnds>(text[stop]) : stop == text.size();
  if (digitCount == 0 || !ended) return false;  // ".", "1e5", "1.0f", too long

  // Take the point out, moving the bytes above it down (with no point,
  // `below` is every byte), then shift the digits to the top of the word,
  // which drops what followed them and leaves zeros to lead.
  int point = std::countr_zero(points) / 8;
  std::uint64_t below = (points >> 7) - 1;
  std::uint64_t packed = (word & below) | ((word >> 8) & ~below);
  packed = (packed << (8 * (8 - digitCount))) & everyByte(0x0F);
  int fractionDigits = points != 0 ? end - point - 1 : 0;
  double magnitude =
      static_cast<double>(eightDigitsValue(packed)) / kExactPowersOfTen[fractionDigits];
  value = std::bit_cast<double>(std::bit_cast<std::uint64_t>(magnitude) |
                                (std::uint64_t{negative} << 63));
  length = stop;
  return true;
}

// The value of `literal`, which scanLiteral found valid as a whole: the fast
// path when it applies, std::from_chars otherwise.
ParsedNumber convert(std::string_view literal, const LiteralShape& shape) {
  ParsedNumber result;
  if (fastValue(shape, result.value)) return result;
  std::string_view body = literal;
  if (body.front() == '+') body.remove_prefix(1);  // from_chars takes no '+'
  double value = 0.0;
  auto [ptr, ec] =
      std::from_chars(body.data(), body.data() + body.size(), value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    result.status =
        leadingExponent(literal, shape) >= 0 ? NumberStatus::Overflow : NumberStatus::Underflow;
    return result;
  }
  if (ec != std::errc{} || ptr != body.data() + body.size()) {
    result.status = NumberStatus::Syntax;
    return result;
  }
  result.value = value;
  return result;
}

// parseLeadingNumber for what readShortLiteral declines. Kept out of line:
// inlined, its registers and stack would burden the common case.
template <bool kLineBreakEnds>
[[gnu::noinline]] ParsedNumber parseLeadingLiteral(std::string_view text, std::size_t& length) {
  LiteralShape shape = scanLiteral(text);
  length = shape.length;
  if (!shape.valid) return {0.0, NumberStatus::Syntax};
  // The token goes on past the literal: "1.0f", "1.2.3".
  if (length != text.size() && !endsToken<kLineBreakEnds>(text[length])) {
    return {0.0, NumberStatus::Syntax};
  }
  return convert(text.substr(0, length), shape);
}

}  // namespace

ParsedNumber parseNumber(std::string_view token) {
  // The grammar is checked first: from_chars alone would take "inf", "nan"
  // and a sign after '+'.
  LiteralShape shape = scanLiteral(token);
  if (!shape.valid || shape.length != token.size()) return {0.0, NumberStatus::Syntax};
  return convert(token, shape);
}

ParsedNumber parseLeadingNumber(std::string_view text, std::size_t readable, std::size_t& length) {
  ParsedNumber result;
  if (readShortLiteral<false>(text, readable, result.value, length)) return result;
  return parseLeadingLiteral<false>(text, length);
}

ParsedNumber parseLeadingNumberInText(std::string_view text, std::size_t& length) {
  ParsedNumber result;
  if (readShortLiteral<true>(text, text.size(), result.value, length)) return result;
  return parseLeadingLiteral<true>(text, length);
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
  if (isLiteral(token)) return "";
  // A valid literal followed by letters: "1.0f", "1.0abc".
  std::size_t end = 0;
  while (end < token.size() &&
         (isDigit(token[end]) || token[end] == '.' || token[end] == '+' || token[end] == '-')) {
    ++end;
  }
  if (end > 0 && end < token.size() && isLiteral(token.substr(0, end))) {
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
