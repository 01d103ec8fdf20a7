/// @file
/// The triangle meshes that stand for the four primitives wherever a program
/// needs polygons instead of exact shapes: the glTF writer, and the builder,
/// which draws the same meshes that a glTF export holds.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "scenefile/scene.h"

namespace scene {

/// Indexed triangles in the primitive's local space, counter-clockwise seen
/// from outside (from +Y for the plane), with one unit normal per vertex.
struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<std::uint32_t> indices;  ///< three per triangle
};

/// How finely curved surfaces are cut: the sphere and the cylinder get
/// `segments` vertices around their axis, and the sphere segments / 2 rings.
inline constexpr int kDefaultSegments = 32;
inline constexpr int kMinSegments = 3;     ///< the fewest segments a mesh takes
inline constexpr int kMaxSegments = 1024;  ///< the most segments a mesh takes

/// The unit sphere: a UV sphere with one vertex at each pole.
TriangleMesh sphereMesh(int segments = kDefaultSegments);
/// The box [-1, 1]^3 with flat normals: four vertices per face.
TriangleMesh cubeMesh();
/// Radius 1 about Y from y = -1 to 1, closed by two flat caps; the side and
/// the caps have their own vertices, so the rim's normals stay sharp.
TriangleMesh cylinderMesh(int segments = kDefaultSegments);
/// The square [-halfSize, halfSize]^2 of the plane y = 0, facing +Y: the
/// infinite PLANE made finite.
TriangleMesh planeMesh(float halfSize);

/// The half-size of the square that stands for every PLANE of `scene`:
/// twice the farthest corner of the bounds of everything else (the camera's
/// eye, the lights, each object's box, each plane's origin) from each
/// plane's origin in its own x and z, rounded up to a power of two (at
/// least 1, at most 1e30), so that the square reaches past the scene.
float scenePlaneHalfSize(const Scene& scene);

/// The mesh of `kind`; `planeHalfSize` is used by PLANE alone.
TriangleMesh primitiveMesh(ObjectKind kind, int segments, float planeHalfSize);

}  // namespace scene
