// The web build's std::from_chars and std::to_chars of a double
// (compat/charconv) are charconv_compat's, since libc++ 14 has none: every
// number a scene file holds is read and written by them there. This holds
// them to libstdc++'s, the native build's, bit for bit and byte for byte, so
// that the page reads and writes every number exactly as the tools do.
#include "web/wasm/charconv_compat.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "libscene/testing/random_cases.h"

namespace {

std::string nativeShortest(double value) {
  char text[64];
  auto [end, ec] = std::to_chars(text, text + sizeof text, value);
  return ec == std::errc() ? std::string(text, end) : "(error)";
}

std::string compatShortest(double value) {
  char text[64];
  char* end = charconv_compat::writeShortest(text, text + sizeof text, value);
  return end ? std::string(text, end) : "(error)";
}

std::string nativeHex(double value) {
  char text[64];
  auto [end, ec] = std::to_chars(text, text + sizeof text, value, std::chars_format::hex);
  return ec == std::errc() ? std::string(text, end) : "(error)";
}

std::string compatHex(double value) {
  char text[64];
  char* end = charconv_compat::writeHex(text, text + sizeof text, value);
  return end ? std::string(text, end) : "(error)";
}

// What from_chars makes of `text`: the bits, the length read and the error.
struct Reading {
  std::uint64_t bits = 0;
  std::ptrdiff_t length = 0;
  int error = 0;
  bool operator==(const Reading&) const = default;
};

std::ostream& operator<<(std::ostream& out, const Reading& r) {
  return out << std::hexfloat << std::bit_cast<double>(r.bits) << " after " << r.length << " error "
             << r.error;
}

Reading nativeReading(const std::string& text, std::chars_format format) {
  double value = 12345;  // kept on an error, as the compat one keeps it
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, format);
  return {std::bit_cast<std::uint64_t>(value), end - text.data(), static_cast<int>(ec)};
}

Reading compatReading(const std::string& text, charconv_compat::Syntax syntax) {
  charconv_compat::Parsed parsed =
      charconv_compat::parseDouble(text.data(), text.data() + text.size(), syntax);
  double value = parsed.status == charconv_compat::ParseStatus::Ok ? parsed.value : 12345;
  std::errc ec = parsed.status == charconv_compat::ParseStatus::Ok ? std::errc()
                 : parsed.status == charconv_compat::ParseStatus::OutOfRange
                     ? std::errc::result_out_of_range
                     : std::errc::invalid_argument;
  return {std::bit_cast<std::uint64_t>(value), parsed.end - text.data(), static_cast<int>(ec)};
}

void expectSameWriting(double value) {
  ASSERT_EQ(compatShortest(value), nativeShortest(value)) << std::hexfloat << value;
  ASSERT_EQ(compatHex(value), nativeHex(value)) << std::hexfloat << value;
}

void expectSameReading(const std::string& text) {
  ASSERT_EQ(compatReading(text, charconv_compat::Syntax::Decimal),
            nativeReading(text, std::chars_format::general))
      << text;
}

std::vector<double> edgeCases() {
  std::vector<double> values = {0.0,
                                -0.0,
                                5e-324,
                                -5e-324,
                                DBL_MIN,
                                -DBL_MIN,
                                DBL_MAX,
                                -DBL_MAX,
                                DBL_TRUE_MIN * 3,
                                std::nextafter(DBL_MIN, 0.0),
                                1.0,
                                0.1,
                                0.3,
                                1.0 / 3,
                                2.0 / 3,
                                123456.0,
                                1234567.0,
                                9007199254740992.0,
                                9007199254740993.0,
                                1.2345678901234567e17,
                                5e-7,
                                1e-5,
                                1.5e-5};
  for (int e = -1074; e <= 1023; ++e) values.push_back(std::ldexp(1.0, e));
  for (int e = -323; e <= 308; ++e)
    values.push_back(std::strtod(("1e" + std::to_string(e)).c_str(), nullptr));
  for (int e = 15; e <= 23; ++e) {
    double power = std::strtod(("1e" + std::to_string(e)).c_str(), nullptr);
    for (double v : {power, std::nextafter(power, 0.0), std::nextafter(power, HUGE_VAL), power - 1,
                     power + 1, power * 1.5}) {
      values.push_back(v);
    }
  }
  return values;
}

TEST(CharconvCompat, WritesTheEdgeCasesAsLibstdcxx) {
  for (double value : edgeCases()) {
    expectSameWriting(value);
    expectSameWriting(-value);
  }
}

TEST(CharconvCompat, ReadsTheEdgeCasesAsLibstdcxx) {
  for (double value : edgeCases()) {
    expectSameReading(nativeShortest(value));
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", value);
    expectSameReading(text);
  }
  for (const char* text : {"",
                           "-",
                           ".",
                           "-.",
                           "1e",
                           "1e+",
                           "1e-x",
                           "1.e5",
                           ".5",
                           "5.",
                           "0001",
                           "-0",
                           "1e400",
                           "-1e400",
                           "1e-400",
                           "-1e-400",
                           "0e999999",
                           "0.000e-999999",
                           "2.4703282292062327e-324",
                           "2.4703282292062328e-324",
                           "1.7976931348623158e308",
                           "1.7976931348623159e308",
                           "inf",
                           "-Infinity",
                           "infinit",
                           "nan",
                           "NaN(abc_1)",
                           "nan(",
                           "nan(a b)",
                           "+1",
                           "0x1p3",
                           " 1",
                           "1 ",
                           "1E5",
                           "1e+05",
                           "123456789012345678901234567890",
                           "1..2",
                           "e5",
                           "-e5",
                           "1e99999999999999999999"}) {
    expectSameReading(text);
  }
}

// Random bit patterns cover every exponent and digit count; random short
// decimals the numbers people type, whose shortest form is the typed one. A
// quarter of them under the sanitizers (randomCases).
TEST(CharconvCompat, AgreesWithLibstdcxxOnAMillionRandomDoubles) {
  const int each = scene::testing::randomCases(500'000);
  std::mt19937_64 random(20261206);
  std::uniform_int_distribution<int> digitCount(1, 17);
  std::uniform_int_distribution<int> exponent(-330, 310);
  for (int i = 0; i < each; ++i) {
    double value = std::bit_cast<double>(random());
    if (!std::isfinite(value)) continue;
    expectSameWriting(value);
    expectSameReading(nativeShortest(value));
  }
  for (int i = 0; i < each; ++i) {
    std::string text = std::to_string(random() % 100'000'000'000'000'000ULL);
    text.resize(static_cast<std::size_t>(std::min<int>(digitCount(random), text.size())));
    text.insert(1, ".");
    text += "e" + std::to_string(exponent(random));
    expectSameReading(text);
    double value = std::strtod(text.c_str(), nullptr);
    if (std::isfinite(value)) expectSameWriting(value);
  }
}

}  // namespace
