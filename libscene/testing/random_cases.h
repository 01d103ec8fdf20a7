// How many random cases a property test draws.
#pragma once

namespace scene::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderSanitizers = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderSanitizers = true;
#else
inline constexpr bool kUnderSanitizers = false;
#endif
#else
inline constexpr bool kUnderSanitizers = false;
#endif

// `count` in the optimised build of make test, a quarter of it under the
// sanitizers. There every case runs five to ten times slower, and the six
// longest property tests took 270 of the 993 s that the sanitize stage's
// tests took together (537 s on two cores). The sanitizers look for memory
// errors and undefined behaviour, which the paths of a quarter of the cases
// reach as well, while the property itself keeps its full count where the
// suite runs optimised.
inline constexpr int randomCases(int count) {
  return kUnderSanitizers ? count / 4 : count;
}

}  // namespace scene::testing
