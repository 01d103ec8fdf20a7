// A reference ray caster for the geometry and acne tests, written from
// RENDERING.md and FORMATS.md alone and sharing no code with the renderer.
//
// Everything is in long double (80-bit on x86-64: 64 mantissa bits against
// double's 53), so that its answers are exact for the purpose of judging a
// double-precision renderer: the camera ray through each pixel centre, each
// object's inverse matrix by Gaussian elimination with partial pivoting, the
// intersection with the unit shape in local space, the nearest t > 0 by brute
// force over all objects, and shadow segments to lights.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "scenefile/scene.h"

namespace geomref {

using Real = long double;

struct Vec3 {
  Real x = 0;
  Real y = 0;
  Real z = 0;

  Real operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  Real& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  friend Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator*(Real s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
  friend Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
};

inline Real dot(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Real length(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
inline Vec3 normalize(const Vec3& a) {
  return (1 / length(a)) * a;
}

struct Ray {
  Vec3 origin;
  Vec3 direction;  // need not be unit
};

// The pinhole camera of FORMATS.md with the image plane of RENDERING.md.
class Camera {
 public:
  Camera(const scene::Camera& camera, int width, int height, double verticalFovDegrees);

  // The ray through image position (x, y) in pixels from the top-left corner,
  // x to the right and y down; its direction is unit.
  Ray rayThrough(Real x, Real y) const;
  // The same ray turned by `angle` radians (small) toward the image-plane
  // direction at `k` * 45 degrees from the right (k = 0..7).
  Ray turned(Real x, Real y, Real angle, int k) const;

  const Vec3& eye() const { return eye_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Vec3 eye_, forward_, up_, right_;
  Real tanHalfHeight_ = 0;
  Real tanHalfWidth_ = 0;
  int width_ = 0;
  int height_ = 0;
};

// A surface point met by a ray.
struct Hit {
  std::int32_t object = -1;
  Real t = 0;           // along the ray's own direction
  Vec3 point;           // world space
  Vec3 normal;          // world space, unit, outward (a plane: its local +y side)
  bool inside = false;  // the ray started inside the solid and met it leaving
};

class Scene {
 public:
  explicit Scene(const scene::Scene& scene);

  // The nearest surface at t > 0, by brute force over every object.
  std::optional<Hit> closestHit(const Ray& ray) const;
  // The object whose surface the ray meets first, or -1.
  std::int32_t objectId(const Ray& ray) const;
  // Whether any object other than `skip` meets the open segment from `from`
  // to `to`. The point a shadow ray leaves lies on `skip`, and since every
  // solid is convex and the plane flat, a segment that leaves it outward can
  // never meet it again: skipping it is exact, not a tolerance.
  bool segmentBlocked(const Vec3& from, const Vec3& to, std::int32_t skip) const;

  const std::vector<Vec3>& lights() const { return lights_; }
  std::size_t objectCount() const { return objects_.size(); }

 private:
  struct Object {
    scene::ObjectKind kind = scene::ObjectKind::Sphere;
    Real toWorld[3][3] = {};  // [row][col]
    Vec3 translation;
    Real toLocal[3][3] = {};  // inverse of toWorld, [row][col]
  };
  // The parameters where the line meets the unit shape: [enter, exit] for a
  // solid, enter == exit for the plane; local normals at both ends.
  struct Span {
    bool hit = false;
    Real enter = 0;
    Real exit = 0;
    Vec3 enterNormal;
    Vec3 exitNormal;
  };
  static Span intersectLocal(scene::ObjectKind kind, const Vec3& o, const Vec3& d);
  Span intersect(const Object& object, const Ray& ray) const;

  std::vector<Object> objects_;
  std::vector<Vec3> lights_;
};

// Per pixel, row by row from the top, the object each pixel centre's ray
// meets first (-1: none).
std::vector<std::int32_t> castObjectIds(const Scene& scene, const Camera& camera);

// Whether a silhouette passes within `angle` radians of the centre ray of
// pixel (i, j): the rays turned by `angle` in eight directions around it do
// not all meet the same object as the centre ray. An angle of 1e-6 is a
// lateral distance of 1e-6 times the distance from the eye, so at most 1e-6
// of the scene's size for whatever lies within the scene around the eye.
bool nearSilhouette(const Scene& scene, const Camera& camera, int i, int j, Real angle);

// The smallest of 1e-12, 1e-11, ..., 1e-2 radians at which
// nearSilhouette(...) holds, or infinity: an order-of-magnitude estimate of
// the angular distance from the pixel centre's ray to the nearest silhouette.
Real silhouetteDistance(const Scene& scene, const Camera& camera, int i, int j);

inline Vec3 toReal(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}

}  // namespace geomref
