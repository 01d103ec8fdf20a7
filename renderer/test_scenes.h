// Building small scenes in the renderer's tests.
#pragma once

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "renderer/render_scene.h"
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

// Seeded random numbers for the property tests.
class Random {
 public:
  explicit Random(std::uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  glm::dvec3 point(double reach) {
    return {uniform(-reach, reach), uniform(-reach, reach), uniform(-reach, reach)};
  }
  glm::dvec3 direction() {
    for (;;) {
      glm::dvec3 d = point(1.0);
      double l = glm::length(d);
      if (l > 0.1 && l <= 1.0) return d / l;
    }
  }

 private:
  std::mt19937_64 rng_;
};

// Objects of every kind (planes too, which stay outside the hierarchy) in a
// box of side 20, scaled, rotated and moved at random; some transparent.
inline scene::Scene randomScene(Random& random, int objects) {
  scene::Scene s = sceneLookingAt({0, 0, 30}, {0, 0, 0});
  constexpr scene::ObjectKind kKinds[] = {scene::ObjectKind::Sphere, scene::ObjectKind::Cube,
                                          scene::ObjectKind::Cylinder, scene::ObjectKind::Plane};
  for (int i = 0; i < objects; ++i) {
    // One plane in twenty.
    scene::ObjectKind kind = random.below(20) == 0 ? kKinds[3] : kKinds[random.below(3)];
    glm::dvec3 at = random.point(10.0);
    scene::Material m;
    m.colour = {random.uniform(0, 1), random.uniform(0, 1), random.uniform(0, 1)};
    m.reflectivity = random.below(3) == 0 ? 0.5 : 0.0;
    m.transparency = random.below(4) == 0 ? 0.7 : 0.0;
    m.ri = 1.5;
    s.objects.push_back(
        object(kind,
               {scale(random.uniform(0.2, 2), random.uniform(0.2, 2), random.uniform(0.2, 2)),
                rotateX(random.uniform(-3.2, 3.2)), rotateY(random.uniform(-3.2, 3.2)),
                rotateZ(random.uniform(-3.2, 3.2)), translate(at.x, at.y, at.z)},
               m));
  }
  s.lights.push_back(light({20, 30, 40}));
  s.lights.push_back(light({-25, 10, 5}, {0.5, 0.5, 0.4}));
  return s;
}

inline void expectSameHit(const std::optional<Hit>& packet, const std::optional<Hit>& alone,
                          const std::string& where) {
  ASSERT_EQ(packet.has_value(), alone.has_value()) << where;
  if (!alone) return;
  // Exact: the same object test on the same ray gives the same numbers.
  EXPECT_EQ(packet->t, alone->t) << where;
  EXPECT_EQ(packet->object, alone->object) << where;
  EXPECT_EQ(packet->point, alone->point) << where;
  EXPECT_EQ(packet->pointError, alone->pointError) << where;
  EXPECT_EQ(packet->normal, alone->normal) << where;
  EXPECT_EQ(packet->fromInside, alone->fromInside) << where;
}

}  // namespace render::testing
