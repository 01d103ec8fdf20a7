#include "libscene/matrix.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/gtc/matrix_access.hpp>
#include <glm/matrix.hpp>

namespace scene {

glm::dmat3 linearPart(const glm::dmat4& m) { return glm::dmat3(m); }

glm::dmat4 transposed(const glm::dmat4& m) { return glm::transpose(m); }

glm::dvec3 singularValues(const glm::dmat3& a) {
  // One-sided Jacobi (Hestenes): rotate pairs of columns until they are
  // orthogonal; the column norms are then the singular values.
  glm::dmat3 u = a;
  for (int sweep = 0; sweep < 30; ++sweep) {
    bool rotated = false;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        double alpha = glm::dot(u[p], u[p]);
        double beta = glm::dot(u[q], u[q]);
        double gamma = glm::dot(u[p], u[q]);
        if (gamma == 0.0 ||
            std::abs(gamma) <= std::numeric_limits<double>::epsilon() * std::sqrt(alpha * beta)) {
          continue;
        }
        rotated = true;
        double zeta = (beta - alpha) / (2.0 * gamma);
        double t = std::copysign(1.0, zeta) / (std::abs(zeta) + std::hypot(1.0, zeta));
        double c = 1.0 / std::hypot(1.0, t);
        double s = c * t;
        glm::dvec3 up = u[p];
        u[p] = c * up - s * u[q];
        u[q] = s * up + c * u[q];
      }
    }
    if (!rotated) break;
  }
  double s[3] = {glm::length(u[0]), glm::length(u[1]), glm::length(u[2])};
  std::sort(s, s + 3, [](double x, double y) { return x > y; });
  return {s[0], s[1], s[2]};
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

}  // namespace scene
