// libFuzzer target: the POV-Ray reader on any bytes. It must stop on every
// input, in bounded time and memory, whatever it accepts or refuses; what it
// accepts holds only finite numbers (0/0, sqrt(-1), exp(1000) are errors).
#include "libscene/formats/pov/pov_reader.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scene::PovImport imported = scene::importPov(fuzz::asText(data, size), "fuzz.pov");
  // Every object the reader reports must have its closing brace inside the text.
  for (std::size_t end : imported.objectEnds) {
    if (end >= size) fuzz::propertyFailed("an object ends past the end of the text", "");
  }
  if (imported.read.ok()) fuzz::requireFinite(imported.read.scene, "fuzz.pov");
  return 0;
}
