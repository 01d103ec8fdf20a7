#include "libscene/formats/sf/sf_writer.h"

#include "libscene/text/number.h"

namespace scene {

namespace {

void appendRecord(std::string& out, std::string_view name, const glm::dvec3& colour,
                  const glm::dmat4& matrix) {
  if (!out.empty()) out += '\n';
  out += name;
  out += '\n';
  for (int i = 0; i < 3; ++i) {
    if (i) out += ' ';
    appendNumber(out, colour[i]);
  }
  out += '\n';
  // Row by row; GLM holds matrix[column][row].
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      if (c) out += ' ';
      appendNumber(out, matrix[c][r]);
    }
    out += '\n';
  }
}

}  // namespace

std::string writeSceneFile(const Scene& scene) {
  std::string out;
  // About 25 bytes a number leaves room for all but the longest numbers.
  out.reserve((1 + scene.lights.size() + scene.objects.size()) * 19 * 25);
  appendRecord(out, "CAMERA", scene.camera.colour, scene.camera.matrix);
  for (const Light& light : scene.lights) appendRecord(out, "LIGHT", light.colour, light.matrix);
  for (const Object& object : scene.objects) {
    appendRecord(out, objectKindName(object.kind), object.material.colour, object.matrix);
  }
  return out;
}

}  // namespace scene
