#include "web/wasm/charconv_compat.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace charconv_compat {
namespace {

char lower(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

// Whether [p, last) starts with `word`, in any case.
bool startsWithWord(const char* p, const char* last, const char* word) {
  std::size_t n = std::strlen(word);
  if (static_cast<std::size_t>(last - p) < n) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (lower(p[i]) != word[i]) return false;
  }
  return true;
}

bool isDigit(char c, Syntax syntax) {
  if (c >= '0' && c <= '9') return true;
  return syntax == Syntax::Hex && lower(c) >= 'a' && lower(c) <= 'f';
}

// "inf", "infinity", "nan" or "nan(chars)" at p; `negative` gives the sign.
Parsed parseSpecial(const char* first, const char* p, const char* last, bool negative) {
  Parsed parsed{first, 0.0, ParseStatus::Invalid};
  if (startsWithWord(p, last, "inf")) {
    parsed.end = p + (startsWithWord(p, last, "infinity") ? 8 : 3);
    parsed.value = negative ? -HUGE_VAL : HUGE_VAL;
    parsed.status = ParseStatus::Ok;
  } else if (startsWithWord(p, last, "nan")) {
    parsed.end = p + 3;
    const char* q = parsed.end;
    if (q != last && *q == '(') {
      ++q;
      while (q != last && (isDigit(*q, Syntax::Decimal) || (lower(*q) >= 'a' && lower(*q) <= 'z') ||
                           *q == '_')) {
        ++q;
      }
      if (q != last && *q == ')') parsed.end = q + 1;
    }
    parsed.value = negative ? -std::nan("") : std::nan("");
    parsed.status = ParseStatus::Ok;
  }
  return parsed;
}

}  // namespace

Parsed parseDouble(const char* first, const char* last, Syntax syntax) {
  const char* p = first;
  bool negative = p != last && *p == '-';
  if (negative) ++p;
  if (p != last && (lower(*p) == 'i' || lower(*p) == 'n')) {
    return parseSpecial(first, p, last, negative);
  }
  const char* start = p;
  std::size_t digits = 0;
  bool nonZero = false;
  for (; p != last && isDigit(*p, syntax); ++p, ++digits) nonZero |= *p != '0';
  if (p != last && *p == '.') {
    for (++p; p != last && isDigit(*p, syntax); ++p, ++digits) nonZero |= *p != '0';
  }
  if (digits == 0) return {first, 0.0, ParseStatus::Invalid};
  // An exponent is taken only with its digits: "1e" is 1 and stops at 'e'.
  char mark = syntax == Syntax::Hex ? 'p' : 'e';
  if (p != last && lower(*p) == mark) {
    const char* q = p + 1;
    if (q != last && (*q == '+' || *q == '-')) ++q;
    if (q != last && isDigit(*q, Syntax::Decimal)) {
      while (q != last && isDigit(*q, Syntax::Decimal)) ++q;
      p = q;
    }
  }
  std::string text = negative ? "-" : "";
  if (syntax == Syntax::Hex) text += "0x";
  text.append(start, p);
  double value = std::strtod(text.c_str(), nullptr);
  bool outOfRange = std::isinf(value) || (value == 0 && nonZero);
  return {p, value, outOfRange ? ParseStatus::OutOfRange : ParseStatus::Ok};
}

namespace {

// A decimal d.ddd x 10^exponent, the digits without the point.
struct Decimal {
  std::string digits;
  int exponent = 0;
};

// `value` (positive, finite) rounded to `precision` significant digits.
Decimal rounded(double value, int precision) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*e", precision - 1, value);
  Decimal d;
  const char* p = text;
  for (; *p != 'e'; ++p) {
    if (*p != '.') d.digits += *p;
  }
  d.exponent = std::atoi(p + 1);
  return d;
}

double valueOf(const Decimal& d) {
  std::string text =
      d.digits + "e" + std::to_string(d.exponent - static_cast<int>(d.digits.size()) + 1);
  return std::strtod(text.c_str(), nullptr);
}

// The next decimal up with as many digits: 1.29 -> 1.30, 9.99 -> 10.0.
Decimal nextUp(Decimal d) {
  std::size_t i = d.digits.size();
  while (i > 0 && d.digits[i - 1] == '9') d.digits[--i] = '0';
  if (i == 0) {
    d.digits.insert(d.digits.begin(), '1');
    d.digits.pop_back();
    ++d.exponent;
  } else {
    ++d.digits[i - 1];
  }
  return d;
}

// The shortest decimal that reads back to `value` (positive, finite), the
// closest to it of those. The correctly rounded one of each length is the
// closest; only where the interval that reads back is lopsided (a power of
// two, whose lower neighbour is nearer) may it miss on the near side while
// the next one up lies within.
Decimal shortest(double value) {
  bool powerOfTwo = (std::bit_cast<std::uint64_t>(value) & ((std::uint64_t{1} << 52) - 1)) == 0 &&
                    value >= 2 * 2.2250738585072014e-308;
  for (int precision = 1; precision < 17; ++precision) {
    Decimal d = rounded(value, precision);
    double back = valueOf(d);
    if (back == value) return d;
    if (powerOfTwo && back < value) {
      Decimal up = nextUp(d);
      if (valueOf(up) == value) return up;
    }
  }
  return rounded(value, 17);
}

std::string scientific(const Decimal& d) {
  std::string text(1, d.digits[0]);
  if (d.digits.size() > 1) text += "." + d.digits.substr(1);
  int e = std::abs(d.exponent);
  text += d.exponent < 0 ? "e-" : "e+";
  if (e < 10) text += '0';
  return text + std::to_string(e);
}

std::string fixed(const Decimal& d) {
  int length = static_cast<int>(d.digits.size());
  if (d.exponent < 0) return "0." + std::string(-d.exponent - 1, '0') + d.digits;
  if (length <= d.exponent + 1) return d.digits + std::string(d.exponent + 1 - length, '0');
  return d.digits.substr(0, d.exponent + 1) + "." + d.digits.substr(d.exponent + 1);
}

char* copyOut(char* first, char* last, const std::string& text) {
  if (static_cast<std::size_t>(last - first) < text.size()) return nullptr;
  std::memcpy(first, text.data(), text.size());
  return first + text.size();
}

std::string special(double value) {
  if (std::isnan(value)) return std::signbit(value) ? "-nan" : "nan";
  if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
  return std::signbit(value) ? "-0" : "0";
}

}  // namespace

char* writeShortest(char* first, char* last, double value) {
  if (!std::isfinite(value) || value == 0) return copyOut(first, last, special(value));
  Decimal d = shortest(std::fabs(value));
  while (d.digits.size() > 1 && d.digits.back() == '0') d.digits.pop_back();
  std::string f = fixed(d);
  std::string s = scientific(d);
  if (f.size() > s.size()) return copyOut(first, last, (value < 0 ? "-" : "") + s);
  // An integer in fixed notation beyond its shortest digits is written
  // exactly, as libstdc++ writes it: 2^57 is 144115188075855872, not
  // 144115188075855870.
  if (d.exponent + 1 > static_cast<int>(d.digits.size())) {
    char exact[32];
    std::snprintf(exact, sizeof exact, "%.0f", value);
    return copyOut(first, last, exact);
  }
  return copyOut(first, last, (value < 0 ? "-" : "") + f);
}

char* writeHex(char* first, char* last, double value) {
  if (!std::isfinite(value) || value == 0) {
    return copyOut(first, last, std::isfinite(value) ? special(value) + "p+0" : special(value));
  }
  std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
  std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
  int biased = static_cast<int>((bits >> 52) & 0x7ff);
  int exponent = biased == 0 ? -1022 : biased - 1023;
  char digits[16];
  std::snprintf(digits, sizeof digits, "%013llx", static_cast<unsigned long long>(mantissa));
  std::string fraction = digits;
  while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
  std::string text = std::signbit(value) ? "-" : "";
  text += biased == 0 ? '0' : '1';
  if (!fraction.empty()) text += "." + fraction;
  text += exponent < 0 ? "p-" : "p+";
  return copyOut(first, last, text + std::to_string(std::abs(exponent)));
}

}  // namespace charconv_compat
