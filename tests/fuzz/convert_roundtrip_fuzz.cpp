// libFuzzer target: sfconvert's whole path. The input is read in whatever
// format it is in, converted to every output format, and each output read
// again. The properties are the contract of sfconvert (TOOLS.md):
// - nothing it writes fails to read back;
// - a scene file comes back bit for bit through .sf, glTF, GLB and POV-Ray;
// - an instruction file written from a scene reads back to one that writes
//   the same instruction file.
#include "libscene/conversion.h"
#include "libscene/scene_reader.h"
#include "libscene/sf_writer.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

using scene::OutputFormat;

const char* nameFor(OutputFormat format) {
  switch (format) {
    case OutputFormat::SceneFile:
      return "out.sf";
    case OutputFormat::InstructionFile:
      return "out.txt";
    case OutputFormat::Gltf:
      return "out.gltf";
    case OutputFormat::Glb:
      return "out.glb";
    case OutputFormat::Pov:
      return "out.pov";
  }
  return "out";
}

// Converts and reads back; nothing when the conversion refuses (a loss it
// cannot express is reported, which is allowed).
std::optional<scene::ReadResult> throughFormat(const scene::Scene& scene, OutputFormat format,
                                               std::string& text) {
  scene::DiagnosticList diagnostics;
  std::optional<std::string> converted = scene::convertScene(scene, format, {}, diagnostics);
  if (!converted) return std::nullopt;
  text = *converted;
  scene::ReadResult back = scene::parseScene(text, nameFor(format));
  if (!back.ok()) {
    std::string first;
    for (const scene::Diagnostic& d : back.diagnostics.items()) {
      if (d.severity == scene::Severity::Error) {
        first = d.message;
        break;
      }
    }
    fuzz::propertyFailed("sfconvert wrote a file it cannot read back",
                         std::string(nameFor(format)) + ": " + first + "\n" + text);
  }
  return back;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path folder = fuzz::emptyFolder();
  scene::ReadResult read =
      scene::parseScene(fuzz::asText(data, size), (folder / "fuzz-input").string());
  if (!read.ok()) return 0;

  // Step 1: as an instruction file; writing that file again is a fixed point.
  std::string text;
  if (auto back = throughFormat(read.scene, OutputFormat::InstructionFile, text)) {
    std::string again;
    auto twice = throughFormat(back->scene, OutputFormat::InstructionFile, again);
    if (!twice || again != text) {
      fuzz::propertyFailed("instruction file written twice differs", text + "\n---\n" + again);
    }
  }

  // Step 2: as a scene file, then that scene through every format.
  auto sfBack = throughFormat(read.scene, OutputFormat::SceneFile, text);
  if (!sfBack) return 0;
  const std::string sf = text;
  if (scene::writeSceneFile(sfBack->scene) != sf) {
    fuzz::propertyFailed("a scene file read and written again differs", sf);
  }
  for (OutputFormat format :
       {OutputFormat::SceneFile, OutputFormat::Gltf, OutputFormat::Glb, OutputFormat::Pov}) {
    auto back = throughFormat(sfBack->scene, format, text);
    if (!back) fuzz::propertyFailed("a valid scene file could not be converted", sf);
    if (scene::writeSceneFile(back->scene) != sf) {
      fuzz::propertyFailed("a scene file does not come back bit for bit",
                           std::string(nameFor(format)) + "\n" + sf + "\n---\n" + text);
    }
  }
  return 0;
}
