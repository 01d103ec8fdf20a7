#include "tests/geometry/reference_caster.h"

#include <algorithm>
#include <limits>
#include <numbers>
#include <utility>

namespace geomref {

namespace {

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();

// The inverse of a 3x3 matrix by Gauss-Jordan elimination with partial
// pivoting on [A | I]. FORMATS.md guarantees the block is invertible with a
// condition number of at most 1e12, so the 64-bit mantissa keeps at least
// 7 digits in the worst case and about 19 in the usual one.
void invert3(const Real a[3][3], Real inverse[3][3]) {
  Real m[3][6];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      m[r][c] = a[r][c];
      m[r][c + 3] = r == c ? 1 : 0;
    }
  }
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 3; ++r) {
      if (std::abs(m[r][col]) > std::abs(m[pivot][col])) pivot = r;
    }
    if (pivot != col) std::swap(m[pivot], m[col]);
    for (int r = 0; r < 3; ++r) {
      if (r == col) continue;
      Real f = m[r][col] / m[col][col];
      for (int k = col; k < 6; ++k) m[r][k] -= f * m[col][k];
    }
  }
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) inverse[r][c] = m[r][c + 3] / m[r][r];
  }
}

Vec3 multiply(const Real m[3][3], const Vec3& v) {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
          m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Vec3 multiplyTransposed(const Real m[3][3], const Vec3& v) {
  return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z,
          m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
          m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
}

// Where the line o + t d is within distance 1 of the origin (a sphere) or of
// the Y axis (a cylinder, given the x and z components only). The root
// comes from the point of the line nearest the centre, not from the
// textbook discriminant, which cancels catastrophically for a far-off ray.
bool unitRoots(const Vec3& o, const Vec3& d, Real& t0, Real& t1) {
  Real a = dot(d, d);
  if (a == 0) return false;
  Real tc = -dot(o, d) / a;
  Vec3 nearest = o + tc * d;
  Real h2 = 1 - dot(nearest, nearest);
  if (h2 < 0) return false;
  Real half = std::sqrt(h2 / a);
  t0 = tc - half;
  t1 = tc + half;
  return true;
}

}  // namespace

Camera::Camera(const scene::Camera& camera, int width, int height, double verticalFovDegrees)
    : width_(width), height_(height) {
  const glm::dmat4& m = camera.matrix;
  // M * (0,0,0,1), M * (0,0,-1,0) and M * (0,1,0,0) of FORMATS.md.
  eye_ = {m[3][0], m[3][1], m[3][2]};
  forward_ = normalize(Vec3{-m[2][0], -m[2][1], -m[2][2]});
  Vec3 up{m[1][0], m[1][1], m[1][2]};
  up_ = normalize(up - dot(up, forward_) * forward_);
  // Right-handed world: right = forward x up.
  right_ = cross(forward_, up_);
  tanHalfHeight_ = std::tan(static_cast<Real>(verticalFovDegrees) * std::numbers::pi_v<Real> / 360);
  tanHalfWidth_ = tanHalfHeight_ * width / height;
}

Ray Camera::rayThrough(Real x, Real y) const {
  Real sx = (2 * x / width_ - 1) * tanHalfWidth_;
  Real sy = (1 - 2 * y / height_) * tanHalfHeight_;
  return {eye_, normalize(forward_ + sx * right_ + sy * up_)};
}

Ray Camera::turned(Real x, Real y, Real angle, int k) const {
  Ray ray = rayThrough(x, y);
  const Vec3& d = ray.direction;
  Vec3 e1 = normalize(right_ - dot(right_, d) * d);
  Vec3 e2 = cross(d, e1);
  Real diagonal = std::sqrt(static_cast<Real>(0.5));
  constexpr int kCos[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  constexpr int kSin[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  Real scale = k % 2 == 0 ? 1 : diagonal;
  Vec3 side = (scale * kCos[k]) * e1 + (scale * kSin[k]) * e2;
  ray.direction = normalize(d + angle * side);
  return ray;
}

Scene::Scene(const scene::Scene& scene) {
  for (const scene::Object& o : scene.objects) {
    Object object;
    object.kind = o.kind;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) object.toWorld[r][c] = o.matrix[c][r];
    }
    object.translation = {o.matrix[3][0], o.matrix[3][1], o.matrix[3][2]};
    invert3(object.toWorld, object.toLocal);
    objects_.push_back(object);
  }
  for (const scene::Light& light : scene.lights) lights_.push_back(toReal(light.position()));
}

Scene::Span Scene::intersectLocal(scene::ObjectKind kind, const Vec3& o, const Vec3& d) {
  Span span;
  span.enter = -kInfinity;
  span.exit = kInfinity;
  // Narrows the span to -1 <= o[axis] + t d[axis] <= 1.
  auto slab = [&](int axis) {
    if (d[axis] == 0) {
      if (std::abs(o[axis]) > 1) span.exit = -kInfinity;
      return;
    }
    Real tLow = (-1 - o[axis]) / d[axis];
    Real tHigh = (1 - o[axis]) / d[axis];
    Vec3 nLow, nHigh;
    nLow[axis] = -1;
    nHigh[axis] = 1;
    if (tLow > tHigh) {
      std::swap(tLow, tHigh);
      std::swap(nLow, nHigh);
    }
    if (tLow > span.enter) {
      span.enter = tLow;
      span.enterNormal = nLow;
    }
    if (tHigh < span.exit) {
      span.exit = tHigh;
      span.exitNormal = nHigh;
    }
  };
  switch (kind) {
    case scene::ObjectKind::Plane:
      if (d.y == 0) return span;
      span.enter = span.exit = -o.y / d.y;
      span.enterNormal = span.exitNormal = {0, 1, 0};
      span.hit = true;
      return span;
    case scene::ObjectKind::Sphere: {
      Real t0 = 0, t1 = 0;
      if (!unitRoots(o, d, t0, t1)) return span;
      span.enter = t0;
      span.exit = t1;
      span.enterNormal = o + t0 * d;
      span.exitNormal = o + t1 * d;
      span.hit = true;
      return span;
    }
    case scene::ObjectKind::Cube:
      for (int axis = 0; axis < 3; ++axis) slab(axis);
      break;
    case scene::ObjectKind::Cylinder: {
      Vec3 o2{o.x, 0, o.z};
      Vec3 d2{d.x, 0, d.z};
      if (d2.x == 0 && d2.z == 0) {
        // Along the axis: inside the tube for every t or for none.
        if (dot(o2, o2) > 1) return span;
      } else {
        Real t0 = 0, t1 = 0;
        if (!unitRoots(o2, d2, t0, t1)) return span;
        span.enter = t0;
        span.exit = t1;
        span.enterNormal = o2 + t0 * d2;
        span.exitNormal = o2 + t1 * d2;
      }
      slab(1);
      break;
    }
  }
  span.hit = span.enter <= span.exit;
  return span;
}

Scene::Span Scene::intersect(const Object& object, const Ray& ray) const {
  Vec3 o = multiply(object.toLocal, ray.origin - object.translation);
  Vec3 d = multiply(object.toLocal, ray.direction);
  return intersectLocal(object.kind, o, d);
}

std::optional<Hit> Scene::closestHit(const Ray& ray) const {
  std::optional<Hit> best;
  Vec3 localNormal;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    Span span = intersect(objects_[i], ray);
    if (!span.hit) continue;
    // The nearest end ahead of the eye: the entry, or the exit for an eye
    // inside the solid.
    Real t = 0;
    bool inside = false;
    if (span.enter > 0) {
      t = span.enter;
      localNormal = span.enterNormal;
    } else if (span.exit > 0 && objects_[i].kind != scene::ObjectKind::Plane) {
      t = span.exit;
      localNormal = span.exitNormal;
      inside = true;
    } else {
      continue;
    }
    if (best && t >= best->t) continue;
    Hit hit;
    hit.object = static_cast<std::int32_t>(i);
    hit.t = t;
    hit.point = ray.origin + t * ray.direction;
    // Normals map by the inverse transpose, which also keeps them outward
    // under a mirror.
    hit.normal = normalize(multiplyTransposed(objects_[i].toLocal, localNormal));
    hit.inside = inside;
    best = hit;
  }
  return best;
}

std::int32_t Scene::objectId(const Ray& ray) const {
  std::optional<Hit> hit = closestHit(ray);
  return hit ? hit->object : -1;
}

bool Scene::segmentBlocked(const Vec3& from, const Vec3& to, std::int32_t skip) const {
  Ray ray{from, to - from};
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (static_cast<std::int32_t>(i) == skip) continue;
    Span span = intersect(objects_[i], ray);
    if (!span.hit) continue;
    if (objects_[i].kind == scene::ObjectKind::Plane) {
      if (span.enter > 0 && span.enter < 1) return true;
    } else if (span.enter < 1 && span.exit > 0) {
      return true;
    }
  }
  return false;
}

std::vector<std::int32_t> castObjectIds(const Scene& scene, const Camera& camera) {
  std::vector<std::int32_t> ids;
  ids.reserve(static_cast<std::size_t>(camera.width()) * camera.height());
  for (int j = 0; j < camera.height(); ++j) {
    for (int i = 0; i < camera.width(); ++i) {
      ids.push_back(scene.objectId(camera.rayThrough(i + Real(0.5), j + Real(0.5))));
    }
  }
  return ids;
}

bool nearSilhouette(const Scene& scene, const Camera& camera, int i, int j, Real angle) {
  Real x = i + Real(0.5);
  Real y = j + Real(0.5);
  std::int32_t centre = scene.objectId(camera.rayThrough(x, y));
  for (int k = 0; k < 8; ++k) {
    if (scene.objectId(camera.turned(x, y, angle, k)) != centre) return true;
  }
  return false;
}

Real silhouetteDistance(const Scene& scene, const Camera& camera, int i, int j) {
  // Literals, not a running product, so that 1e-6 here equals 1e-6L in a
  // caller's comparison.
  constexpr Real kAngles[] = {1e-12L, 1e-11L, 1e-10L, 1e-9L, 1e-8L, 1e-7L,
                              1e-6L,  1e-5L,  1e-4L,  1e-3L, 1e-2L};
  for (Real angle : kAngles) {
    if (nearSilhouette(scene, camera, i, j, angle)) return angle;
  }
  return kInfinity;
}

}  // namespace geomref
