// The floating-point std::from_chars and std::to_chars that libc++ 14 lacks
// (compat/charconv declares them from these), written over the C library's
// correctly rounded strtod and snprintf so that they give, byte for byte,
// what libstdc++ gives natively. Plain functions, compiled natively too, so
// that charconv_compat_test.cpp compares them with libstdc++.
#pragma once

namespace charconv_compat {

enum class Syntax { Decimal, Hex };
enum class ParseStatus { Ok, OutOfRange, Invalid };

struct Parsed {
  const char* end = nullptr;  // past the number; `first` when there is none
  double value = 0;
  ParseStatus status = ParseStatus::Invalid;
};

// std::from_chars(first, last, value, general or hex) as libstdc++ reads:
// an optional '-', then digits with an optional point and exponent (hex:
// hexadecimal digits and an optional 'p' exponent, no "0x"), or "inf",
// "infinity", "nan", "nan(chars)" in any case; correctly rounded. A finite
// number that rounds to infinity, or to zero from non-zero digits, is
// OutOfRange, and then `value` is not to be used.
Parsed parseDouble(const char* first, const char* last, Syntax syntax);

// std::to_chars(first, last, value): the shortest digits that read back to
// `value` (the closest to it of those), in fixed or scientific notation,
// whichever is shorter, fixed on a tie. The end of what was written, or
// nullptr when it does not fit.
char* writeShortest(char* first, char* last, double value);

// std::to_chars(first, last, value, std::chars_format::hex): "1.8p+1".
char* writeHex(char* first, char* last, double value);

}  // namespace charconv_compat
