// libFuzzer target: sfconvert's whole path. The input is read in whatever
// format it is in, converted to every output format, and each output read
// again. The properties are the contract of sfconvert (TOOLS.md):
// - nothing it writes fails to read back, from the input itself, from the
//   instruction and scene files written from it, and from the input moved
//   out to the edge of the doubles (every position scaled by a power of two
//   up to near the largest double); every number read back is finite;
// - a scene file comes back bit for bit through .sf, glTF, GLB and POV-Ray;
// - an instruction file written from a scene reads back to one that writes
//   the same instruction file.
#include <cmath>
#include <limits>

#include "scenefile/convert.h"
#include "scenefile/read.h"
#include "libscene/formats/sf/sf_writer.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

using scene::Format;

// A file name in the format's first extension: "out.gltf".
std::string nameFor(Format format) {
  return "out" + std::string(scene::formatInfo(format).extensions[0]);
}

// Converts and reads back; nothing when the conversion refuses (a loss it
// cannot express is reported, which is allowed).
std::optional<scene::ReadResult> throughFormat(const scene::Scene& scene, Format format,
                                               std::string& text,
                                               const scene::ConversionOptions& options = {}) {
  scene::DiagnosticList diagnostics;
  std::optional<std::string> converted = scene::convertScene(scene, format, options, diagnostics);
  if (!converted) {
    if (diagnostics.errorCount() == 0) {
      fuzz::propertyFailed("sfconvert refused without an error", nameFor(format));
    }
    return std::nullopt;
  }
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
  fuzz::requireFinite(back.scene, nameFor(format).c_str(), text);
  return back;
}


// The scene with every position (the eye, the lights, the objects'
// translations) scaled by the power of two that takes the largest one to
// [2^1022, 2^1023): the edge where LOOK_AT points, plane sides and light
// sums overflow. Nothing when the scene has no position to scale.
std::optional<scene::Scene> atTheEdge(const scene::Scene& in) {
  double largest = 0.0;
  auto grow = [&largest](const glm::dvec4& p) {
    for (int i = 0; i < 3; ++i) largest = std::max(largest, std::abs(p[i]));
  };
  grow(in.camera.matrix[3]);
  for (const scene::Light& light : in.lights) grow(light.matrix[3]);
  for (const scene::Object& object : in.objects) grow(object.matrix[3]);
  if (!(largest > 0.0)) return std::nullopt;
  int exponent = 0;
  std::frexp(largest, &exponent);
  int shift = 1023 - exponent;
  if (shift <= 0) return std::nullopt;
  scene::Scene out = in;
  auto move = [shift](glm::dvec4& p) {
    for (int i = 0; i < 3; ++i) p[i] = std::ldexp(p[i], shift);
  };
  move(out.camera.matrix[3]);
  out.camera.lookAt.reset();
  for (scene::Light& light : out.lights) move(light.matrix[3]);
  for (scene::Object& object : out.objects) {
    move(object.matrix[3]);
    object.transforms.reset();
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path folder = fuzz::emptyFolder();
  scene::ReadResult read =
      scene::parseScene(fuzz::asText(data, size), (folder / "fuzz-input").string());
  if (!read.ok()) return 0;
  fuzz::requireFinite(read.scene, "the input");

  // Step 0: the input straight into every format, and at the edge of the
  // doubles (with --approximate, so that shear and roll are written too).
  std::string text;
  for (const scene::FormatInfo& row : scene::formats()) {
    throughFormat(read.scene, row.format, text);
  }
  if (std::optional<scene::Scene> edge = atTheEdge(read.scene)) {
    scene::ConversionOptions approximate;
    approximate.instructions.approximate = true;
    for (const scene::FormatInfo& row : scene::formats()) {
      throughFormat(*edge, row.format, text, approximate);
    }
  }

  // Step 1: as an instruction file; writing that file again is a fixed point,
  // and the file written from it reads back in every format.
  if (auto back = throughFormat(read.scene, Format::InstructionFile, text)) {
    std::string again;
    auto twice = throughFormat(back->scene, Format::InstructionFile, again);
    if (!twice || again != text) {
      fuzz::propertyFailed("instruction file written twice differs", text + "\n---\n" + again);
    }
    for (const scene::FormatInfo& row : scene::formats()) {
      throughFormat(back->scene, row.format, again);
    }
  }

  // Step 2: as a scene file, then that scene through every format.
  auto sfBack = throughFormat(read.scene, Format::SceneFile, text);
  if (!sfBack) return 0;
  const std::string sf = text;
  if (scene::writeSceneFile(sfBack->scene) != sf) {
    fuzz::propertyFailed("a scene file read and written again differs", sf);
  }
  for (Format format :
       {Format::SceneFile, Format::Gltf, Format::Glb, Format::Pov}) {
    auto back = throughFormat(sfBack->scene, format, text);
    if (!back) fuzz::propertyFailed("a valid scene file could not be converted", sf);
    if (scene::writeSceneFile(back->scene) != sf) {
      fuzz::propertyFailed("a scene file does not come back bit for bit",
                           std::string(nameFor(format)) + "\n" + sf + "\n---\n" + text);
    }
  }
  return 0;
}
