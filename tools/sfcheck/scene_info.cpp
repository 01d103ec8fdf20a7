#include "tools/sfcheck/scene_info.h"

#include <cctype>
#include <cstdio>

#include "scenefile/matrix.h"
#include "scenefile/scene_summary.h"
#include "tools/common/tool_output.h"

namespace tools {

namespace {

// "sphere" for SPHERE: the kind as a word.
std::string kindWord(scene::ObjectKind kind) {
  std::string word(scene::objectKindName(kind));
  for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return word;
}

std::string number(double value) {
  if (value == 0) value = 0;  // -0 (a mirrored axis) reads as 0
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string point(const glm::dvec3& p) {
  return "(" + number(p.x) + " " + number(p.y) + " " + number(p.z) + ")";
}

nlohmann::json triple(const glm::dvec3& p) {
  return nlohmann::json::array({p.x, p.y, p.z});
}

glm::dvec3 position(const scene::Camera& c) {
  return glm::dvec3(c.matrix[3]);
}
glm::dvec3 direction(const scene::Camera& c) {
  return scene::unitDirection(-glm::dvec3(c.matrix[2]));
}
glm::dvec3 up(const scene::Camera& c) {
  return scene::unitDirection(glm::dvec3(c.matrix[1]));
}

}  // namespace

std::string sceneInfoText(const std::string& shown, scene::Format format, std::uintmax_t bytes,
                          const scene::Scene& scene) {
  scene::SceneSummary summary = scene::summarizeScene(scene);
  std::string text = shown + ": " + std::string(scene::formatInfo(format).singular) + ", " +
                     countOf(bytes, "byte") + "\n";
  text += "  objects: " + std::to_string(scene.objects.size()) + " (";
  for (scene::ObjectKind kind : scene::kObjectKinds) {
    text +=
        (kind == scene::kObjectKinds[0] ? "" : ", ") + countOf(summary.count(kind), kindWord(kind));
  }
  text += ")\n  lights: " + std::to_string(summary.lights) + "\n";
  text += "  camera: at " + point(position(scene.camera)) + ", looking along " +
          point(direction(scene.camera));
  if (scene.view) {
    text += ", a vertical field of view of " + number(scene.view->verticalFovDegrees) + " degrees";
    if (scene.view->aspectRatio)
      text += " at an aspect ratio of " + number(*scene.view->aspectRatio);
  }
  text += "\n  box: ";
  text += summary.bounds ? point(summary.bounds->low) + " to " + point(summary.bounds->high)
                         : std::string("none");
  std::size_t planes = summary.count(scene::ObjectKind::Plane);
  if (planes) text += ", and " + countOf(planes, "plane") + ", infinite";
  if (summary.unbounded > planes) {
    text += ", and " + countOf(summary.unbounded - planes, "object") + " too large to bound";
  }
  text += "\n  materials: " + std::to_string(summary.materials) + " distinct\n";
  return text;
}

nlohmann::json sceneInfoJson(std::uintmax_t bytes, const scene::Scene& scene) {
  scene::SceneSummary summary = scene::summarizeScene(scene);
  nlohmann::json objects = {{"total", scene.objects.size()}};
  for (scene::ObjectKind kind : scene::kObjectKinds) objects[kindWord(kind)] = summary.count(kind);
  nlohmann::json camera = {{"position", triple(position(scene.camera))},
                           {"direction", triple(direction(scene.camera))},
                           {"up", triple(up(scene.camera))}};
  if (scene.view) {
    camera["verticalFov"] = scene.view->verticalFovDegrees;
    if (scene.view->aspectRatio) camera["aspectRatio"] = *scene.view->aspectRatio;
  }
  nlohmann::json bounds = nullptr;
  if (summary.bounds) {
    bounds = {{"low", triple(summary.bounds->low)}, {"high", triple(summary.bounds->high)}};
  }
  return {{"bytes", bytes},
          {"objects", objects},
          {"lights", summary.lights},
          {"materials", summary.materials},
          {"camera", camera},
          {"bounds", bounds},
          {"unbounded", summary.unbounded}};
}

}  // namespace tools
