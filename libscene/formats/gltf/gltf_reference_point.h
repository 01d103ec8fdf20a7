// Where a glTF light's inverse-square falloff is made to agree with a scene
// file's light, which does not fall off (docs/GLTF.md, "Lights"): the point
// the camera looks at. The writer and the reader use the same rule, the
// reader on the scene it has read.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "scenefile/scene.h"

namespace scene::gltf {

struct ReferencePoint {
  enum class Source : std::uint8_t {
    CameraRay,      // where the camera's forward ray first meets an object
    ObjectsCentre,  // the ray meets none: the centre of the bounded objects' box
    NearestPlane,   // only planes, which the ray misses: the nearest plane's point nearest the eye
    Eye,            // none of those: the camera's eye
  };
  glm::dvec3 point{0.0};
  Source source = Source::Eye;
};

// The reference point of a scene, in the order of ReferencePoint::Source: the
// first rule that gives a finite point.
ReferencePoint referencePoint(const Scene& scene);

// The reference distance of a light at `light`: its distance to the point;
// 1 where it stands on the point (no intensity matches an inverse-square
// light there), and the largest double where the distance overflows.
double referenceDistance(const glm::dvec3& light, const ReferencePoint& reference);

// The point in words, for the notes that state the reference distance:
// "the point the camera looks at, on the first object its forward ray
// meets, (0 0.9 2.7)".
std::string describeReferencePoint(const ReferencePoint& reference);

// A number to six significant digits, in its shortest form: what a message
// needs of a distance or an intensity.
std::string approximateNumber(double value);

// The smallest t > 0 at which origin + t * direction meets the object (a
// solid, or a PLANE's infinite plane), if any: the camera ray's test.
std::optional<double> rayHit(const Object& object, const glm::dvec3& origin,
                             const glm::dvec3& direction);

}  // namespace scene::gltf
