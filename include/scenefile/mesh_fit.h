/// @file
/// Recognising the four primitives in a triangle mesh from another program
/// (a glTF file, a Blender object): which primitive the vertices describe,
/// and the transform that takes the unit primitive onto them (the mesh's own
/// size, offset and orientation). The inverse of scenefile/mesh.h.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string>

#include "scenefile/scene.h"

namespace scene {

/// The largest deviation a fit accepts, relative to the shape's size: far
/// above float rounding (1e-7), far below any visible difference.
inline constexpr double kFitTolerance = 1e-4;

/// A primitive recognised in a mesh.
struct MeshFit {
  /// Which primitive.
  ObjectKind kind = ObjectKind::Sphere;
  /// Takes the unit primitive of FORMATS.md onto the mesh, in the mesh's
  /// space: the object's matrix is the mesh's placement times this.
  glm::dmat4 shape{1.0};
  /// The largest distance of a vertex from the fitted surface, relative to
  /// the shape's size (and for a sphere, cylinder or disc, how far the mesh
  /// falls short of the whole shape's volume or area does not count: that is
  /// tessellation).
  double error = 0.0;
};

/// What fitPrimitive found.
struct FitResult {
  /// Set when some primitive fits within the tolerance.
  std::optional<MeshFit> fit;
  /// Otherwise the nearest candidate and why it failed, for a diagnostic
  /// ("it has no area", "nearest: a CYLINDER, 3.2% off", ...).
  std::string reason;
};

/// Fits `positions` as indexed triangles, three indices a triangle, counter-
/// clockwise seen from outside. Tried in turn: a flat quad or disc (PLANE,
/// with the mesh's front as +Y), a box, a capped cylinder along any axis, a
/// sphere; docs/GLTF.md ("Other programs' meshes") gives the rules. Indices
/// that are not whole triangles, an index past the positions and a vertex
/// that is not finite fit nothing, and the reason says so.
FitResult fitPrimitive(std::span<const glm::dvec3> positions,
                       std::span<const std::uint32_t> indices, double tolerance = kFitTolerance);

}  // namespace scene
