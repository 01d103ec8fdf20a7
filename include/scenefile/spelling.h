/// @file
/// Did-you-mean: the closest of a list of names to a word that is none of
/// them. The readers suggest keywords with it (`sphere` -> `SPHERE`), and
/// the tools suggest their options and choices.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace scene {

/// The candidate that `word` most likely meant: one that differs from it
/// only in case, else the one at the smallest edit distance (insertions,
/// deletions, substitutions and swaps of two neighbours, case ignored) when
/// that is at most a third of the word's length, and at least 1; nothing
/// when none is that close.
std::optional<std::string_view> suggestSpelling(std::string_view word,
                                                std::span<const std::string_view> candidates);

/// Whether `a` and `b` are the same word but for the case of ASCII letters.
bool equalsIgnoringCase(std::string_view a, std::string_view b);

/// The edit distance of suggestSpelling, capped at 64 for words longer
/// than 64 characters.
std::size_t spellingDistance(std::string_view a, std::string_view b);

}  // namespace scene
