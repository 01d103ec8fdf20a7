#include "libscene/number.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace scene {
namespace {

TEST(ParseNumber, AcceptsEveryFormOfTheGrammar) {
  struct Case {
    const char* text;
    double value;
  };
  for (Case c : {Case{"1", 1.0}, Case{"-0.5", -0.5}, Case{".5", 0.5}, Case{"5.", 5.0},
                 Case{"1e-3", 1e-3}, Case{"+2", 2.0}, Case{"1E3", 1000.0}, Case{"-.25e+1", -2.5},
                 Case{"007", 7.0}, Case{"4e-320", 4e-320}}) {
    ParsedNumber n = parseNumber(c.text);
    EXPECT_EQ(n.status, NumberStatus::Ok) << c.text;
    EXPECT_EQ(n.value, c.value) << c.text;
  }
}

TEST(ParseNumber, KeepsTheSignOfZero) {
  EXPECT_TRUE(std::signbit(parseNumber("-0").value));
  EXPECT_FALSE(std::signbit(parseNumber("0").value));
}

TEST(ParseNumber, RejectsWhatIsNotADecimalLiteral) {
  for (const char* text : {"nan", "inf", "-inf", "NaN", "infinity", "0x1p3", "1,5", "1.0f",
                           "1.0abc", "", "+", "-", ".", "e5", "1e", "1e+", "++1", "+-1", "--1",
                           "1..2", "1.2.3", " 1", "1 "}) {
    EXPECT_EQ(parseNumber(text).status, NumberStatus::Syntax) << '"' << text << '"';
  }
}

TEST(ParseNumber, TellsOverflowFromUnderflow) {
  EXPECT_EQ(parseNumber("1e400").status, NumberStatus::Overflow);
  EXPECT_EQ(parseNumber("-1e400").status, NumberStatus::Overflow);
  EXPECT_EQ(parseNumber("1.7976931348623159e308").status, NumberStatus::Overflow);
  EXPECT_EQ(parseNumber("1.7976931348623157e308").status, NumberStatus::Ok);
  EXPECT_EQ(parseNumber("1e-400").status, NumberStatus::Underflow);
  EXPECT_EQ(parseNumber("0.0000000000000000000000000000001e-300").status,
            NumberStatus::Underflow);
  EXPECT_EQ(parseNumber("0e-400").status, NumberStatus::Ok);  // exactly zero
  EXPECT_EQ(parseNumber("1e99999999999999999999999").status, NumberStatus::Overflow);
  EXPECT_EQ(parseNumber("1e-99999999999999999999999").status, NumberStatus::Underflow);
}

TEST(ParseNumber, HandlesTenThousandDigits) {
  std::string big(10000, '7');
  EXPECT_EQ(parseNumber(big).status, NumberStatus::Overflow);
  std::string small = "0." + std::string(9998, '0') + "1";
  EXPECT_EQ(parseNumber(small).status, NumberStatus::Underflow);
  // Many digits that still fit: correctly rounded, not truncated.
  std::string third = "0." + std::string(10000, '3');
  EXPECT_EQ(parseNumber(third).value, 1.0 / 3.0);
}

TEST(ParseNumber, RoundsCorrectlyAtAHalfwayCase) {
  // 2^53 + 1 lies halfway between two doubles: round to even.
  EXPECT_EQ(parseNumber("9007199254740993").value, 9007199254740992.0);
  EXPECT_EQ(parseNumber("9007199254740993.0000000000000000001").value, 9007199254740994.0);
}

TEST(NumberSyntaxReason, ExplainsCommonMistakes) {
  EXPECT_EQ(numberSyntaxReason("nan"), "infinity and not-a-number are not allowed");
  EXPECT_EQ(numberSyntaxReason("-Inf"), "infinity and not-a-number are not allowed");
  EXPECT_EQ(numberSyntaxReason("0x1p3"), "hexadecimal numbers are not allowed");
  EXPECT_EQ(numberSyntaxReason("1,5"), "use '.' as the decimal separator");
  EXPECT_EQ(numberSyntaxReason("1.0f"), "unexpected 'f' after the number");
  EXPECT_EQ(numberSyntaxReason("abc"), "expected a decimal number");
}

TEST(FormatNumber, WritesTheShortestExactText) {
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(1.0), "1");
  EXPECT_EQ(formatNumber(-0.0), "-0");
  EXPECT_EQ(formatNumber(1e300), "1e+300");
  EXPECT_EQ(formatNumber(4.9406564584124654e-324), "5e-324");
}

TEST(FormatNumber, ReadsBackToTheSameBitsForRandomDoubles) {
  std::mt19937_64 rng(12345);
  for (int i = 0; i < 200000; ++i) {
    double value = std::bit_cast<double>(rng());
    if (!std::isfinite(value)) continue;
    ParsedNumber back = parseNumber(formatNumber(value));
    ASSERT_EQ(back.status, NumberStatus::Ok) << formatNumber(value);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(back.value), std::bit_cast<std::uint64_t>(value));
  }
}

}  // namespace
}  // namespace scene
