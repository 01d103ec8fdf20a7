/// @file
/// Transforms between the two formats: composing an instruction file's
/// operations into a matrix, and decomposing a matrix back into operations.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scenefile/scene.h"

namespace scene {

/// The matrix of one operation, as FORMATS.md defines it.
glm::dmat4 transformMatrix(const TransformOp& op);

/// M = Ok * ... * O2 * O1 for operations O1..Ok in file order.
glm::dmat4 composeTransform(std::span<const TransformOp> ops);

/// The same product, stopping at the first operation after which an entry of
/// the matrix is no longer finite (a chain of SCALE 1e200): its index in
/// `overflow`, and the matrix as it was before it.
glm::dmat4 composeTransform(std::span<const TransformOp> ops,
                            std::optional<std::size_t>& overflow);

/// The instruction camera: eye at `location`, forward toward `lookAt`, up from
/// world +Y (or from -Z / +Z when looking straight down / up). Columns are
/// right, up, -forward and the eye. `location != lookAt` is the caller's.
glm::dmat4 cameraFromLookAt(const glm::dvec3& location, const glm::dvec3& lookAt);

/// A LOOK_AT description of a camera matrix. `roll` is the angle in radians
/// by which the matrix's up turns away from the up an instruction camera would
/// get; only a roll of (nearly) 0 can be written exactly.
/// `expressible` is false when no LOOK_AT within the doubles gives the
/// camera's forward (within kLookAtTolerance): an eye at the largest double
/// looking further out has none.
struct LookAtCamera {
  glm::dvec3 location{0.0};           ///< LOCATION: the eye
  glm::dvec3 lookAt{0.0, 0.0, -1.0};  ///< LOOK_AT: a point ahead
  double roll = 0.0;                  ///< radians
  bool expressible = true;            ///< see above
};
/// The LOOK_AT description of the camera matrix `camera`.
LookAtCamera lookAtFromCamera(const glm::dmat4& camera);

/// How far the forward that LOOK_AT gives back may turn from the camera's.
inline constexpr double kLookAtTolerance = 1e-12;

/// Roll below this (radians) is rounding, not intent.
inline constexpr double kRollTolerance = 1e-9;

/// M = T * Rz * Ry * Rx * S: the form an instruction file can write.
struct TransformDecomposition {
  glm::dvec3 scale{1.0};
  glm::dvec3 rotation{0.0};  ///< about x, y, z in radians, applied x first
  glm::dvec3 translation{0.0};
  /// The operations SCALE, ROTATE_X, ROTATE_Y, ROTATE_Z, TRANSLATE, without
  /// those that do nothing.
  std::vector<TransformOp> ops;
  /// composeTransform(ops): what a reader of the written file gets back.
  glm::dmat4 recomposed{1.0};
  /// Largest |recomposed - M| of the 3x3 block relative to its column's norm;
  /// the translation is exact.
  double relativeError = 0.0;
  bool exact() const;
};

/// Relative error per matrix column below which a decomposition is exact
/// (the rounding of the operations' numbers, not a change of shape).
inline constexpr double kDecompositionTolerance = 1e-12;

/// Decomposes the affine matrix M. A matrix with shear gets the nearest
/// rotation and scale (polar decomposition), and exact() is then false.
/// Negative determinants become a negative scale factor.
TransformDecomposition decomposeTransform(const glm::dmat4& m);

}  // namespace scene
