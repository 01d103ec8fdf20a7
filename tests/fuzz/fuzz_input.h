// What the fuzz targets share: the input as text, and a loud stop when a
// property that must hold for every input does not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "libscene/testing/random_scenes.h"
#include "scenefile/scene.h"

namespace fuzz {

inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// An empty folder of the fuzzers' own, where the glTF reader looks for
// external buffers: an input that names a file cannot reach the machine's
// files through it.
inline std::filesystem::path emptyFolder() {
  std::error_code ignored;
  std::filesystem::path folder =
      std::filesystem::temp_directory_path(ignored) / "scenefile-fuzz-empty";
  std::filesystem::create_directories(folder, ignored);
  return folder;
}

// A broken property is a finding like a crash: libFuzzer saves the input
// when the process aborts.
[[noreturn]] inline void propertyFailed(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz property failed: %s\n%s\n", what, detail.c_str());
  std::abort();
}

// An accepted input yields a model whose every number is finite: checked by
// a loop of the tests' own over every double (scene::testing::forEachNumber),
// not by the library's checkSceneFinite, so that the property does not
// trust what it tests.
inline void requireFinite(const scene::Scene& scene, const char* what,
                          std::string_view input = {}) {
  std::string found = scene::testing::firstNonFinite(scene);
  if (!found.empty()) {
    propertyFailed("an accepted input holds a number that is not finite",
                   std::string(what) + ": " + found + "\n" + std::string(input));
  }
}

}  // namespace fuzz
