#include "tools/common/option_checks.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
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

// The value as a double, when all of it is a decimal number; CLI11 itself
// converts with the same rules (strtod), so what passes here converts.
std::optional<double> decimal(const std::string& value) {
  if (value.empty()) return std::nullopt;
  const char* begin = value.data();
  if (*begin == '+') ++begin;
  double parsed = 0;
  auto [end, ec] = std::from_chars(begin, value.data() + value.size(), parsed);
  if (ec != std::errc() || end != value.data() + value.size() || !std::isfinite(parsed)) {
    return std::nullopt;
  }
  return parsed;
}

std::optional<std::int64_t> whole(const std::string& value) {
  if (value.empty()) return std::nullopt;
  const char* begin = value.data();
  if (*begin == '+') ++begin;
  std::int64_t parsed = 0;
  auto [end, ec] = std::from_chars(begin, value.data() + value.size(), parsed);
  if (ec != std::errc() || end != value.data() + value.size()) return std::nullopt;
  return parsed;
}

// Why `value` is no whole number: not a number at all, one with a
// fraction, one too large to hold, or one written with an exponent (which
// the conversion after the check would not read).
std::string notWhole(const std::string& value) {
  if (std::optional<double> d = decimal(value)) {
    if (std::floor(*d) != *d) return inQuotes(value) + " is not a whole number";
    if (std::fabs(*d) >= 9.2e18) return inQuotes(value) + " is too large";
    return inQuotes(value) + " is not a whole number written in digits";
  }
  return inQuotes(value) + " is not a number";
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
  return CLI::Validator(
      [low, high](std::string& value) -> std::string {
        std::optional<double> d = decimal(value);
        if (!d) return inQuotes(value) + " is not a number";
        if (*d < low || *d > high) {
          return value + " is not between " + boundText(low) + " and " + boundText(high);
        }
        return {};
      },
      "", "number in range");
}

CLI::Validator wholeNumberIn(std::int64_t low, std::int64_t high) {
  return CLI::Validator(
      [low, high](std::string& value) -> std::string {
        std::optional<std::int64_t> n = whole(value);
        if (!n) return notWhole(value);
        if (*n < low || *n > high) {
          return value + " is not between " + std::to_string(low) + " and " + std::to_string(high);
        }
        return {};
      },
      "", "whole number in range");
}

CLI::Validator wholeNumber() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        return whole(value) ? std::string() : notWhole(value);
      },
      "", "whole number");
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
        for (char& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        static constexpr std::string_view kUnits[] = {
            "",    "b", "k",  "kb", "ki",  "kib", "m",  "mb", "mi",  "mib", "g",  "gb", "gi",
            "gib", "t", "tb", "ti", "tib", "p",   "pb", "pi", "pib", "e",   "eb", "ei", "eib"};
        for (std::string_view known : kUnits) {
          if (unit == known) return {};
        }
        return inQuotes(value) +
               " has no unit of size that is known (use KiB, MiB, GiB, kB, MB "
               "or GB)";
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
        bool numbers = std::all_of(names.begin(), names.end(),
                                   [](const std::string& n) { return whole(n).has_value(); });
        if (numbers && !decimal(value)) return inQuotes(value) + " is not a number";
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
