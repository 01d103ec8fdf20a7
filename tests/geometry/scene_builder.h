// Scenes built in code for the geometry cross-checks: affine maps, a fluent
// builder, every primitive at any scale, and a seeded scene of sheared and
// mirrored objects. Shared by the exact-reference and POV-Ray tests.
#pragma once

#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <random>

#include "scenefile/scene.h"
#include "scenefile/transform.h"

namespace testscenes {

using K = scene::ObjectKind;
using glm::dmat4;
using glm::dvec3;

inline dmat4 translate(double x, double y, double z) {
  return glm::translate(dmat4(1.0), dvec3(x, y, z));
}
inline dmat4 scale(double x, double y, double z) {
  return glm::scale(dmat4(1.0), dvec3(x, y, z));
}
inline dmat4 scale(double s) {
  return scale(s, s, s);
}
inline dmat4 rotate(double angle, const dvec3& axis) {
  return glm::rotate(dmat4(1.0), angle, axis);
}
// The identity plus `k` in row `row`, column `col`: x_row += k * x_col.
inline dmat4 shear(int row, int col, double k) {
  dmat4 m(1.0);
  m[col][row] = k;
  return m;
}

// A scene with one light above it (which object-identity tests ignore).
class SceneBuilder {
 public:
  SceneBuilder& camera(const dvec3& eye, const dvec3& target) {
    scene_.camera.matrix = scene::cameraFromLookAt(eye, target);
    return *this;
  }
  SceneBuilder& cameraMatrix(const dmat4& m) {
    scene_.camera.matrix = m;
    return *this;
  }
  SceneBuilder& add(K kind, const dmat4& m) {
    scene::Object o;
    o.kind = kind;
    o.matrix = m;
    scene_.objects.push_back(o);
    return *this;
  }
  scene::Scene build() {
    scene::Light light;
    light.matrix[3] = glm::dvec4(3.0, 10.0, 5.0, 1.0);
    scene_.lights.push_back(light);
    return scene_;
  }

 private:
  scene::Scene scene_;
};

// Every primitive, scaled by `s` about the origin and moved to `at`.
inline scene::Scene primitives(double s, const dvec3& at, const dvec3& eye, const dvec3& target) {
  dmat4 place = translate(at.x, at.y, at.z) * scale(s);
  auto p = [&](const dvec3& v) { return dvec3(place * glm::dvec4(v, 1.0)); };
  return SceneBuilder()
      .camera(p(eye), p(target))
      .add(K::Plane, place * translate(0, -1, 0))
      .add(K::Sphere, place * translate(-2.5, 0, 0))
      .add(K::Cube, place * rotate(0.3, {1, 0, 0}) * rotate(0.6, {0, 1, 0}))
      .add(K::Cylinder, place * translate(2.5, 0, 0) * rotate(0.4, {0, 0, 1}))
      .build();
}

// Every kind under shear, the plane tilted by it.
inline scene::Scene shearScene() {
  return SceneBuilder()
      .camera({0, 1, 9}, {0, 0, 0})
      // y += 0.2 x tilts the plane.
      .add(K::Plane, translate(0, -2, 0) * shear(1, 0, 0.2))
      .add(K::Cube,
           translate(-3, 0, 0) * shear(0, 1, 0.8) * shear(2, 0, 0.3) * rotate(0.3, {0, 1, 0}))
      .add(K::Sphere, shear(0, 1, 0.9) * shear(1, 2, -0.5))
      .add(K::Cylinder,
           translate(3, 0, 0) * shear(0, 1, 0.7) * shear(1, 0, -0.3) * scale(0.8, 1.2, 0.8))
      .build();
}

// A seeded scene of many objects under random affine maps with shear and
// mirrors; the bits come straight from mt19937_64, whose output the
// standard fixes, so the scene is the same on every platform.
inline scene::Scene randomAffineScene(std::uint64_t seed) {
  std::mt19937_64 bits(seed);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(bits() >> 11) * 0x1.0p-53;
  };
  SceneBuilder b;
  b.camera({0, 2, 25}, {0, 0, 0});
  b.add(K::Plane, translate(0, -8, 0) * rotate(0.1, {1, 0, 1}));
  for (int n = 0; n < 60; ++n) {
    K kind = static_cast<K>(1 + bits() % 3);
    dmat4 m =
        translate(uniform(-9, 9), uniform(-6, 6), uniform(-12, 8)) *
        rotate(uniform(0, 2 * std::numbers::pi),
               glm::normalize(dvec3(uniform(-1, 1), uniform(-1, 1), 1))) *
        shear(static_cast<int>(bits() % 3), static_cast<int>(bits() % 2 + 1) % 3,
              uniform(-0.6, 0.6)) *
        scale(uniform(0.2, 1.5) * (bits() % 4 == 0 ? -1 : 1), uniform(0.2, 1.5), uniform(0.2, 1.5));
    b.add(kind, m);
  }
  return b.build();
}

}  // namespace testscenes
