#include "renderer/tracer.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "renderer/float_error.h"

namespace render {

namespace {

// A ray leaving a hit in `direction`: its origin just off the surface on
// that side, by the hit point's error bound.
Ray spawnFrom(const Hit& hit, const glm::dvec3& direction) {
  return Ray{offsetRayOrigin(hit.point, hit.pointError, hit.normal, direction), direction};
}

RaySource leaving(const Hit& hit, const glm::dvec3& direction) {
  return RaySource{hit.object, glm::dot(direction, hit.normal) < 0.0};
}

// x^e, by repeated squaring when e is a whole number up to 1024 (the usual
// Phong exponents, such as 200): the same value as std::pow to within a few
// ulps, at a tenth of its cost, which was 7% of a render.
double specularPower(double x, double e) {
  if (!(e >= 0.0 && e <= 1024.0) || e != std::floor(e)) return std::pow(x, e);
  auto n = static_cast<unsigned>(e);
  double result = 1.0;
  while (n > 0) {
    if (n & 1u) result *= x;
    x *= x;
    n >>= 1;
  }
  return result;
}

}  // namespace

void MediumStack::remove(std::uint32_t object) {
  for (int i = size_ - 1; i >= 0; --i) {
    if (objects_[i] == object) {
      std::copy(objects_.begin() + i + 1, objects_.begin() + size_, objects_.begin() + i);
      --size_;
      return;
    }
  }
}

double MediumStack::refractiveIndex(const RenderScene& scene) const {
  return size_ == 0 ? 1.0 : scene.objects()[objects_[size_ - 1]].material.ri;
}

double schlickReflectance(double n1, double n2, double cosIncident) {
  double r0 = (n1 - n2) / (n1 + n2);
  r0 *= r0;
  double cosine = cosIncident;
  if (n1 > n2) {
    // Going into a lighter medium, the transmitted angle is the larger one.
    double sin2t = (n1 / n2) * (n1 / n2) * (1.0 - cosIncident * cosIncident);
    if (sin2t >= 1.0) return 1.0;
    cosine = std::sqrt(1.0 - sin2t);
  }
  double x = 1.0 - cosine;
  return r0 + (1.0 - r0) * x * x * x * x * x;
}

bool refractDirection(const glm::dvec3& d, const glm::dvec3& n, double n1, double n2,
                      glm::dvec3& refracted) {
  double eta = n1 / n2;
  double cosIncident = -glm::dot(d, n);
  double k = 1.0 - eta * eta * (1.0 - cosIncident * cosIncident);
  if (k < 0.0) return false;
  refracted = glm::normalize(eta * d + (eta * cosIncident - std::sqrt(k)) * n);
  return true;
}

bool Tracer::shadowed(const Hit& hit, const glm::dvec3& light, TraceContext& context,
                      std::uint32_t* lastOccluder) const {
  ++context.counts.shadow;
  Ray ray;
  glm::dvec3 toLight = light - hit.point;
  ray.origin = offsetRayOrigin(hit.point, hit.pointError, hit.normal, toLight);
  ray.direction = light - ray.origin;
  RaySource source{hit.object, glm::dot(ray.direction, hit.normal) < 0.0};
  // The open segment ends just short of the light by the rounding a hit
  // there could carry, so that a light lying on a surface is not hidden by
  // that surface.
  double extent =
      std::max({std::abs(light.x), std::abs(light.y), std::abs(light.z), std::abs(ray.origin.x),
                std::abs(ray.origin.y), std::abs(ray.origin.z)});
  double length =
      std::max({std::abs(ray.direction.x), std::abs(ray.direction.y), std::abs(ray.direction.z)});
  if (length == 0.0) return false;
  double tMax = 1.0 - gamma(32) * extent / length;
  if (tMax <= 0.0) return false;
  return scene_.anyHit(ray, source, tMax, lastOccluder);
}

glm::dvec3 Tracer::shadeSurface(const Hit& hit, const glm::dvec3& normal,
                                const glm::dvec3& toViewer, TraceContext& context) const {
  const scene::Material& m = scene_.objects()[hit.object].material;
  glm::dvec3 colour(0.0);
  const std::vector<RenderLight>& lights = scene_.lights();
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const RenderLight& light = lights[i];
    colour += m.colour * light.colour * m.ambient;
    glm::dvec3 l = light.position - hit.point;
    double distance = glm::length(l);
    if (!(distance > 0.0)) continue;
    l /= distance;
    double cosine = glm::dot(l, normal);
    if (cosine <= 0.0 || shadowed(hit, light.position, context,
                                  &context.lastOccluder[i % TraceContext::kOccluderSlots])) {
      continue;
    }
    colour += m.colour * light.colour * (m.diffuse * cosine);
    glm::dvec3 reflected = glm::reflect(-l, normal);
    double highlight = std::max(0.0, glm::dot(reflected, toViewer));
    if (highlight > 0.0 && m.specular > 0.0) {
      colour += light.colour * (m.specular * specularPower(highlight, m.shininess));
    }
  }
  return colour;
}

template <bool kRefraction>
glm::dvec3 Tracer::traceWith(const Ray& ray, const RaySource& source, int bounce,
                             MediumStack& media, TraceContext& context) const {
  if (bounce > maxDepth_) return glm::dvec3(0.0);
  std::optional<Hit> found = scene_.closestHit(ray, source);
  if (!found) return glm::dvec3(0.0);
  const Hit& hit = *found;
  const RenderObject& object = scene_.objects()[hit.object];
  const scene::Material& m = object.material;

  glm::dvec3 d = glm::normalize(ray.direction);
  // The normal that faces the incoming ray.
  glm::dvec3 n = glm::dot(hit.normal, d) > 0.0 ? -hit.normal : hit.normal;
  glm::dvec3 colour = shadeSurface(hit, n, -d, context);

  glm::dvec3 reflected(0.0);
  if (m.reflectivity > 0.0) {
    ++context.counts.secondary;
    glm::dvec3 r = glm::reflect(d, n);
    reflected = m.reflectivity * traceWith<kRefraction>(spawnFrom(hit, r), leaving(hit, r),
                                                        bounce + 1, media, context);
  }
  if constexpr (!kRefraction) {
    return colour + reflected;
  } else {
    if (m.transparency <= 0.0) return colour + reflected;
    return colour + refract(hit, d, n, bounce, media, reflected, context);
  }
}

glm::dvec3 Tracer::refract(const Hit& hit, const glm::dvec3& d, const glm::dvec3& n, int bounce,
                           const MediumStack& media, const glm::dvec3& reflected,
                           TraceContext& context) const {
  const RenderObject& object = scene_.objects()[hit.object];
  const scene::Material& m = object.material;

  glm::dvec3 refracted(0.0);
  double reflectance = 1.0;
  if (object.kind == scene::ObjectKind::Plane) {
    // A plane is a sheet, not a solid: light passes it without bending.
    ++context.counts.secondary;
    reflectance = 0.0;
    MediumStack same = media;
    refracted = m.transparency *
                traceWith<true>(spawnFrom(hit, d), leaving(hit, d), bounce + 1, same, context);
  } else {
    // The innermost solid the ray is in gives n1; entering this one, n2 is
    // its own index, and leaving it, the index of what contains it.
    bool entering = !hit.fromInside;
    double n1 = entering ? media.refractiveIndex(scene_) : m.ri;
    MediumStack after = media;
    if (entering) {
      after.push(hit.object);
    } else {
      after.remove(hit.object);
    }
    double n2 = entering ? m.ri : after.refractiveIndex(scene_);
    reflectance = schlickReflectance(n1, n2, -glm::dot(d, n));
    glm::dvec3 t;
    if (refractDirection(d, n, n1, n2, t)) {
      ++context.counts.secondary;
      refracted = m.transparency *
                  traceWith<true>(spawnFrom(hit, t), leaving(hit, t), bounce + 1, after, context);
    }
  }
  // With both, Schlick's reflectance shares the light between them.
  if (m.reflectivity > 0.0) return reflectance * reflected + (1.0 - reflectance) * refracted;
  return refracted;
}

template glm::dvec3 Tracer::traceWith<true>(const Ray&, const RaySource&, int, MediumStack&,
                                            TraceContext&) const;
template glm::dvec3 Tracer::traceWith<false>(const Ray&, const RaySource&, int, MediumStack&,
                                             TraceContext&) const;

}  // namespace render
