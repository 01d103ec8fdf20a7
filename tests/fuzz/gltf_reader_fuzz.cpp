// libFuzzer target: the glTF reader (JSON and GLB) on any bytes, with
// external buffers looked for in an empty folder (fuzz::emptyFolder). A
// file it accepts must hold only finite numbers.
#include "libscene/formats/gltf/gltf_reader.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path folder = fuzz::emptyFolder();
  std::string_view bytes = fuzz::asText(data, size);
  const char* name = scene::looksLikeGlb(bytes) ? "fuzz.glb" : "fuzz.gltf";
  scene::ReadResult read = scene::parseGltf(bytes, name, folder);
  if (read.ok()) fuzz::requireFinite(read.scene, name);
  return 0;
}
