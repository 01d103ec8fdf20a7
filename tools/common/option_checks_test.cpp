#include "tools/common/option_checks.h"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <limits>
#include <string>
#include <utility>

namespace tools {
namespace {

// What a check says of `text`, and the text it hands on to CLI11.
std::pair<std::string, std::string> checked(const CLI::Validator& check, std::string text) {
  std::string message = check(text);
  return {message, text};
}

TEST(OptionChecks, NumbersAreReadWhole) {
  using Said = std::pair<std::string, std::string>;
  CLI::Validator whole = wholeNumberIn(0, 100);
  EXPECT_EQ(checked(whole, "12abc").first, "'12abc' is not a number");
  EXPECT_EQ(checked(whole, "").first, "'' is not a number");
  EXPECT_EQ(checked(whole, "+5"), Said("", "5"));
  EXPECT_EQ(checked(whole, "1e3").first, "'1e3' is not a whole number written in digits");
  EXPECT_EQ(checked(whole, "1.5").first, "'1.5' is not a whole number");
  EXPECT_EQ(checked(whole, "99999999999999999999").first,
            "99999999999999999999 is not between 0 and 100");
  EXPECT_EQ(checked(whole, "inf").first, "'inf' is not a finite number");
  // Decimal whatever the leading zeros: no octal, no hexadecimal.
  EXPECT_EQ(checked(whole, "010"), Said("", "10"));
  EXPECT_EQ(checked(whole, "0x10").first, "'0x10' is not a number");
  CLI::Validator unit = numberIn(0, 1);
  EXPECT_EQ(checked(unit, "nan").first, "'nan' is not a finite number");
  EXPECT_EQ(checked(unit, "-inf").first, "'-inf' is not a finite number");
  EXPECT_EQ(checked(unit, ".5"), Said("", "0x1p-1"));
  EXPECT_EQ(checked(unit, " .5").first, "' .5' is not a number");
  EXPECT_EQ(checked(unit, "1e400").first, "1e400 is not between 0 and 1");
  EXPECT_EQ(checked(numberIn(-1, 1), "-1e-400").first,
            "'-1e-400' is too small for a 64-bit double: it would round to 0");
  EXPECT_EQ(checked(numberIn(1, 2), "1e-400").first, "1e-400 is not between 1 and 2");
  EXPECT_EQ(checked(numberIn(0, std::numeric_limits<double>::infinity()), "2e308").first,
            "'2e308' is too large for a 64-bit double");
  // A subnormal is the number it is, and reaches CLI11 exactly.
  EXPECT_EQ(checked(numberAbove(0, 1), "4.9e-324"), Said("", "0x0.0000000000001p-1022"));
  EXPECT_EQ(checked(numberAbove(0, 1), "0").first, "0 is not above 0 and at most 1");
  EXPECT_EQ(checked(numberAbove(0, 1), "-0").first, "-0 is not above 0 and at most 1");
  EXPECT_EQ(checked(numberIn(0, 1), "-0"), Said("", "-0x0p+0"));
}

TEST(OptionChecks, SizesAreReadWithTheirUnitAndWithinAnInt64) {
  using Said = std::pair<std::string, std::string>;
  CLI::Validator size = sizeInBytes();
  EXPECT_EQ(checked(size, "512MiB"), Said("", "536870912"));
  EXPECT_EQ(checked(size, "2GB"), Said("", "2000000000"));
  EXPECT_EQ(checked(size, "64k"), Said("", "64000"));
  EXPECT_EQ(checked(size, "010"), Said("", "10"));
  EXPECT_EQ(checked(size, "7EiB"), Said("", "8070450532247928832"));
  EXPECT_EQ(checked(size, "8EiB").first, "8EiB is not between 0 and 9223372036854775807 bytes");
  EXPECT_EQ(checked(size, "99999999999999999999").first,
            "99999999999999999999 is not between 0 and 9223372036854775807 bytes");
  EXPECT_EQ(checked(size, "").first, "'' is not a number of bytes");
  EXPECT_EQ(checked(size, "-5").first, "'-5' is not a number of bytes");
  EXPECT_EQ(checked(size, "5 parsecs").first,
            "'5 parsecs' has no unit of size that is known (use KiB, MiB, GiB, kB, MB or GB)");
}

}  // namespace
}  // namespace tools
