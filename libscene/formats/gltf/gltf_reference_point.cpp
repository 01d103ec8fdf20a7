#include "libscene/formats/gltf/gltf_reference_point.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <utility>

#include "libscene/text/number.h"
#include "scenefile/matrix.h"

namespace scene::gltf {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The parameter interval [lo, hi] of the ray inside the slab |p[axis]| <= 1,
// narrowed into `range`; false when it is empty.
bool narrowToSlab(const glm::dvec3& o, const glm::dvec3& d, int axis,
                  std::pair<double, double>& range) {
  if (d[axis] == 0.0) return std::abs(o[axis]) <= 1.0;
  double a = (-1.0 - o[axis]) / d[axis];
  double b = (1.0 - o[axis]) / d[axis];
  range.first = std::max(range.first, std::min(a, b));
  range.second = std::min(range.second, std::max(a, b));
  return range.first <= range.second;
}

// The interval where a*t^2 + 2*b*t + c <= 0 (a > 0), narrowed into `range`.
bool narrowToQuadric(double a, double b, double c, std::pair<double, double>& range) {
  if (a == 0.0) return c <= 0.0;
  double discriminant = b * b - a * c;
  if (!(discriminant >= 0.0)) return false;
  double root = std::sqrt(discriminant);
  range.first = std::max(range.first, (-b - root) / a);
  range.second = std::min(range.second, (-b + root) / a);
  return range.first <= range.second;
}

// The first parameter above 0 of a convex solid's interval, if any.
std::optional<double> firstPositive(const std::pair<double, double>& range) {
  if (range.first > 0.0 && std::isfinite(range.first)) return range.first;
  if (range.second > 0.0 && std::isfinite(range.second)) return range.second;
  return std::nullopt;
}

std::optional<ReferencePoint> cameraRayPoint(const Scene& scene, const glm::dvec3& eye,
                                             const glm::dvec3& forward) {
  double nearest = kInfinity;
  for (const Object& object : scene.objects) {
    std::optional<double> t = rayHit(object, eye, forward);
    if (t && *t < nearest) nearest = *t;
  }
  glm::dvec3 point = eye + nearest * forward;
  if (!std::isfinite(nearest) || !finite(point)) return std::nullopt;
  return ReferencePoint{point, ReferencePoint::Source::CameraRay};
}

std::optional<ReferencePoint> objectsCentre(const Scene& scene) {
  glm::dvec3 lo(kInfinity), hi(-kInfinity);
  for (const Object& object : scene.objects) {
    if (object.kind == ObjectKind::Plane) continue;
    for (int corner = 0; corner < 8; ++corner) {
      glm::dvec4 local((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0,
                       (corner & 4) ? 1.0 : -1.0, 1.0);
      glm::dvec3 p(object.matrix * local);
      if (!finite(p)) continue;
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  if (!(lo.x <= hi.x)) return std::nullopt;
  // Halves first: the sum of two large corners could overflow.
  glm::dvec3 centre = 0.5 * lo + 0.5 * hi;
  if (!finite(centre)) return std::nullopt;
  return ReferencePoint{centre, ReferencePoint::Source::ObjectsCentre};
}

std::optional<ReferencePoint> nearestPlanePoint(const Scene& scene, const glm::dvec3& eye) {
  std::optional<ReferencePoint> best;
  double bestDistance = kInfinity;
  for (const Object& object : scene.objects) {
    if (object.kind != ObjectKind::Plane) continue;
    // The plane's normal is the inverse transpose's image of its local +Y.
    glm::dmat3 inverse = glm::inverse(glm::dmat3(object.matrix));
    glm::dvec3 normal = unitDirection(glm::transpose(inverse) * glm::dvec3(0.0, 1.0, 0.0));
    double height = glm::dot(eye - glm::dvec3(object.matrix[3]), normal);
    glm::dvec3 foot = eye - height * normal;
    if (!finite(normal) || !finite(foot) || !(std::abs(height) < bestDistance)) continue;
    bestDistance = std::abs(height);
    best = ReferencePoint{foot, ReferencePoint::Source::NearestPlane};
  }
  return best;
}

}  // namespace

std::string approximateNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  ParsedNumber parsed = parseNumber(text);
  return parsed.status == NumberStatus::Ok ? formatNumber(parsed.value) : text;
}

std::optional<double> rayHit(const Object& object, const glm::dvec3& origin,
                             const glm::dvec3& direction) {
  // In the object's own space, where it is the unit shape; t is the same.
  glm::dmat3 inverse = glm::inverse(glm::dmat3(object.matrix));
  glm::dvec3 o = inverse * (origin - glm::dvec3(object.matrix[3]));
  glm::dvec3 d = inverse * direction;
  if (!finite(o) || !finite(d)) return std::nullopt;
  std::pair<double, double> range{-kInfinity, kInfinity};
  switch (object.kind) {
    case ObjectKind::Plane: {
      if (d.y == 0.0) return std::nullopt;
      double t = -o.y / d.y;
      if (t > 0.0 && std::isfinite(t)) return t;
      return std::nullopt;
    }
    case ObjectKind::Sphere:
      if (!narrowToQuadric(glm::dot(d, d), glm::dot(o, d), glm::dot(o, o) - 1.0, range)) {
        return std::nullopt;
      }
      break;
    case ObjectKind::Cube:
      for (int axis = 0; axis < 3; ++axis) {
        if (!narrowToSlab(o, d, axis, range)) return std::nullopt;
      }
      break;
    case ObjectKind::Cylinder:
      if (!narrowToSlab(o, d, 1, range) ||
          !narrowToQuadric(d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z,
                           o.x * o.x + o.z * o.z - 1.0, range)) {
        return std::nullopt;
      }
      break;
  }
  return firstPositive(range);
}

ReferencePoint referencePoint(const Scene& scene) {
  const glm::dmat4& camera = scene.camera.matrix;
  glm::dvec3 eye(camera[3]);
  glm::dvec3 forward = unitDirection(-glm::dvec3(camera[2]));
  if (finite(forward) && glm::dot(forward, forward) > 0.0) {
    if (auto hit = cameraRayPoint(scene, eye, forward)) return *hit;
  }
  if (auto centre = objectsCentre(scene)) return *centre;
  if (auto plane = nearestPlanePoint(scene, eye)) return *plane;
  return ReferencePoint{eye, ReferencePoint::Source::Eye};
}

double referenceDistance(const glm::dvec3& light, const ReferencePoint& reference) {
  // Halves first, so that the difference of two large coordinates stays
  // finite; scaledLength neither overflows nor underflows on the way.
  double distance = 2.0 * scaledLength(0.5 * light - 0.5 * reference.point);
  if (std::isnan(distance) || distance == 0.0) return 1.0;
  return std::min(distance, std::numeric_limits<double>::max());
}

std::string describeReferencePoint(const ReferencePoint& reference) {
  const glm::dvec3& p = reference.point;
  std::string at = "(" + approximateNumber(p.x) + " " + approximateNumber(p.y) + " " +
                   approximateNumber(p.z) + ")";
  switch (reference.source) {
    case ReferencePoint::Source::CameraRay:
      return "the point the camera looks at, on the first object its forward ray meets, " + at;
    case ReferencePoint::Source::ObjectsCentre:
      return "the centre of the objects' bounds " + at +
             ", since the camera's forward ray meets "
             "no object";
    case ReferencePoint::Source::NearestPlane:
      return "the point of the nearest plane nearest the camera " + at +
             ", since the camera's forward ray meets no object";
    case ReferencePoint::Source::Eye:
      return "the camera " + at + ", since no object gives a point to look at";
  }
  return at;
}

}  // namespace scene::gltf
