// Ray intersection with the four unit shapes of FORMATS.md, in object space.
//
// The three solids (sphere, cube, cylinder) are convex, so a line meets each
// in one interval [enter, exit]; computing that interval, rather than
// separate surface hits, keeps cube edges and corners and the cylinder's rims
// watertight (the faces share the interval's ends). The plane y = 0 is met at
// one point.
#pragma once

#include <glm/vec3.hpp>

#include "libscene/scene.h"

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

// The point origin + t * direction pulled exactly onto the shape's surface
// on the face whose outward normal is `normal`, with its error bound.
SurfacePoint refineOntoSurface(scene::ObjectKind kind, const glm::dvec3& origin,
                               const glm::dvec3& direction, double t, const glm::dvec3& normal);

}  // namespace render
