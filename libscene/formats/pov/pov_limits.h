// The hard limits of the POV-Ray reader (pov_reader.h): on the size, the
// tokens, the nesting and the declarations, so that any input's time and
// memory are bounded [pov-limit].
#pragma once

#include <cstddef>

namespace scene {

inline constexpr std::size_t kMaxPovBytes = std::size_t{256} << 20;
inline constexpr std::size_t kMaxPovTokens = 50'000'000;
inline constexpr int kMaxPovNesting = 64;  // braces, parentheses and vectors inside each other
inline constexpr std::size_t kMaxPovDeclarations = 100'000;

}  // namespace scene
