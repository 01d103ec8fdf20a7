// Ray intersection with the four unit shapes of FORMATS.md, in object space.
//
// The three solids (sphere, cube, cylinder) are convex, so a line meets each
// in one interval [enter, exit]; computing that interval, rather than
// separate surface hits, keeps cube edges and corners and the cylinder's rims
// watertight (the faces share the interval's ends). The plane y = 0 is met at
// one point.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <utility>

#include "renderer/float_error.h"
#include "scenefile/scene.h"

namespace render {

// Where a ray meets a unit shape, refined onto the surface.
struct SurfacePoint {
  glm::dvec3 point{0.0};   // on the surface, in object space
  glm::dvec3 normal{0.0};  // outward, object space, not normalised
  glm::dvec3 error{0.0};   // bound on |point - exact point| per component
};

// The parameter interval in which the line origin + t * direction lies
// inside a solid, with the surface normal at each end; `empty` when the line
// misses. For the plane, enter == exit.
struct ShapeSpan {
  double enter = 0.0;
  double exit = 0.0;
  glm::dvec3 enterNormal{0.0};
  glm::dvec3 exitNormal{0.0};
  bool empty = true;
};

ShapeSpan intersectUnitShape(scene::ObjectKind kind, const glm::dvec3& origin,
                             const glm::dvec3& direction);

// Which surface bounds one end of a span: a flat face (axis and side), the
// curved surface of a sphere or cylinder, or none (the span is unbounded
// there).
enum class SpanFace : std::int8_t {
  None = -2,
  Curved = -1,
  // 2 * axis + (1 for the +1 face, 0 for the -1 face).
  LowX = 0,
};

// The span as distances and faces only, with no normal vectors: what the
// search for the nearest object needs. intersectUnitShape is built on it, so
// the distances of both are the same numbers.
struct SpanDistances {
  double enter = -std::numeric_limits<double>::infinity();
  double exit = std::numeric_limits<double>::infinity();
  SpanFace enterFace = SpanFace::None;
  SpanFace exitFace = SpanFace::None;
  bool empty = false;
};

namespace detail {

// Narrows `span` to the parameters where -1 <= o + t d <= 1 on one axis.
inline void clipToSlab(SpanDistances& span, double o, double d, int axis) {
  if (d == 0.0) {
    // Parallel to the slab: inside it everywhere or nowhere.
    if (o < -1.0 || o > 1.0) span.empty = true;
    return;
  }
  double tLow = (-1.0 - o) / d;
  double tHigh = (1.0 - o) / d;
  auto lowFace = static_cast<SpanFace>(2 * axis);
  auto highFace = static_cast<SpanFace>(2 * axis + 1);
  // A ray going up the axis enters through the -1 face.
  if (d < 0.0) {
    std::swap(tLow, tHigh);
    std::swap(lowFace, highFace);
  }
  if (tLow > span.enter) {
    span.enter = tLow;
    span.enterFace = lowFace;
  }
  if (tHigh < span.exit) {
    span.exit = tHigh;
    span.exitFace = highFace;
  }
}

// Roots of |f + t g|^2 = 1 for the 2D or 3D vectors given as o and d, in a
// form that keeps its digits for a distant small shape and a near huge one:
// the discriminant comes from the line's distance to the centre (Ray Tracing
// Gems, chapter 7), and the two roots from the stable quadratic formula.
template <typename Vec>
inline bool unitQuadricRoots(const Vec& o, const Vec& d, double& t0, double& t1) {
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

}  // namespace detail

// The outward normal, in object space and not normalised, of the span end
// at parameter t on `face`.
glm::dvec3 spanFaceNormal(scene::ObjectKind kind, SpanFace face, const glm::dvec3& origin,
                          const glm::dvec3& direction, double t);

// Inline, and forced so (GCC otherwise keeps one out-of-line copy and calls
// it, with the span going back through memory): it runs for every object a
// ray's search reaches.
[[gnu::always_inline]] inline SpanDistances unitShapeDistances(scene::ObjectKind kind,
                                                               const glm::dvec3& o,
                                                               const glm::dvec3& d) {
  SpanDistances span;
  switch (kind) {
    case scene::ObjectKind::Plane:
      if (d.y == 0.0) {
        span.empty = true;
        return span;
      }
      span.enter = span.exit = -o.y / d.y;
      span.enterFace = span.exitFace = static_cast<SpanFace>(3);  // +y
      return span;
    case scene::ObjectKind::Cube:
      for (int axis = 0; axis < 3 && !span.empty; ++axis) {
        detail::clipToSlab(span, o[axis], d[axis], axis);
      }
      break;
    case scene::ObjectKind::Sphere:
      if (!detail::unitQuadricRoots(o, d, span.enter, span.exit)) span.empty = true;
      span.enterFace = span.exitFace = SpanFace::Curved;
      return span;
    case scene::ObjectKind::Cylinder: {
      glm::dvec2 o2(o.x, o.z);
      glm::dvec2 d2(d.x, d.z);
      if (d2 == glm::dvec2(0.0)) {
        // Along the axis: inside the tube everywhere or nowhere.
        if (glm::dot(o2, o2) > 1.0) span.empty = true;
      } else {
        if (!detail::unitQuadricRoots(o2, d2, span.enter, span.exit)) {
          span.empty = true;
          return span;
        }
        span.enterFace = span.exitFace = SpanFace::Curved;
      }
      if (!span.empty) detail::clipToSlab(span, o.y, d.y, 1);
      break;
    }
  }
  if (!span.empty && !(span.enter <= span.exit)) span.empty = true;
  return span;
}

// refineOntoSurface for the plane y = 0, the surface most camera rays of a
// scene over a floor meet (84% of them on the floor scenes): inline, and
// with no face to look at.
inline SurfacePoint refineOntoPlane(const glm::dvec3& o, const glm::dvec3& d, double t) {
  SurfacePoint s;
  s.point = o + t * d;
  // The rounding error of o + t d, for the coordinates that stay as computed.
  glm::dvec3 rawError = gamma(3) * (abs(o) + abs(t * d));
  s.point.y = 0.0;
  s.normal = glm::dvec3(0.0, 1.0, 0.0);
  s.error = glm::dvec3(rawError.x, 0.0, rawError.z);
  return s;
}

// The point origin + t * direction pulled exactly onto the shape's surface
// on the face whose outward normal is `normal`, with its error bound.
SurfacePoint refineOntoSurface(scene::ObjectKind kind, const glm::dvec3& origin,
                               const glm::dvec3& direction, double t, const glm::dvec3& normal);

}  // namespace render
