// libFuzzer target: the glTF reader (JSON and GLB) on any bytes. External
// buffers are looked for in an empty folder of the fuzzer's own, so that
// an input naming a file cannot reach the machine's files through it.
#include <filesystem>
#include <system_error>

#include "libscene/gltf_reader.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

std::filesystem::path emptyFolder() {
  std::error_code ignored;
  std::filesystem::path folder =
      std::filesystem::temp_directory_path(ignored) / "scenefile-fuzz-empty";
  std::filesystem::create_directories(folder, ignored);
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path folder = emptyFolder();
  std::string_view bytes = fuzz::asText(data, size);
  const char* name = scene::looksLikeGlb(bytes) ? "fuzz.glb" : "fuzz.gltf";
  scene::ReadResult read = scene::parseGltf(bytes, name, folder);
  (void)read;
  return 0;
}
