// libFuzzer target: the instruction file reader on any bytes. A file it
// accepts must hold only finite numbers (a chain of operations that
// overflows is an error), and write back to an instruction file that reads
// again to the same scene. What an editor asks of the text holds too
// (editor_views.h).
#include "libscene/formats/instruction/instruction_reader.h"
#include "libscene/formats/instruction/instruction_writer.h"
#include "tests/fuzz/editor_views.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scene::ReadResult read = scene::parseInstructionFile(fuzz::asText(data, size), "fuzz.txt");
  fuzz::checkEditorViews(fuzz::asText(data, size), scene::Format::InstructionFile, read);
  if (!read.ok()) return 0;
  fuzz::requireFinite(read.scene, "fuzz.txt");
  scene::DiagnosticList losses;
  std::optional<std::string> written = scene::writeInstructionFile(read.scene, {}, losses);
  if (!written) return 0;
  scene::ReadResult again = scene::parseInstructionFile(*written, "again.txt");
  if (!again.ok()) {
    fuzz::propertyFailed("an instruction file read and written cannot be read back", *written);
  }
  if (!(again.scene == read.scene)) {
    fuzz::propertyFailed("an instruction file read, written and read again differs", *written);
  }
  return 0;
}
