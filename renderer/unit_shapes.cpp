#include "renderer/unit_shapes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>

#include "renderer/float_error.h"

namespace render {

glm::dvec3 spanFaceNormal(scene::ObjectKind kind, SpanFace face, const glm::dvec3& o,
                          const glm::dvec3& d, double t) {
  if (face == SpanFace::None) return glm::dvec3(0.0);
  if (face == SpanFace::Curved) {
    switch (kind) {
      case scene::ObjectKind::Sphere:
        return o + t * d;
      case scene::ObjectKind::Cylinder:
      case scene::ObjectKind::Plane:  // flat faces only: never asked
      case scene::ObjectKind::Cube: {
        glm::dvec2 n = glm::dvec2(o.x, o.z) + t * glm::dvec2(d.x, d.z);
        return glm::dvec3(n.x, 0.0, n.y);
      }
    }
  }
  int code = static_cast<int>(face);
  glm::dvec3 n(0.0);
  n[code / 2] = code % 2 == 1 ? 1.0 : -1.0;
  return n;
}

ShapeSpan intersectUnitShape(scene::ObjectKind kind, const glm::dvec3& o, const glm::dvec3& d) {
  SpanDistances distances = unitShapeDistances(kind, o, d);
  ShapeSpan span;
  span.empty = distances.empty;
  span.enter = distances.enter;
  span.exit = distances.exit;
  if (span.empty) return span;
  span.enterNormal = spanFaceNormal(kind, distances.enterFace, o, d, span.enter);
  span.exitNormal = spanFaceNormal(kind, distances.exitFace, o, d, span.exit);
  return span;
}

SurfacePoint refineOntoSurface(scene::ObjectKind kind, const glm::dvec3& o, const glm::dvec3& d,
                               double t, const glm::dvec3& normal) {
  if (kind == scene::ObjectKind::Plane) return refineOntoPlane(o, d, t);
  SurfacePoint s;
  glm::dvec3 p = o + t * d;
  // Rounding error of o + t d, for the coordinates that stay as computed.
  glm::dvec3 rawError = gamma(3) * (abs(o) + abs(t * d));
  switch (kind) {
    case scene::ObjectKind::Plane:  // refineOntoPlane, above
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
