#include "scenefile/matrix.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/common.hpp>
#include <glm/gtc/matrix_access.hpp>
#include <glm/matrix.hpp>

namespace scene {

glm::dmat3 linearPart(const glm::dmat4& m) { return glm::dmat3(m); }

glm::dmat4 transposed(const glm::dmat4& m) { return glm::transpose(m); }

glm::dvec3 singularValues(const glm::dmat3& a) {
  glm::dvec3 sigma = glm::abs(rotationScaleRotation(a).sigma);
  std::sort(&sigma[0], &sigma[0] + 3, [](double x, double y) { return x > y; });
  return sigma;
}

RotationScaleRotation rotationScaleRotation(const glm::dmat3& a) {
  // One-sided Jacobi (Hestenes), which keeps relative accuracy even for a
  // nearly singular block. Rotate pairs of columns of W = A * V until they are orthogonal: then
  // W = U * diag(|w_i|).
  glm::dmat3 w = a;
  glm::dmat3 v(1.0);
  for (int sweep = 0; sweep < 60; ++sweep) {
    bool rotated = false;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        double alpha = glm::dot(w[p], w[p]);
        double beta = glm::dot(w[q], w[q]);
        double gamma = glm::dot(w[p], w[q]);
        if (gamma == 0.0 ||
            std::abs(gamma) <= std::numeric_limits<double>::epsilon() * std::sqrt(alpha * beta)) {
          continue;
        }
        rotated = true;
        double zeta = (beta - alpha) / (2.0 * gamma);
        double t = std::copysign(1.0, zeta) / (std::abs(zeta) + std::hypot(1.0, zeta));
        double c = 1.0 / std::hypot(1.0, t);
        double s = c * t;
        glm::dvec3 wp = w[p];
        w[p] = c * wp - s * w[q];
        w[q] = s * wp + c * w[q];
        glm::dvec3 vp = v[p];
        v[p] = c * vp - s * v[q];
        v[q] = s * vp + c * v[q];
      }
    }
    if (!rotated) break;
  }
  RotationScaleRotation out;
  out.v = v;
  for (int i = 0; i < 3; ++i) {
    out.sigma[i] = glm::length(w[i]);
    out.u[i] = out.sigma[i] > 0.0 ? w[i] / out.sigma[i] : glm::dvec3(0.0);
  }
  // A singular block leaves a zero column of U: complete it to a basis.
  for (int i = 0; i < 3; ++i) {
    if (out.sigma[i] == 0.0) {
      out.u[i] = glm::normalize(glm::cross(out.u[(i + 1) % 3], out.u[(i + 2) % 3]));
    }
  }
  // Make both factors rotations; their signs move into sigma.
  if (glm::determinant(out.v) < 0.0) {
    out.v[2] = -out.v[2];
    out.u[2] = -out.u[2];
  }
  if (glm::determinant(out.u) < 0.0) {
    out.u[2] = -out.u[2];
    out.sigma[2] = -out.sigma[2];
  }
  return out;
}

namespace {

double frobeniusNorm(const glm::dmat3& m) {
  return std::sqrt(glm::dot(m[0], m[0]) + glm::dot(m[1], m[1]) + glm::dot(m[2], m[2]));
}

}  // namespace

double conditionNumber(const glm::dmat3& a) {
  double det = glm::determinant(a);
  if (det == 0.0 || !std::isfinite(det)) return std::numeric_limits<double>::infinity();
  glm::dvec3 sigma = singularValues(a);
  if (sigma.z == 0.0) return std::numeric_limits<double>::infinity();
  return sigma.x / sigma.z;
}

bool conditionNumberExceeds(const glm::dmat3& a, double limit) {
  double det = glm::determinant(a);
  if (det == 0.0 || !std::isfinite(det)) return true;
  // kappa_F = |A|_F |A^-1|_F lies in [kappa_2, 3 kappa_2], and costs no
  // iteration: it settles all but the matrices near the limit. The adjugate
  // is formed directly, since glm::inverse divides by the determinant first.
  glm::dmat3 adjugate = glm::transpose(
      glm::dmat3(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]), glm::cross(a[0], a[1])));
  double kappaF = frobeniusNorm(a) * frobeniusNorm(adjugate) / std::abs(det);
  if (std::isfinite(kappaF)) {
    if (kappaF <= limit) return false;
    if (kappaF > 3.0 * limit) return true;
  }
  return conditionNumber(a) > limit;
}

namespace {

// The power of two that brings the largest component of v into [1, 2); 0
// for a zero or non-finite vector.
int scaleExponent(const glm::dvec3& v) {
  double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(largest > 0.0) || !std::isfinite(largest)) return 0;
  int exponent = 0;
  std::frexp(largest, &exponent);
  return exponent - 1;
}

}  // namespace

double scaledLength(const glm::dvec3& v) {
  int e = scaleExponent(v);
  glm::dvec3 w(std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e));
  return std::ldexp(std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z), e);
}

glm::dvec3 scaledNormalize(const glm::dvec3& v) {
  int e = scaleExponent(v);
  glm::dvec3 w(std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e));
  double length = std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
  if (!(length > 0.0)) return glm::dvec3(0.0);
  return w / length;
}

bool isModerate(const glm::dvec3& v) {
  double d = glm::dot(v, v);
  return d >= 0x1p-960 && d <= 0x1p960;
}

glm::dvec3 unitDirection(const glm::dvec3& v) {
  return isModerate(v) ? glm::normalize(v) : scaledNormalize(v);
}

}  // namespace scene
