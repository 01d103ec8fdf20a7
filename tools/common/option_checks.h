// The checks of the tools' option values, with messages in the house style:
// a value that is no number says so ("'abc' is not a number"), one out of
// range gives the range ("0 is not between 1 and 32768"), a name not among
// the choices lists them. CLI11's own (CLI::Range, CLI::IsMember) say "not
// in range" of a word that is no number at all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tools/common/cli_forward.h"

namespace tools {

// The one conversion of every numeric option of every tool: the text is
// read whole, in decimal (a leading 0 is no octal, 0x no hexadecimal, no
// blank around it), with correct rounding; a subnormal is the tiny number
// it is. A value that is empty, no number, NaN or infinite, too large for
// its type or too small for a double, or outside [low, high] is refused
// with the value in the message: "'' is not a number", "0 is not between 1
// and 32768". What passes is rewritten as text that CLI11's own conversion
// (strtoll, strtold) reads to exactly that number, so add these with
// ->transform(), never ->check(), which would hand CLI11 the text as typed.

// A decimal number (a double) in [low, high].
CLI::Validator numberIn(double low, double high);

// A decimal number above `low` (excluded) and at most `high`.
CLI::Validator numberAbove(double low, double high);

// A whole number in [low, high], written in digits.
CLI::Validator wholeNumberIn(std::int64_t low, std::int64_t high);

// A size in bytes, 0 to 2^63 - 1: a whole number, with a unit if wanted
// (512MiB, 2GB, 64k: k, M, G, T, P, E powers of 1000, Ki to Ei of 1024, B
// or nothing bytes, case ignored), rewritten as the number of bytes.
CLI::Validator sizeInBytes();

// One of `names`, exactly; the message lists them and suggests the closest.
CLI::Validator oneOf(std::vector<std::string> names);

// The choices of an option checked with oneOf (for the completion), or
// none; and how oneOf writes them into the option's type: "{a,b,c}".
std::vector<std::string> choicesOf(const CLI::Option& option);
std::string choiceList(const std::vector<std::string>& names);

}  // namespace tools
