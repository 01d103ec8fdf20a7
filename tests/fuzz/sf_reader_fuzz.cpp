// libFuzzer target: the scene file reader on any bytes. A file it accepts
// must hold only finite numbers, and write back to text that reads again to
// the same scene. What an editor asks of the text holds too (editor_views.h).
#include "libscene/formats/sf/sf_reader.h"
#include "libscene/formats/sf/sf_writer.h"
#include "tests/fuzz/editor_views.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scene::ReadResult read = scene::parseSceneFile(fuzz::asText(data, size), "fuzz.sf");
  fuzz::checkEditorViews(fuzz::asText(data, size), scene::Format::SceneFile, read);
  if (!read.ok()) return 0;
  fuzz::requireFinite(read.scene, "fuzz.sf");
  std::string written = scene::writeSceneFile(read.scene);
  scene::ReadResult again = scene::parseSceneFile(written, "again.sf");
  if (!again.ok()) fuzz::propertyFailed("a scene read from a .sf cannot be read back", written);
  if (!(again.scene == read.scene)) {
    fuzz::propertyFailed("a .sf read, written and read again differs", written);
  }
  return 0;
}
