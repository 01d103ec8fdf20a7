#include "tools/common/option_checks.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string_view>

#include "scenefile/spelling.h"

namespace tools {

namespace {

std::string inQuotes(const std::string& value) {
  return "'" + value + "'";
}

// The shortest text of a bound, as it would be typed: 1, 0.001, 180.
std::string boundText(double value) {
  char text[64];
  auto [end, ec] = std::to_chars(text, text + sizeof text, value);
  return ec == std::errc() ? std::string(text, end) : std::to_string(value);
}

// What the text of a value is, read as a decimal number.
enum class Reading { Number, NotANumber, NotFinite, TooLarge, TooSmall };

struct Decimal {
  Reading reading = Reading::NotANumber;
  double value = 0;
};

// The text without one leading '+', which strtod allows and from_chars
// does not ("+-1" keeps its '+', and is no number).
std::string_view withoutPlus(const std::string& text) {
  std::string_view view = text;
  if (view.size() > 1 && view[0] == '+' && view[1] != '+' && view[1] != '-') view.remove_prefix(1);
  return view;
}

Decimal readDecimal(const std::string& text) {
  std::string_view digits = withoutPlus(text);
  const char* end = digits.data() + digits.size();
  double value = 0;
  auto [stop, ec] = std::from_chars(digits.data(), end, value);
  if (digits.empty() || stop != end) return {};
  if (ec == std::errc::result_out_of_range) {
    // from_chars leaves the value alone: strtod tells overflow from
    // underflow, on text from_chars has found to be a decimal literal.
    double rounded = std::strtod(std::string(digits).c_str(), nullptr);
    return {std::isinf(rounded) ? Reading::TooLarge : Reading::TooSmall,
            std::isinf(rounded) ? rounded : std::copysign(0.0, rounded)};
  }
  if (ec != std::errc()) return {};
  if (!std::isfinite(value)) return {Reading::NotFinite, value};
  return {Reading::Number, value};
}

// Text that strtold, CLI11's conversion of a double, reads to exactly
// `value`: a hexadecimal float, which no rounding touches.
std::string exactText(double value) {
  char text[64];
  auto [end, ec] =
      std::to_chars(text, text + sizeof text, std::fabs(value), std::chars_format::hex);
  return (std::signbit(value) ? "-0x" : "0x") + std::string(text, end);
}

// The message for a value that is no number at all, or none a double holds.
std::string notANumber(const std::string& value, const Decimal& d) {
  switch (d.reading) {
    case Reading::NotFinite:
      return inQuotes(value) + " is not a finite number";
    case Reading::TooLarge:
      return inQuotes(value) + " is too large for a 64-bit double";
    case Reading::TooSmall:
      return inQuotes(value) + " is too small for a 64-bit double: it would round to 0";
    default:
      return inQuotes(value) + " is not a number";
  }
}

// A decimal number in a range, the low end excluded or not.
CLI::Validator decimalIn(double low, bool lowIncluded, double high) {
  std::string range = lowIncluded ? "between " + boundText(low) + " and " + boundText(high)
                                  : "above " + boundText(low) + " and at most " + boundText(high);
  auto inRange = [=](double v) { return (lowIncluded ? v >= low : v > low) && v <= high; };
  return CLI::Validator(
      [=](std::string& value) -> std::string {
        Decimal d = readDecimal(value);
        // A number beyond a double, or too near 0 for one, is out of a
        // range that does not reach that far: say the range.
        bool outOfRange =
            (d.reading == Reading::TooLarge && !inRange(d.value)) ||
            (d.reading == Reading::TooSmall &&
             !inRange(std::copysign(std::numeric_limits<double>::denorm_min(), d.value)));
        if (d.reading != Reading::Number && !outOfRange) return notANumber(value, d);
        if (outOfRange || !inRange(d.value)) return value + " is not " + range;
        value = exactText(d.value);
        return {};
      },
      "", "number in range");
}

}  // namespace

std::string choiceList(const std::vector<std::string>& names) {
  std::string list = "{";
  for (std::size_t i = 0; i < names.size(); ++i) list += (i == 0 ? "" : ",") + names[i];
  return list + "}";
}

std::vector<std::string> choicesOf(const CLI::Option& option) {
  std::string type = option.get_type_name();
  std::size_t open = type.find(":{");
  std::size_t close = type.find('}', open);
  if (open == std::string::npos || close == std::string::npos) return {};
  std::vector<std::string> choices;
  std::string list = type.substr(open + 2, close - open - 2);
  for (std::size_t at = 0; at <= list.size();) {
    std::size_t comma = std::min(list.find(',', at), list.size());
    choices.push_back(list.substr(at, comma - at));
    at = comma + 1;
  }
  return choices;
}

CLI::Validator numberIn(double low, double high) {
  return decimalIn(low, true, high);
}

CLI::Validator numberAbove(double low, double high) {
  return decimalIn(low, false, high);
}

CLI::Validator wholeNumberIn(std::int64_t low, std::int64_t high) {
  std::string range = "between " + std::to_string(low) + " and " + std::to_string(high);
  return CLI::Validator(
      [low, high, range](std::string& value) -> std::string {
        std::string_view digits = withoutPlus(value);
        const char* end = digits.data() + digits.size();
        std::int64_t n = 0;
        auto [stop, ec] = std::from_chars(digits.data(), end, n);
        if (!digits.empty() && stop == end) {
          // Digits beyond an int64 are out of every range an option has.
          if (ec != std::errc() || n < low || n > high) return value + " is not " + range;
          value = std::to_string(n);
          return {};
        }
        Decimal d = readDecimal(value);
        if (d.reading == Reading::TooLarge) return value + " is not " + range;
        if (d.reading != Reading::Number) return notANumber(value, d);
        if (std::floor(d.value) != d.value) return inQuotes(value) + " is not a whole number";
        return inQuotes(value) + " is not a whole number written in digits";
      },
      "", "whole number in range");
}

CLI::Validator sizeInBytes() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        std::size_t digits = 0;
        while (digits < value.size() && std::isdigit(static_cast<unsigned char>(value[digits]))) {
          ++digits;
        }
        if (digits == 0) return inQuotes(value) + " is not a number of bytes";
        std::string unit = value.substr(digits);
        while (!unit.empty() && unit.front() == ' ') unit.erase(0, 1);
        // A blank may part the number from its unit, and is no unit itself.
        if (unit.empty() && digits < value.size()) {
          return inQuotes(value) + " is not a number of bytes";
        }
        for (char& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (!unit.empty() && unit.back() == 'b') unit.pop_back();
        // "", "k", "ki", "m", ... : the power of 1000 or 1024 a unit stands for.
        static constexpr std::string_view kPrefixes = "kmgtpe";
        std::uint64_t base = unit.size() == 2 && unit[1] == 'i' ? 1024 : 1000;
        std::size_t power = 0;
        if (!unit.empty()) {
          std::size_t at = kPrefixes.find(unit[0]);
          if (at == std::string_view::npos || unit.size() > (base == 1024 ? 2u : 1u)) {
            return inQuotes(value) +
                   " has no unit of size that is known (use KiB, MiB, GiB, kB, MB or GB)";
          }
          power = at + 1;
        }
        constexpr auto kMax = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
        std::uint64_t bytes = 0;
        auto [stop, ec] = std::from_chars(value.data(), value.data() + digits, bytes);
        bool fits = ec == std::errc();
        for (std::size_t i = 0; i < power && fits; ++i) {
          fits = bytes <= kMax / base;
          bytes *= base;
        }
        if (!fits || bytes > kMax) {
          return value + " is not between 0 and " + std::to_string(kMax) + " bytes";
        }
        value = std::to_string(bytes);
        return {};
      },
      "", "size in bytes");
}

CLI::Validator oneOf(std::vector<std::string> names) {
  return CLI::Validator(
      [names](std::string& value) -> std::string {
        for (const std::string& name : names) {
          if (value == name) return {};
        }
        std::string list;
        for (std::size_t i = 0; i < names.size(); ++i) {
          list += i == 0 ? "" : i + 1 == names.size() ? " or " : ", ";
          list += names[i];
        }
        // Numbers to choose from (--bits 8|16|32): a word is no number.
        bool numbers = std::all_of(names.begin(), names.end(), [](const std::string& n) {
          return std::all_of(n.begin(), n.end(), [](char c) { return c >= '0' && c <= '9'; });
        });
        if (numbers && readDecimal(value).reading == Reading::NotANumber) {
          return inQuotes(value) + " is not a number";
        }
        std::string message = inQuotes(value) + " is not " + list;
        std::vector<std::string_view> candidates(names.begin(), names.end());
        if (auto closest = scene::suggestSpelling(value, candidates)) {
          message += "; did you mean '" + std::string(*closest) + "'?";
        }
        return message;
      },
      // The description CLI11 adds to the option's type ("TEXT:{a,b}"):
      // --help leaves it out, and the completion reads the choices from it.
      choiceList(names), "one of");
}

}  // namespace tools
