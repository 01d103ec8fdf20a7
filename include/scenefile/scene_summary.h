/// @file
/// What a scene holds, summed up (as `assimp info` sums up a model): its
/// objects by kind, its lights, its distinct materials and the box its
/// finite objects fill.
#pragma once

#include <array>
#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <iterator>
#include <optional>

#include "scenefile/scene.h"

namespace scene {

/// A box in world space, its sides parallel to the axes.
struct Bounds {
  glm::dvec3 low{0.0};
  glm::dvec3 high{0.0};
  friend bool operator==(const Bounds&, const Bounds&) = default;
};

/// The world box of a primitive under its matrix, exact: the extremes of the
/// unit sphere, the cube [-1, 1]^3 or the closed cylinder (radius 1, y in
/// [-1, 1]) along each world axis. Nothing for a PLANE, which is infinite.
std::optional<Bounds> objectBounds(ObjectKind kind, const glm::dmat4& matrix);

struct SceneSummary {
  /// The objects of each kind, in the order of kObjectKinds.
  std::array<std::size_t, std::size(kObjectKinds)> objects{};
  std::size_t lights = 0;
  /// The distinct materials among the objects (equal in every value).
  std::size_t materials = 0;
  /// The box of the objects that have one (every kind but PLANE), where
  /// every number is finite; nothing when no object has one.
  std::optional<Bounds> bounds;
  /// The objects left out of `bounds`: the planes, and any whose box is not
  /// finite.
  std::size_t unbounded = 0;

  /// The objects of `kind`.
  std::size_t count(ObjectKind kind) const { return objects[static_cast<std::size_t>(kind)]; }
};

/// The summary of `scene`.
SceneSummary summarizeScene(const Scene& scene);

}  // namespace scene
