/// @file
/// Small dense linear algebra on the 3x3 block of a transform, done with the
/// care that the validator and the decomposition need.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace scene {

/// The upper-left 3x3 block: the linear part of an affine transform.
glm::dmat3 linearPart(const glm::dmat4& m);

/// Singular values in descending order, by one-sided Jacobi rotations, which
/// keep relative accuracy even for a nearly singular block.
glm::dvec3 singularValues(const glm::dmat3& a);

/// The 2-norm condition number sigma_max / sigma_min; infinity when singular.
double conditionNumber(const glm::dmat3& a);

/// conditionNumber(a) > limit, where a cheap Frobenius-norm bound decides most
/// matrices without the SVD (the validator runs this once per object).
bool conditionNumberExceeds(const glm::dmat3& a, double limit);

/// A = U * diag(sigma) * V^T with U and V rotations (determinant +1); a
/// mirror leaves its sign on the last entry of sigma. By one-sided Jacobi
/// rotations, as singularValues, with the rotations kept. Used to write a
/// matrix with shear as two rotation-and-scale transforms.
struct RotationScaleRotation {
  glm::dmat3 u{1.0};
  glm::dvec3 sigma{1.0};
  glm::dmat3 v{1.0};
};
/// The RotationScaleRotation of `a`.
RotationScaleRotation rotationScaleRotation(const glm::dmat3& a);

/// The length of v with no overflow or underflow on the way: v is first
/// scaled by a power of two (exactly) so that its largest component lies in
/// [1, 2). A vector of components 1e-300 or 1e300 has a length, not 0 or
/// infinity; the result itself overflows only when the length does.
double scaledLength(const glm::dvec3& v);

/// v / |v| by the same scaling, so that any finite non-zero vector, however
/// short or long, has a direction. Zero for the zero vector.
glm::dvec3 scaledNormalize(const glm::dvec3& v);

/// Whether v * v is a normal double (between 2^-960 and 2^960), so that
/// glm::normalize neither underflows nor overflows on v.
bool isModerate(const glm::dvec3& v);

/// v / |v| for any finite vector: glm::normalize where v is moderate (so that
/// ordinary values keep the bits they always had), else scaledNormalize. The
/// direction of the zero vector is zero.
glm::dvec3 unitDirection(const glm::dvec3& v);

/// The transpose of a 4x4, as a file written column by column needs.
glm::dmat4 transposed(const glm::dmat4& m);

}  // namespace scene
