#include "tools/sfls/scene_description.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <optional>

#include "renderer/camera.h"
#include "renderer/render_scene.h"
#include "renderer/render_settings.h"

namespace sfls {

std::string numberText(double value) {
  // -0 (a negated axis's zero) reads as 0 to a person.
  if (value == 0.0) value = 0.0;
  std::array<char, 32> buffer;
  auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  if (error != std::errc()) return "?";
  return std::string(buffer.data(), end);
}

std::string vectorText(const glm::dvec3& value) {
  return numberText(value.x) + " " + numberText(value.y) + " " + numberText(value.z);
}

std::string matrixMarkdown(const glm::dmat4& matrix) {
  // Each column as wide as its widest number, so that the rows line up.
  std::array<std::array<std::string, 4>, 4> cells;
  std::array<std::size_t, 4> widths{};
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) {
      cells[row][column] = numberText(matrix[column][row]);
      widths[column] = std::max(widths[column], cells[row][column].size());
    }
  }
  std::string out = "```\n";
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) {
      const std::string& cell = cells[row][column];
      if (column > 0) out += ' ';
      out.append(widths[column] - cell.size(), ' ');
      out += cell;
    }
    out += '\n';
  }
  return out + "```";
}

std::string describeObject(const scene::Object& object) {
  std::string out = "- COLOUR " + vectorText(object.material.colour) + "\n";
  for (scene::MaterialProperty property : scene::kMaterialProperties) {
    double value = scene::materialValue(object.material, property);
    out += "- " + std::string(scene::materialPropertyName(property)) + " " + numberText(value);
    if (value == scene::defaultMaterialValue(property)) out += " (default)";
    out += '\n';
  }
  std::optional<render::Bounds> box = render::shapeBounds(object.kind, object.matrix);
  if (!box) return out + "\nWorld-space bounds: none, a plane is unbounded";
  out += "\nWorld-space bounds:\n";
  const char* axes[] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    out += std::string("- ") + axes[axis] + " from " + numberText(box->lo[axis]) + " to " +
           numberText(box->hi[axis]) + "\n";
  }
  out.pop_back();
  return out;
}

std::string describeCamera(const scene::Scene& scene) {
  // The renderer's own camera, so that what is shown is what it renders.
  render::RenderSettings settings;
  if (scene.view) settings.verticalFovDegrees = scene.view->verticalFovDegrees;
  render::PinholeCamera camera(scene.camera, settings);
  std::string out = "- eye " + vectorText(camera.eye()) + "\n";
  out += "- forward " + vectorText(camera.forward()) + "\n";
  out += "- up " + vectorText(camera.up()) + "\n";
  out += "- vertical field of view " + numberText(settings.verticalFovDegrees) + " degrees";
  if (!scene.view) out += " (sfrender's default; --fov sets another)";
  return out;
}

std::string describeLight(const scene::Light& light) {
  return "- position " + vectorText(light.position()) + "\n- colour " + vectorText(light.colour);
}

}  // namespace sfls
