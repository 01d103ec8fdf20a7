#include "libscene/text/number.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "libscene/testing/random_cases.h"

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
  for (const char* text :
       {"nan", "inf", "-inf", "NaN", "infinity", "0x1p3", "1,5", "1.0f", "1.0abc", "",   "+", "-",
        ".",   "e5",  "1e",   "1e+", "++1",      "+-1",   "--1", "1..2", "1.2.3",  " 1", "1 "}) {
    EXPECT_EQ(parseNumber(text).status, NumberStatus::Syntax) << '"' << text << '"';
  }
}

TEST(ParseNumber, TellsOverflowFromUnderflow) {
  EXPECT_EQ(parseNumber("1e400").status, NumberStatus::Overflow);
  EXPECT_EQ(parseNumber("-1e400").status, NumberStatus::Overflow);
  EXPECT_EQ(parseNumber("1.7976931348623159e308").status, NumberStatus::Overflow);
  EXPECT_EQ(parseNumber("1.7976931348623157e308").status, NumberStatus::Ok);
  EXPECT_EQ(parseNumber("1e-400").status, NumberStatus::Underflow);
  EXPECT_EQ(parseNumber("0.0000000000000000000000000000001e-300").status, NumberStatus::Underflow);
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

// What the contract asks of every literal: the bits std::from_chars gives,
// or out of range exactly where it says so.
void expectSameAsFromChars(std::string_view literal, const ParsedNumber& parsed) {
  std::string_view body = literal;
  if (body.front() == '+') body.remove_prefix(1);
  double expected = 0.0;
  auto [ptr, ec] =
      std::from_chars(body.data(), body.data() + body.size(), expected, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    ASSERT_TRUE(parsed.status == NumberStatus::Overflow || parsed.status == NumberStatus::Underflow)
        << literal;
    return;
  }
  ASSERT_EQ(ec, std::errc{}) << literal;
  ASSERT_EQ(ptr, body.data() + body.size()) << literal;
  ASSERT_EQ(parsed.status, NumberStatus::Ok) << literal;
  ASSERT_EQ(std::bit_cast<std::uint64_t>(parsed.value), std::bit_cast<std::uint64_t>(expected))
      << literal;
}

// A random literal of one of many shapes: short ones like the files have,
// long ones, ones at the edges of the fast paths (eight characters, 2^53,
// 19 digits, powers of ten near 22), leading zeros, huge and tiny exponents.
std::string randomLiteral(std::mt19937_64& rng) {
  auto below = [&rng](std::uint64_t n) { return static_cast<std::size_t>(rng() % n); };
  auto digits = [&](std::size_t count) {
    std::string out;
    for (std::size_t i = 0; i < count; ++i) out += static_cast<char>('0' + below(10));
    return out;
  };
  std::string mantissa;
  switch (below(7)) {
    case 0:  // like the generated scenes: a few significant digits
      mantissa = digits(below(3)) + "." + digits(1 + below(5));
      break;
    case 1:  // up to eight characters with the point anywhere: "5.", ".5", "1234567"
      mantissa = digits(below(9));
      mantissa.insert(below(mantissa.size() + 1), ".");
      if (below(4) == 0) mantissa.pop_back();
      if (mantissa.empty() || mantissa == ".") mantissa = digits(1 + below(8));
      break;
    case 2: {  // around 2^53, the fast path's limit
      std::uint64_t value = (std::uint64_t{1} << 53) - 50 + below(100);
      mantissa = std::to_string(value);
      mantissa.insert(below(mantissa.size() + 1), ".");
      break;
    }
    case 3:  // 15 to 20 significant digits
      mantissa = digits(1 + below(20));
      mantissa += "." + digits(below(21 - std::min<std::size_t>(mantissa.size(), 20)));
      break;
    case 4:  // leading zeros before and after the point
      mantissa =
          std::string(below(25), '0') + "." + std::string(below(25), '0') + digits(1 + below(8));
      break;
    case 5:  // many digits
      mantissa = digits(1 + below(40)) + "." + digits(below(40));
      break;
    default:  // an integer, with zeros that the exponent may shift
      mantissa = digits(1 + below(6)) + std::string(below(6), '0');
      break;
  }
  std::string literal;
  if (std::size_t sign = below(3); sign > 0) literal += sign == 1 ? '-' : '+';
  literal += mantissa;
  switch (below(5)) {
    case 0: {  // near the largest exact power of ten, counting the fraction digits
      std::size_t point = mantissa.find('.');
      long long fraction =
          point == std::string::npos ? 0 : static_cast<long long>(mantissa.size() - point - 1);
      long long exponent = fraction + (below(2) ? 22 : -22) + static_cast<long long>(below(5)) - 2;
      literal += (below(2) ? "e" : "E") + std::to_string(exponent);
      break;
    }
    case 1:  // small, with an explicit sign or leading zeros sometimes
      literal += below(2) ? "e" : "E";
      if (below(3) == 0) literal += below(2) ? "+" : "-";
      literal += std::string(below(3), '0') + std::to_string(below(30));
      break;
    case 2:  // towards overflow, underflow and the subnormals
      literal += "e" + std::to_string(static_cast<long long>(below(700)) - 350);
      break;
    default:
      break;
  }
  return literal;
}

TEST(ParseNumber, GivesTheBitsOfFromCharsForAMillionRandomLiterals) {
  std::mt19937_64 rng(20261123);
  // Behind the literal: a blank and more text, so that parseLeadingNumber
  // may read a whole word past a short literal, as it does in a file.
  std::string buffer;
  for (int i = 0; i < scene::testing::randomCases(1'000'000); ++i) {
    std::string literal = randomLiteral(rng);
    ASSERT_NO_FATAL_FAILURE(expectSameAsFromChars(literal, parseNumber(literal))) << literal;

    buffer = literal + (rng() % 2 ? " " : "\t") + "0.25 -1\n";
    std::size_t length = 0;
    ParsedNumber leading = parseLeadingNumber(
        std::string_view(buffer).substr(0, literal.size() + 5), buffer.size(), length);
    ASSERT_NO_FATAL_FAILURE(expectSameAsFromChars(literal, leading)) << literal;
    if (leading.status == NumberStatus::Ok) {
      ASSERT_EQ(length, literal.size()) << literal;
    }

    // At the very end of what may be read, too: in a block of its own size,
    // so that a sanitizer sees any byte read beyond.
    std::vector<char> exact(literal.begin(), literal.end());
    ParsedNumber last =
        parseLeadingNumber(std::string_view(exact.data(), exact.size()), exact.size(), length);
    ASSERT_NO_FATAL_FAILURE(expectSameAsFromChars(literal, last)) << literal;
  }
}

// The grammar of FORMATS.md, `[+-]?(digits[.digits?]|.digits)([eE][+-]?digits)?`,
// written as plainly as possible to judge the reader's two ways of checking it.
bool matchesGrammar(std::string_view s) {
  auto digitsAt = [&s](std::size_t i) {
    std::size_t n = 0;
    while (i + n < s.size() && s[i + n] >= '0' && s[i + n] <= '9') ++n;
    return n;
  };
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t before = digitsAt(i);
  i += before;
  std::size_t after = 0;
  if (i < s.size() && s[i] == '.') {
    after = digitsAt(i + 1);
    i += 1 + after;
  }
  if (before == 0 && after == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t exponent = digitsAt(i);
    if (exponent == 0) return false;
    i += exponent;
  }
  return i == s.size();
}

TEST(ParseNumber, AcceptsExactlyTheGrammarWhereverATokenEnds) {
  // Random short strings over the characters a literal has and a few it
  // must not: the word path and the scan must agree with the grammar, and
  // reading a token in its line must agree with reading it alone.
  // Bytes above 0x7F include ones that are digits and a point but for their
  // high bit.
  const std::string alphabet = "0123456789..++--eEx,f\x80\xB1\xAE";
  std::mt19937_64 rng(7);
  for (int i = 0; i < 300'000; ++i) {
    std::string token;
    for (std::size_t n = rng() % 11; n > 0; --n) token += alphabet[rng() % alphabet.size()];
    bool valid = matchesGrammar(token);
    ParsedNumber whole = parseNumber(token);
    ASSERT_EQ(whole.status != NumberStatus::Syntax, valid) << '"' << token << '"';
    if (valid) {
      ASSERT_NO_FATAL_FAILURE(expectSameAsFromChars(token, whole)) << token;
    }

    std::string line = token + " 1 2 3 4 5 6 7 8";
    std::size_t length = 0;
    ParsedNumber leading = parseLeadingNumber(line, line.size(), length);
    ASSERT_EQ(leading.status, whole.status) << '"' << token << '"';
    if (valid) {
      ASSERT_EQ(length, token.size()) << token;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(leading.value),
                std::bit_cast<std::uint64_t>(whole.value))
          << token;
    }

    // A text that ends inside the token ends the token, whatever may be read
    // beyond it.
    std::size_t cut = rng() % (token.size() + 1);
    ParsedNumber prefix = parseNumber(token.substr(0, cut));
    ParsedNumber leadingPrefix =
        parseLeadingNumber(std::string_view(line).substr(0, cut), line.size(), length);
    ASSERT_EQ(leadingPrefix.status, prefix.status) << '"' << token << "\" cut at " << cut;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(leadingPrefix.value),
              std::bit_cast<std::uint64_t>(prefix.value))
        << token << " cut at " << cut;
  }
}

TEST(ParseNumber, ReadsALeadingNumberUpToItsBlank) {
  std::size_t length = 0;
  std::string_view line = "-0.1115\t0.02286 1.832";
  ParsedNumber n = parseLeadingNumber(line, line.size(), length);
  EXPECT_EQ(n.status, NumberStatus::Ok);
  EXPECT_EQ(n.value, -0.1115);
  EXPECT_EQ(length, 7u);
  EXPECT_EQ(parseLeadingNumber("1.0f 2", 6, length).status, NumberStatus::Syntax);
  EXPECT_EQ(parseLeadingNumber("12345678 2", 10, length).value, 12345678.0);
  EXPECT_EQ(parseLeadingNumber("123456789 2", 11, length).value, 123456789.0);
  EXPECT_EQ(parseLeadingNumber("-0", 2, length).status, NumberStatus::Ok);
  EXPECT_TRUE(std::signbit(parseLeadingNumber("-0 1 2 3 4", 10, length).value));
  EXPECT_EQ(parseLeadingNumber("1e400 1 2 3", 11, length).status, NumberStatus::Overflow);
  EXPECT_EQ(parseLeadingNumber(" 1 2 3 4 5", 10, length).status, NumberStatus::Syntax);
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
