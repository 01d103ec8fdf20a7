#include "bench/float_tracer.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <utility>

#include "renderer/bounds.h"
#include "renderer/unit_shapes.h"

namespace bench {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Span {
  float enter = -kInfinity;
  float exit = kInfinity;
  int enterFace = -2;
  int exitFace = -2;
  bool empty = false;
};

// renderer/unit_shapes.h's clipToSlab, in float.
void clipToSlab(Span& span, float o, float d, int axis) {
  if (d == 0.0f) {
    if (o < -1.0f || o > 1.0f) span.empty = true;
    return;
  }
  float tLow = (-1.0f - o) / d;
  float tHigh = (1.0f - o) / d;
  int lowFace = 2 * axis, highFace = 2 * axis + 1;
  if (d < 0.0f) {
    std::swap(tLow, tHigh);
    std::swap(lowFace, highFace);
  }
  if (tLow > span.enter) span.enter = tLow, span.enterFace = lowFace;
  if (tHigh < span.exit) span.exit = tHigh, span.exitFace = highFace;
}

// renderer/unit_shapes.h's unitQuadricRoots (the discriminant from the
// line's distance to the centre, the stable quadratic formula), in float:
// the float tracer gets the better formula, not the textbook one.
template <typename Vec>
bool quadricRoots(const Vec& o, const Vec& d, float& t0, float& t1) {
  float a = glm::dot(d, d);
  if (a == 0.0f) return false;
  float b = glm::dot(o, d);
  Vec f = o - (b / a) * d;
  float discriminant = a * (1.0f - glm::dot(f, f));
  if (!(discriminant >= 0.0f)) return false;
  float q = -(b + std::copysign(std::sqrt(discriminant), b));
  if (q == 0.0f) {
    t0 = t1 = 0.0f;
    return true;
  }
  float c = glm::dot(o, o) - 1.0f;
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

Span shapeSpan(scene::ObjectKind kind, const glm::vec3& o, const glm::vec3& d) {
  Span span;
  switch (kind) {
    case scene::ObjectKind::Plane:
      if (d.y == 0.0f) span.empty = true;
      span.enter = span.exit = -o.y / d.y;
      span.enterFace = span.exitFace = 3;
      return span;
    case scene::ObjectKind::Cube:
      for (int axis = 0; axis < 3 && !span.empty; ++axis) clipToSlab(span, o[axis], d[axis], axis);
      break;
    case scene::ObjectKind::Sphere:
      if (!quadricRoots(o, d, span.enter, span.exit)) span.empty = true;
      span.enterFace = span.exitFace = -1;
      return span;
    case scene::ObjectKind::Cylinder: {
      glm::vec2 o2(o.x, o.z), d2(d.x, d.z);
      if (d2 == glm::vec2(0.0f)) {
        if (glm::dot(o2, o2) > 1.0f) span.empty = true;
      } else {
        if (!quadricRoots(o2, d2, span.enter, span.exit)) {
          span.empty = true;
          return span;
        }
        span.enterFace = span.exitFace = -1;
      }
      if (!span.empty) clipToSlab(span, o.y, d.y, 1);
      break;
    }
  }
  if (!span.empty && !(span.enter <= span.exit)) span.empty = true;
  return span;
}

glm::vec3 localNormal(scene::ObjectKind kind, int face, const glm::vec3& p) {
  if (face >= 0) {
    glm::vec3 n(0.0f);
    n[face / 2] = face % 2 ? 1.0f : -1.0f;
    return n;
  }
  if (kind == scene::ObjectKind::Cylinder) return {p.x, 0.0f, p.z};
  return p;
}

// x^e by repeated squaring for whole e up to 1024, as the renderer's
// specularPower: the two tracers pay the same for highlights.
float specularPower(float x, float e) {
  if (!(e >= 0.0f && e <= 1024.0f) || e != std::floor(e)) return std::pow(x, e);
  auto n = static_cast<unsigned>(e);
  float result = 1.0f;
  for (; n > 0; n >>= 1, x *= x) {
    if (n & 1u) result *= x;
  }
  return result;
}

float largest(const glm::vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

}  // namespace

FloatTracer::FloatTracer(const render::RenderScene& scene, ShadowOffset offset, float epsilon)
    : scene_(scene), offset_(offset), epsilon_(epsilon) {
  for (std::uint32_t i = 0; i < scene.objects().size(); ++i) {
    const render::RenderObject& r = scene.objects()[i];
    Object o;
    o.kind = r.kind;
    o.toLocal = glm::mat3(r.toLocal);
    o.translation = glm::vec3(r.toWorld[3]);
    o.normalToWorld = glm::mat3(r.normalToWorld);
    o.colour = glm::vec3(r.material.colour);
    o.ambient = static_cast<float>(r.material.ambient);
    o.diffuse = static_cast<float>(r.material.diffuse);
    o.specular = static_cast<float>(r.material.specular);
    o.shininess = static_cast<float>(r.material.shininess);
    objects_.push_back(o);
    // The BVH's items are the objects with bounds, in order (RenderScene).
    if (render::worldBounds(r.kind, r.toWorld)) {
      bounded_.push_back(i);
    } else {
      planes_.push_back(i);
    }
  }
  for (const render::RenderLight& l : scene.lights()) {
    lights_.push_back(Light{glm::vec3(l.position), glm::vec3(l.colour)});
  }
}

float FloatTracer::distance(std::uint32_t index, const FloatRay& ray, float tMax, int& face) const {
  const Object& object = objects_[index];
  glm::vec3 o = object.toLocal * (ray.origin - object.translation);
  glm::vec3 d = object.toLocal * ray.direction;
  Span span = shapeSpan(object.kind, o, d);
  if (span.empty) return -1.0f;
  if (span.enter > 0.0f && span.enter < tMax) {
    face = span.enterFace;
    return span.enter;
  }
  if (object.kind != scene::ObjectKind::Plane && span.exit > 0.0f && span.exit < tMax) {
    face = span.exitFace;
    return span.exit;
  }
  return -1.0f;
}

bool FloatTracer::closestHit(const FloatRay& ray, FloatHit& hit) const {
  float best = kInfinity;
  std::uint32_t winner = render::RaySource::kNone;
  int winnerFace = -2;
  auto consider = [&](std::uint32_t index) {
    int face = -2;
    float t = distance(index, ray, best, face);
    if (t >= 0.0f) best = t, winner = index, winnerFace = face;
  };
  for (std::uint32_t plane : planes_) consider(plane);
  render::BoxRay boxRay{glm::dvec3(ray.origin), 1.0 / glm::dvec3(ray.direction)};
  scene_.bvh().traverse(boxRay, static_cast<double>(best), [&](std::uint32_t item) {
    consider(bounded_[item]);
    return static_cast<double>(best);
  });
  if (winner == render::RaySource::kNone) return false;
  const Object& object = objects_[winner];
  hit.t = best;
  hit.object = winner;
  hit.point = ray.origin + best * ray.direction;
  glm::vec3 local = object.toLocal * (hit.point - object.translation);
  hit.normal = glm::normalize(object.normalToWorld * localNormal(object.kind, winnerFace, local));
  return true;
}

bool FloatTracer::anyHit(const FloatRay& ray, float tMax, std::uint32_t& hint) const {
  int face = -2;
  if (hint < objects_.size() && distance(hint, ray, tMax, face) >= 0.0f) return true;
  for (std::uint32_t plane : planes_) {
    if (distance(plane, ray, tMax, face) >= 0.0f) {
      hint = plane;
      return true;
    }
  }
  std::uint32_t found = render::RaySource::kNone;
  render::BoxRay boxRay{glm::dvec3(ray.origin), 1.0 / glm::dvec3(ray.direction)};
  scene_.bvh().traverse(boxRay, static_cast<double>(tMax), [&](std::uint32_t item) {
    if (distance(bounded_[item], ray, tMax, face) >= 0.0f) {
      found = bounded_[item];
      return -1.0;
    }
    return static_cast<double>(tMax);
  });
  hint = found;
  return found != render::RaySource::kNone;
}

glm::vec3 FloatTracer::shadowOrigin(const FloatHit& hit, const FloatRay& ray,
                                    const glm::vec3& side) const {
  float amount = epsilon_;
  if (offset_ == ShadowOffset::ErrorBound) {
    amount = 32.0f * std::numeric_limits<float>::epsilon() *
             std::max(largest(ray.origin), hit.t * largest(ray.direction));
  }
  return hit.point + amount * side;
}

glm::vec3 FloatTracer::shade(const FloatHit& hit, const FloatRay& ray,
                             std::vector<std::uint32_t>& hints, FloatCounts& counts,
                             bool measureSelf) const {
  const Object& m = objects_[hit.object];
  glm::vec3 d = glm::normalize(ray.direction);
  glm::vec3 n = glm::dot(hit.normal, d) > 0.0f ? -hit.normal : hit.normal;
  glm::vec3 toViewer = -d;
  glm::vec3 colour(0.0f);
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    const Light& light = lights_[i];
    colour += m.colour * light.colour * m.ambient;
    glm::vec3 l = light.position - hit.point;
    float length = glm::length(l);
    if (!(length > 0.0f)) continue;
    l /= length;
    float cosine = glm::dot(l, n);
    if (cosine <= 0.0f) continue;
    ++counts.shadow;
    FloatRay shadow;
    shadow.origin = shadowOrigin(hit, ray, n);
    shadow.direction = light.position - shadow.origin;
    const float tMax = 1.0f - 1e-4f;
    if (measureSelf) {
      ++counts.litPoints;
      int face = -2;
      if (distance(hit.object, shadow, tMax, face) >= 0.0f) ++counts.selfShadowed;
    }
    if (anyHit(shadow, tMax, hints[i])) continue;
    colour += m.colour * light.colour * (m.diffuse * cosine);
    glm::vec3 reflected = glm::reflect(-l, n);
    float highlight = std::max(0.0f, glm::dot(reflected, toViewer));
    if (highlight > 0.0f && m.specular > 0.0f) {
      colour += light.colour * (m.specular * specularPower(highlight, m.shininess));
    }
  }
  return colour;
}

}  // namespace bench
