// Seeded random scenes for property tests: every kind of record, materials
// in their ranges, matrices with rotation, non-uniform scale, shear and
// mirrors, and numbers from subnormal to 1e300 where nothing bounds them.
// Header-only: the unit tests and the glTF validator test both draw from it.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iterator>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "scenefile/scene.h"
#include "scenefile/transform.h"

namespace scene::testing {

// Every double a scene holds, in a fixed order: the camera (matrix, colour,
// LOOK_AT), each light (matrix, colour), each object (colour, material,
// matrix, operations). A loop of its own, so that a test of finiteness or of
// bits does not trust the library's own checks.
inline void forEachNumber(const Scene& s, const std::function<void(double)>& f) {
  auto matrix = [&f](const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) f(m[c][r]);
    }
  };
  auto vector = [&f](const glm::dvec3& v) {
    for (int i = 0; i < 3; ++i) f(v[i]);
  };
  matrix(s.camera.matrix);
  vector(s.camera.colour);
  if (s.camera.lookAt) vector(*s.camera.lookAt);
  for (const Light& light : s.lights) {
    matrix(light.matrix);
    vector(light.colour);
  }
  for (const Object& object : s.objects) {
    const Material& m = object.material;
    vector(m.colour);
    for (double v :
         {m.ambient, m.diffuse, m.specular, m.shininess, m.reflectivity, m.transparency, m.ri}) {
      f(v);
    }
    matrix(object.matrix);
    if (object.transforms) {
      for (const TransformOp& op : *object.transforms) vector(op.value);
    }
  }
}

// The bits of every number, for comparisons where -0 is not 0.
inline std::vector<std::uint64_t> numberBits(const Scene& s) {
  std::vector<std::uint64_t> bits;
  forEachNumber(s, [&bits](double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    bits.push_back(b);
  });
  return bits;
}

// The first number that is not finite, described; empty when all are.
inline std::string firstNonFinite(const Scene& s) {
  std::size_t index = 0;
  std::string found;
  forEachNumber(s, [&](double v) {
    if (found.empty() && !std::isfinite(v)) found = "number " + std::to_string(index);
    ++index;
  });
  return found;
}

class RandomSceneGenerator {
 public:
  explicit RandomSceneGenerator(std::uint64_t seed) : rng_(seed) {}

  // `extreme` allows the huge and subnormal magnitudes; without it every
  // number stays within 1e6 (what other programs are expected to cope with).
  Scene scene(bool extreme = true) {
    extreme_ = extreme;
    limits_ = false;
    return build();
  }

  // Numbers at the edges of the doubles wherever a valid scene may hold
  // them: within a factor of 2 of the largest double, the smallest
  // subnormals, -0, in positions, light matrices and colours, camera axes
  // scaled by 2^-1000 to 2^1000, and materials (instruction scenes) from
  // -0 and subnormals to the largest SHININESS and RI.
  Scene limitScene() {
    extreme_ = true;
    limits_ = true;
    return build();
  }

 private:
  Scene build() {
    Scene s;
    if (pick(2)) {
      glm::dvec3 eye = position();
      glm::dvec3 target = eye + direction() * uniform(0.5, 50.0);
      s.camera.matrix = cameraFromLookAt(eye, target);
      if (pick(2)) s.camera.lookAt = target;
    } else {
      s.camera.matrix = glm::dmat4(rotation());
      if (pick(4) == 0) s.camera.matrix = s.camera.matrix * glm::dmat4(glm::dmat3(uniform(0.5, 2)));
      if (limits_ && pick(3) == 0) {
        double axes = std::ldexp(uniform(1, 2), static_cast<int>(pick(2001)) - 1000);
        s.camera.matrix = s.camera.matrix * glm::dmat4(glm::dmat3(axes));
      }
      s.camera.matrix[3] = glm::dvec4(position(), 1.0);
    }
    s.camera.colour = {unit(), any(), unit()};
    int lights = static_cast<int>(pick(4));
    for (int i = 0; i < lights; ++i) {
      Light light;
      light.colour = {nonNegative(), nonNegative(), pick(5) ? nonNegative() : 0.0};
      if (pick(3) == 0) {
        for (int c = 0; c < 4; ++c) {
          for (int r = 0; r < 3; ++r) light.matrix[c][r] = any();
        }
      } else {
        light.matrix[3] = glm::dvec4(position(), 1.0);
      }
      s.lights.push_back(light);
    }
    int objects = static_cast<int>(pick(9));
    for (int i = 0; i < objects; ++i) s.objects.push_back(object());
    if (pick(3) == 0) s.outputFile = "out" + std::to_string(pick(100)) + ".ppm";
    return s;
  }

 public:
  Object object() {
    Object o;
    o.kind = kObjectKinds[pick(std::size(kObjectKinds))];
    Material& m = o.material;
    m.colour = {unit() * 1.2, unit(), pick(8) ? unit() : 0.0};
    if (pick(2)) {
      m.ambient = unit();
      m.diffuse = unit();
      m.specular = pick(3) ? unit() : 0.9;
      m.shininess = std::pow(10.0, uniform(-2, 4));
      m.reflectivity = pick(2) ? unit() : 0.0;
      m.transparency = pick(2) ? unit() : 0.0;
      m.ri = pick(2) ? uniform(0.5, 3.0) : 1.0;
      if (limits_) {
        for (double* v : {&m.ambient, &m.diffuse, &m.specular, &m.reflectivity, &m.transparency}) {
          if (pick(3) == 0) *v = edgeOfUnit();
        }
        if (pick(3) == 0) m.shininess = edgePositive();
        if (pick(3) == 0) m.ri = edgePositive();
      }
    }
    if (limits_ && pick(4) == 0) m.colour = {edgeNonNegative(), edgeNonNegative(), 0.0};
    switch (pick(3)) {
      case 0: {
        // An instruction file's operations.
        std::vector<TransformOp> ops;
        int count = static_cast<int>(pick(5));
        for (int k = 0; k < count; ++k) {
          TransformOp op;
          switch (pick(3)) {
            case 0:
              op.kind = TransformKind::Scale;
              op.value = {factor(), factor(), factor()};
              break;
            case 1:
              op.kind = TransformKind::Translate;
              op.value = position();
              break;
            default:
              op.kind = static_cast<TransformKind>(2 + pick(3));
              op.value = {uniform(-7, 7), 0.0, 0.0};
          }
          ops.push_back(op);
        }
        o.matrix = composeTransform(ops);
        o.transforms = ops;
        break;
      }
      case 1: {
        // Rotation and scale.
        glm::dmat3 s(1.0);
        for (int k = 0; k < 3; ++k) s[k][k] = factor();
        o.matrix = glm::dmat4(rotation() * s);
        o.matrix[3] = glm::dvec4(position(), 1.0);
        break;
      }
      default: {
        // Any invertible block: rotation, scale, rotation (shear).
        glm::dmat3 s(1.0);
        for (int k = 0; k < 3; ++k) s[k][k] = factor();
        o.matrix = glm::dmat4(rotation() * s * rotation());
        o.matrix[3] = glm::dvec4(position(), 1.0);
      }
    }
    return o;
  }

  std::uint64_t pick(std::uint64_t n) { return rng_() % n; }
  double unit() { return uniform(0.0, 1.0); }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }

 private:
  // Any double where nothing bounds it.
  double any() {
    if (!extreme_) return uniform(-1e3, 1e3);
    if (limits_ && pick(3) == 0) return pick(2) ? edgeNonNegative() : -edgeNonNegative();
    switch (pick(6)) {
      case 0:
        return static_cast<double>(static_cast<int>(pick(2001)) - 1000) / 8.0;
      case 1:
        return std::ldexp(uniform(-1, 1), static_cast<int>(pick(2000)) - 1000);
      case 2:
        return 4.9406564584124654e-324 * static_cast<double>(pick(1000));
      case 3:
        return -0.0;
      default:
        return uniform(-1e3, 1e3);
    }
  }
  double nonNegative() {
    if (limits_ && pick(3) == 0) return edgeNonNegative();
    return pick(4) == 0 ? uniform(1.0, 10.0) : unit();
  }
  // Near the largest double, a subnormal, the smallest normal or a zero.
  double edgeNonNegative() {
    constexpr double kLargest = std::numeric_limits<double>::max();
    switch (pick(5)) {
      case 0:
        return kLargest * uniform(0.5, 1.0);
      case 1:
        return kLargest;
      case 2:
        return std::numeric_limits<double>::denorm_min() * static_cast<double>(1 + pick(4));
      case 3:
        return std::numeric_limits<double>::min();
      default:
        return pick(2) ? -0.0 : 0.0;
    }
  }
  // In [0, 1]: -0, a subnormal, the smallest normal, 1 or just below it.
  double edgeOfUnit() {
    switch (pick(5)) {
      case 0:
        return -0.0;
      case 1:
        return std::numeric_limits<double>::denorm_min();
      case 2:
        return std::numeric_limits<double>::min();
      case 3:
        return 1.0;
      default:
        return std::nextafter(1.0, 0.0);
    }
  }
  // Above 0: near the largest double or a subnormal.
  double edgePositive() {
    double v = edgeNonNegative();
    return v > 0.0 ? v : std::numeric_limits<double>::denorm_min();
  }
  glm::dvec3 position() {
    if (extreme_ && pick(limits_ ? 3 : 8) == 0) return {any(), any(), any()};
    return {uniform(-100, 100), uniform(-100, 100), pick(4) ? uniform(-100, 100) : -0.0};
  }
  glm::dvec3 direction() {
    glm::dvec3 d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    return glm::length(d) > 1e-3 ? glm::normalize(d) : glm::dvec3(0, 0, -1);
  }
  glm::dmat3 rotation() {
    if (pick(5) == 0) return glm::dmat3(1.0);
    glm::dquat q(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    if (glm::length(q) < 1e-3) return glm::dmat3(1.0);
    return glm::mat3_cast(glm::normalize(q));
  }
  // A scale factor from 1e-3 to 1e3 (extreme: 1e-4 to 1e4), either sign.
  double factor() {
    double e = extreme_ ? 4.0 : 3.0;
    double f = std::pow(10.0, uniform(-e, e));
    return pick(5) == 0 ? -f : f;
  }

  std::mt19937_64 rng_;
  bool extreme_ = true;
  bool limits_ = false;
};

}  // namespace scene::testing
