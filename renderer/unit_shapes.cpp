#include "renderer/unit_shapes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>

#include "renderer/float_error.h"

namespace render {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Narrows `span` to the parameters where -1 <= o + t d <= 1 on one axis.
void clipToSlab(ShapeSpan& span, double o, double d, int axis) {
  if (d == 0.0) {
    // Parallel to the slab: inside it everywhere or nowhere.
    if (o < -1.0 || o > 1.0) span.empty = true;
    return;
  }
  double tLow = (-1.0 - o) / d;
  double tHigh = (1.0 - o) / d;
  glm::dvec3 lowNormal(0.0);
  lowNormal[axis] = -1.0;
  glm::dvec3 highNormal(0.0);
  highNormal[axis] = 1.0;
  // A ray going up the axis enters through the -1 face.
  if (d < 0.0) {
    std::swap(tLow, tHigh);
    std::swap(lowNormal, highNormal);
  }
  if (tLow > span.enter) {
    span.enter = tLow;
    span.enterNormal = lowNormal;
  }
  if (tHigh < span.exit) {
    span.exit = tHigh;
    span.exitNormal = highNormal;
  }
}

// Roots of |f + t g|^2 = 1 for the 2D or 3D vectors given as o and d, in a
// form that keeps its digits for a distant small shape and a near huge one:
// the discriminant comes from the line's distance to the centre (Ray Tracing
// Gems, chapter 7), and the two roots from the stable quadratic formula.
template <typename Vec>
bool unitQuadricRoots(const Vec& o, const Vec& d, double& t0, double& t1) {
  double a = glm::dot(d, d);
  if (a == 0.0) return false;
  double b = glm::dot(o, d);
  Vec f = o - (b / a) * d;
  double discriminant = a * (1.0 - glm::dot(f, f));
  if (!(discriminant >= 0.0)) return false;
  double q = -(b + std::copysign(std::sqrt(discriminant), b));
  if (q == 0.0) {
    // b = 0 and a zero discriminant: the line touches at its origin.
    t0 = t1 = 0.0;
    return true;
  }
  double c = glm::dot(o, o) - 1.0;
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

}  // namespace

ShapeSpan intersectUnitShape(scene::ObjectKind kind, const glm::dvec3& o, const glm::dvec3& d) {
  ShapeSpan span;
  span.enter = -kInfinity;
  span.exit = kInfinity;
  span.empty = false;
  switch (kind) {
    case scene::ObjectKind::Plane: {
      if (d.y == 0.0) {
        span.empty = true;
        return span;
      }
      double t = -o.y / d.y;
      span.enter = span.exit = t;
      span.enterNormal = span.exitNormal = glm::dvec3(0.0, 1.0, 0.0);
      return span;
    }
    case scene::ObjectKind::Cube:
      for (int axis = 0; axis < 3 && !span.empty; ++axis) clipToSlab(span, o[axis], d[axis], axis);
      break;
    case scene::ObjectKind::Sphere: {
      double t0 = 0.0;
      double t1 = 0.0;
      if (!unitQuadricRoots(o, d, t0, t1)) {
        span.empty = true;
        return span;
      }
      span.enter = t0;
      span.exit = t1;
      span.enterNormal = o + t0 * d;
      span.exitNormal = o + t1 * d;
      return span;
    }
    case scene::ObjectKind::Cylinder: {
      glm::dvec2 o2(o.x, o.z);
      glm::dvec2 d2(d.x, d.z);
      if (d2 == glm::dvec2(0.0)) {
        // Along the axis: inside the tube everywhere or nowhere.
        if (glm::dot(o2, o2) > 1.0) span.empty = true;
      } else {
        double t0 = 0.0;
        double t1 = 0.0;
        if (!unitQuadricRoots(o2, d2, t0, t1)) {
          span.empty = true;
          return span;
        }
        span.enter = t0;
        span.exit = t1;
        glm::dvec2 n0 = o2 + t0 * d2;
        glm::dvec2 n1 = o2 + t1 * d2;
        span.enterNormal = glm::dvec3(n0.x, 0.0, n0.y);
        span.exitNormal = glm::dvec3(n1.x, 0.0, n1.y);
      }
      if (!span.empty) clipToSlab(span, o.y, d.y, 1);
      break;
    }
  }
  if (!span.empty && !(span.enter <= span.exit)) span.empty = true;
  return span;
}

SurfacePoint refineOntoSurface(scene::ObjectKind kind, const glm::dvec3& o, const glm::dvec3& d,
                               double t, const glm::dvec3& normal) {
  SurfacePoint s;
  glm::dvec3 p = o + t * d;
  // Rounding error of o + t d, for the coordinates that stay as computed.
  glm::dvec3 rawError = gamma(3) * (abs(o) + abs(t * d));
  switch (kind) {
    case scene::ObjectKind::Plane:
      p.y = 0.0;
      s.normal = glm::dvec3(0.0, 1.0, 0.0);
      s.error = glm::dvec3(rawError.x, 0.0, rawError.z);
      break;
    case scene::ObjectKind::Cube: {
      int axis = normal.x != 0.0 ? 0 : (normal.y != 0.0 ? 1 : 2);
      for (int i = 0; i < 3; ++i) p[i] = std::clamp(p[i], -1.0, 1.0);
      p[axis] = normal[axis] > 0.0 ? 1.0 : -1.0;
      s.normal = glm::dvec3(0.0);
      s.normal[axis] = p[axis];
      s.error = rawError;
      s.error[axis] = 0.0;
      break;
    }
    case scene::ObjectKind::Sphere: {
      double length = glm::length(p);
      if (length > 0.0) p /= length;
      s.normal = p;
      s.error = gamma(5) * abs(p);
      break;
    }
    case scene::ObjectKind::Cylinder: {
      if (normal.y != 0.0) {
        p.y = normal.y > 0.0 ? 1.0 : -1.0;
        s.normal = glm::dvec3(0.0, p.y, 0.0);
        s.error = glm::dvec3(rawError.x, 0.0, rawError.z);
      } else {
        double radius = std::hypot(p.x, p.z);
        if (radius > 0.0) {
          p.x /= radius;
          p.z /= radius;
        }
        p.y = std::clamp(p.y, -1.0, 1.0);
        s.normal = glm::dvec3(p.x, 0.0, p.z);
        s.error = glm::dvec3(gamma(5) * std::abs(p.x), rawError.y, gamma(5) * std::abs(p.z));
      }
      break;
    }
  }
  s.point = p;
  return s;
}

}  // namespace render
