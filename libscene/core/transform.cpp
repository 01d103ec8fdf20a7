#include "scenefile/transform.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "scenefile/matrix.h"
#include "scenefile/validation.h"

namespace scene {

namespace {

// Applies O to M from the left (M <- O * M), touching only what O changes,
// so that translations and scales add no rounding of their own.
void applyOp(const TransformOp& op, glm::dmat4& m) {
  auto rotateRows = [&m](int i, int j, double angle) {
    // Rows i and j of M become c*row_i - s*row_j and s*row_i + c*row_j.
    double c = std::cos(angle);
    double s = std::sin(angle);
    for (int col = 0; col < 4; ++col) {
      double ri = m[col][i];
      double rj = m[col][j];
      m[col][i] = c * ri - s * rj;
      m[col][j] = s * ri + c * rj;
    }
  };
  switch (op.kind) {
    case TransformKind::Scale:
      for (int col = 0; col < 4; ++col) {
        for (int r = 0; r < 3; ++r) m[col][r] *= op.value[r];
      }
      return;
    case TransformKind::Translate:
      for (int r = 0; r < 3; ++r) m[3][r] += op.value[r];
      return;
    case TransformKind::RotateX:
      rotateRows(1, 2, op.value.x);
      return;
    case TransformKind::RotateY:
      rotateRows(2, 0, op.value.x);
      return;
    case TransformKind::RotateZ:
      rotateRows(0, 1, op.value.x);
      return;
  }
}

// The orthogonal factor of A's polar decomposition (Newton's iteration).
glm::dmat3 nearestOrthogonal(const glm::dmat3& a) {
  glm::dmat3 x = a;
  for (int i = 0; i < 100; ++i) {
    glm::dmat3 next = 0.5 * (x + glm::transpose(glm::inverse(x)));
    double change = 0.0;
    for (int c = 0; c < 3; ++c) change = std::max(change, glm::length(next[c] - x[c]));
    x = next;
    if (change < 1e-15) break;
  }
  return x;
}

// Euler angles of R = Rz(c) * Ry(b) * Rx(a). The angle about z is taken first
// and the other two from Rz(-c) * R, so that they make up for any error in c:
// near b = +-pi/2, where a and c are each ill-determined, the product stays
// exact (after Mike Day's "Extracting Euler angles from a rotation matrix").
glm::dvec3 eulerXYZ(const glm::dmat3& rot) {
  auto r = [&rot](int row, int col) { return rot[col][row]; };
  double c = std::atan2(r(1, 0), r(0, 0));
  double cc = std::cos(c);
  double sc = std::sin(c);
  double r00 = cc * r(0, 0) + sc * r(1, 0);
  double r11 = -sc * r(0, 1) + cc * r(1, 1);
  double r12 = -sc * r(0, 2) + cc * r(1, 2);
  double b = std::atan2(-r(2, 0), r00);
  double a = std::atan2(-r12, r11);
  return {a, b, c};
}

}  // namespace

glm::dmat4 transformMatrix(const TransformOp& op) {
  glm::dmat4 m(1.0);
  applyOp(op, m);
  return m;
}

glm::dmat4 composeTransform(std::span<const TransformOp> ops) {
  glm::dmat4 m(1.0);
  for (const TransformOp& op : ops) applyOp(op, m);
  return m;
}

glm::dmat4 composeTransform(std::span<const TransformOp> ops,
                            std::optional<std::size_t>& overflow) {
  glm::dmat4 m(1.0);
  for (std::size_t i = 0; i < ops.size(); ++i) {
    glm::dmat4 next = m;
    applyOp(ops[i], next);
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        if (!std::isfinite(next[c][r])) {
          overflow = i;
          return m;
        }
      }
    }
    m = next;
  }
  return m;
}

glm::dmat4 cameraFromLookAt(const glm::dvec3& location, const glm::dvec3& lookAt) {
  // Points 1e-320 or 1e200 apart underflow or overflow the plain
  // normalisation (to infinity, or to a zero vector that looks finite);
  // unitDirection scales them by a power of two first.
  glm::dvec3 forward = unitDirection(lookAt - location);
  glm::dvec3 upHint(0.0, 1.0, 0.0);
  if (glm::length(glm::cross(forward, upHint)) < kParallelTolerance) {
    upHint = glm::dvec3(0.0, 0.0, forward.y < 0.0 ? -1.0 : 1.0);
  }
  glm::dvec3 right = glm::normalize(glm::cross(forward, upHint));
  glm::dvec3 up = glm::cross(right, forward);
  // Cross products of axis vectors give -0 entries; adding +0 clears the
  // sign, which no reader of the matrix should have to see.
  glm::dvec3 back = -forward + 0.0;
  right += 0.0;
  up += 0.0;
  return glm::dmat4(glm::dvec4(right, 0.0), glm::dvec4(up, 0.0), glm::dvec4(back, 0.0),
                    glm::dvec4(location, 1.0));
}

LookAtCamera lookAtFromCamera(const glm::dmat4& camera) {
  LookAtCamera out;
  out.location = glm::dvec3(camera[3]);
  glm::dvec3 forward = unitDirection(-glm::dvec3(camera[2]));
  // A power of two at least as large as the eye's coordinates keeps the
  // rounding of location + forward * distance small against the distance;
  // at most 2^1023, the largest power of two, and halved while the point
  // overflows (an eye near the largest double looking further out).
  double extent = std::max({1.0, std::abs(out.location.x), std::abs(out.location.y),
                            std::abs(out.location.z)});
  double distance = std::exp2(std::min(std::ceil(std::log2(extent)), 1023.0));
  glm::dmat4 rebuilt;
  out.expressible = false;
  // Each halving costs a bit of the direction; past 40 of them the point
  // is no better than the eye itself.
  for (int halvings = 0; halvings < 40 && !out.expressible; ++halvings, distance /= 2) {
    out.lookAt = out.location + forward * distance;
    if (!std::isfinite(out.lookAt.x) || !std::isfinite(out.lookAt.y) ||
        !std::isfinite(out.lookAt.z) || out.lookAt == out.location) {
      continue;
    }
    glm::dvec3 d = out.lookAt - out.location;
    if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) continue;
    rebuilt = cameraFromLookAt(out.location, out.lookAt);
    out.expressible = scaledLength(-glm::dvec3(rebuilt[2]) - forward) <= kLookAtTolerance;
  }
  if (!out.expressible) return out;
  // Compare the matrix's up with the one the instruction camera would get.
  glm::dvec3 up = glm::dvec3(camera[1]);
  if (!isModerate(up)) up = unitDirection(up);
  up = unitDirection(up - glm::dot(up, forward) * forward);
  glm::dvec3 rebuiltUp = glm::dvec3(rebuilt[1]);
  out.roll = std::atan2(glm::dot(glm::cross(rebuiltUp, up), forward), glm::dot(rebuiltUp, up));
  return out;
}

bool TransformDecomposition::exact() const { return relativeError <= kDecompositionTolerance; }

TransformDecomposition decomposeTransform(const glm::dmat4& m) {
  TransformDecomposition out;
  glm::dmat3 a = linearPart(m);
  out.translation = glm::dvec3(m[3]);
  glm::dvec3 norms(scaledLength(a[0]), scaledLength(a[1]), scaledLength(a[2]));

  // Step 1: signs of the scale factors. Scales stay positive unless A is a
  // mirror; then one factor is negative, the one whose rotation turns least
  // (largest trace), so that SCALE -1 1 1 comes back as itself.
  double det = glm::determinant(a);
  glm::dvec3 bestSigns(1.0);
  if (det < 0.0) {
    double bestTrace = -std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      glm::dvec3 signs(1.0);
      signs[axis] = -1.0;
      double trace = 0.0;
      for (int i = 0; i < 3; ++i) trace += signs[i] * a[i][i] / norms[i];
      if (trace > bestTrace) {
        bestTrace = trace;
        bestSigns = signs;
      }
    }
  }
  out.scale = bestSigns * norms;

  // Step 2: the rotation. Without shear, A / S is already orthogonal up to
  // rounding; the polar factor is the nearest rotation either way.
  glm::dmat3 rot(a[0] / out.scale.x, a[1] / out.scale.y, a[2] / out.scale.z);
  rot = nearestOrthogonal(rot);
  out.rotation = eulerXYZ(rot);

  // Step 3: the operations, then what a reader would rebuild from them.
  auto add = [&out](TransformKind kind, glm::dvec3 value) {
    out.ops.push_back(TransformOp{kind, value, {}});
  };
  if (out.scale != glm::dvec3(1.0)) add(TransformKind::Scale, out.scale);
  if (out.rotation.x != 0.0) add(TransformKind::RotateX, glm::dvec3(out.rotation.x, 0.0, 0.0));
  if (out.rotation.y != 0.0) add(TransformKind::RotateY, glm::dvec3(out.rotation.y, 0.0, 0.0));
  if (out.rotation.z != 0.0) add(TransformKind::RotateZ, glm::dvec3(out.rotation.z, 0.0, 0.0));
  if (out.translation != glm::dvec3(0.0)) add(TransformKind::Translate, out.translation);
  out.recomposed = composeTransform(out.ops);

  for (int c = 0; c < 3; ++c) {
    double columnError = glm::length(glm::dvec3(out.recomposed[c]) - a[c]);
    out.relativeError = std::max(out.relativeError, columnError / norms[c]);
  }
  return out;
}

}  // namespace scene
