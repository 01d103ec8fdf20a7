// Building small scenes in the renderer's tests.
#pragma once

#include <vector>

#include "scenefile/scene.h"
#include "scenefile/transform.h"

namespace render::testing {

inline scene::TransformOp scale(double x, double y, double z) {
  return {scene::TransformKind::Scale, {x, y, z}, {}};
}
inline scene::TransformOp scale(double s) {
  return scale(s, s, s);
}
inline scene::TransformOp translate(double x, double y, double z) {
  return {scene::TransformKind::Translate, {x, y, z}, {}};
}
inline scene::TransformOp rotateX(double a) {
  return {scene::TransformKind::RotateX, {a, 0, 0}, {}};
}
inline scene::TransformOp rotateY(double a) {
  return {scene::TransformKind::RotateY, {a, 0, 0}, {}};
}
inline scene::TransformOp rotateZ(double a) {
  return {scene::TransformKind::RotateZ, {a, 0, 0}, {}};
}

inline scene::Object object(scene::ObjectKind kind, std::vector<scene::TransformOp> ops = {},
                            scene::Material material = {}) {
  scene::Object o;
  o.kind = kind;
  o.material = material;
  o.matrix = scene::composeTransform(ops);
  return o;
}

// A material that shows only C * L * ambient: no diffuse, no highlight.
inline scene::Material flat(const glm::dvec3& colour, double ambient = 1.0) {
  scene::Material m;
  m.colour = colour;
  m.ambient = ambient;
  m.diffuse = 0.0;
  m.specular = 0.0;
  return m;
}

inline scene::Light light(const glm::dvec3& position, const glm::dvec3& colour = glm::dvec3(1.0)) {
  scene::Light l;
  l.matrix[3] = glm::dvec4(position, 1.0);
  l.colour = colour;
  return l;
}

inline scene::Scene sceneLookingAt(const glm::dvec3& eye, const glm::dvec3& target) {
  scene::Scene s;
  s.camera.matrix = scene::cameraFromLookAt(eye, target);
  return s;
}

}  // namespace render::testing
