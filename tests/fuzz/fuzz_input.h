// What the fuzz targets share: the input as text, and a loud stop when a
// property that must hold for every input does not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace fuzz {

inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A broken property is a finding like a crash: libFuzzer saves the input
// when the process aborts.
[[noreturn]] inline void propertyFailed(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz property failed: %s\n%s\n", what, detail.c_str());
  std::abort();
}

}  // namespace fuzz
