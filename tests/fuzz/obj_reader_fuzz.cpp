// libFuzzer target: the OBJ reader on any bytes, with no folder to read MTL
// files from. It must stop on every input, in bounded time and memory;
// what it accepts holds only finite numbers.
#include "libscene/formats/obj/obj_reader.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scene::ReadOptions options;
  options.obj.maxVertices = 100'000;
  scene::ReadResult read =
      scene::parseObj(fuzz::asText(data, size), "fuzz.obj", std::nullopt, options);
  if (read.ok()) fuzz::requireFinite(read.scene, "fuzz.obj");
  return 0;
}
