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

// A decimal number (a float) in [low, high].
CLI::Validator numberIn(double low, double high);

// A whole number in [low, high].
CLI::Validator wholeNumberIn(std::int64_t low, std::int64_t high);

// Any whole number that fits the option's type (--seed).
CLI::Validator wholeNumber();

// A size in bytes as CLI::AsSizeValue reads it: a whole number, with a unit
// if wanted (512MiB, 2GB, 64k); to be added as a transform after
// AsSizeValue, so that it runs first and a word, a sign or an unknown unit
// is told in these words.
CLI::Validator sizeInBytes();

// One of `names`, exactly; the message lists them and suggests the closest.
CLI::Validator oneOf(std::vector<std::string> names);

// The choices of an option checked with oneOf (for the completion), or
// none; and how oneOf writes them into the option's type: "{a,b,c}".
std::vector<std::string> choicesOf(const CLI::Option& option);
std::string choiceList(const std::vector<std::string>& names);

}  // namespace tools
