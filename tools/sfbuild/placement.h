// Where the builder puts what it adds: a new object where the camera looks,
// resting on the ground (y = 0); a new light above the scene.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>

#include "scenefile/scene.h"

namespace sfbuild {

// How far ahead of the camera a new object goes when its forward ray meets
// the ground behind it, not at all, or farther than kMaxGroundDistance.
inline constexpr double kPlacementDistance = 8.0;
inline constexpr double kMaxGroundDistance = 50.0;
// How far above the objects' highest point a new light goes.
inline constexpr double kLightHeightAboveScene = 2.0;
// Where a new thing goes is rounded to this, far below what the eye tells
// apart, so that a saved file says 2 where the arithmetic gave 2 + 1e-15.
inline constexpr double kPlacementStep = 0.001;

// The lowest world y of the shape, exact (scene::objectBounds); a plane:
// its height when horizontal, minus infinity otherwise.
double lowestY(scene::ObjectKind kind, const glm::dmat4& matrix);

// The point the camera looks at: where its forward ray meets y = 0 in front
// of it and within kMaxGroundDistance, or kPlacementDistance along the ray;
// rounded to kPlacementStep.
glm::dvec3 placementPoint(const scene::Camera& camera);

// A new object's matrix: above placementPoint with its lowest point at
// y = 0; a plane is the ground itself (the identity).
glm::dmat4 placedObjectMatrix(scene::ObjectKind kind, const scene::Camera& camera);

// A new light: kLightHeightAboveScene above the highest point of the
// bounded objects, over the middle of their box; with none, above
// placementPoint.
glm::dvec3 placedLightPosition(const scene::Scene& scene);

}  // namespace sfbuild
