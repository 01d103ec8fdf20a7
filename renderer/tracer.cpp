#include "renderer/tracer.h"

#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <glm/geometric.hpp>
#include <utility>

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

// Two values side by side, one a lane: each operation on them is the scalar
// one on each lane, so that a lane holds the same bits as the scalar
// expression it follows (GCC's and Clang's vector extension: SSE2 on
// x86-64, pairs of scalar operations elsewhere).
using Lanes = double __attribute__((vector_size(16)));

Lanes sqrtLanes(Lanes x) {
#if defined(__SSE2__)
  return _mm_sqrt_pd(x);
#else
  return Lanes{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
}

// std::max(0.0, x) in each lane: x where x > 0, else 0 (NaN too).
Lanes atLeastZero(Lanes x) {
#if defined(__SSE2__)
  return _mm_max_pd(x, _mm_setzero_pd());
#else
  return Lanes{std::max(0.0, x[0]), std::max(0.0, x[1])};
#endif
}

// x^e in each lane, by repeated squaring when e is a whole number up to
// 1024 (the usual Phong exponents, such as 200): the same value as std::pow
// to within a few ulps, at a tenth of its cost, which was 7% of a render.
// Both lanes share the exponent, so one loop serves them.
Lanes specularPowers(Lanes x, double e) {
  auto each = [&] { return Lanes{std::pow(x[0], e), std::pow(x[1], e)}; };
  if (!(e >= 0.0 && e <= 1024.0)) return each();
  // Whole when truncation keeps it: floor's test for e >= 0, without the
  // call floor is on baseline x86-64 (no SSE4.1 rounding instruction).
  auto n = static_cast<unsigned>(e);
  if (static_cast<double>(n) != e) return each();
  Lanes result{1.0, 1.0};
  while (n > 0) {
    if (n & 1u) result *= x;
    x *= x;
    n >>= 1;
  }
  return result;
}

// What shadeSurface needs of two lights at a hit, lane k for light k: the
// distance to it, the cosine of its direction l with the normal, and the
// highlight (the reflection of -l about the normal, dotted with the
// viewer's direction, at least 0). The expressions are glm's (length,
// l / distance, dot, reflect), lane by lane.
struct LightPair {
  Lanes distance, cosine, highlight;
};

LightPair lightPair(const glm::dvec3& light0, const glm::dvec3& light1, const glm::dvec3& point,
                    const glm::dvec3& n, const glm::dvec3& toViewer) {
  auto both = [](double v) { return Lanes{v, v}; };
  Lanes lx = Lanes{light0.x, light1.x} - both(point.x);
  Lanes ly = Lanes{light0.y, light1.y} - both(point.y);
  Lanes lz = Lanes{light0.z, light1.z} - both(point.z);
  LightPair pair;
  pair.distance = sqrtLanes(lx * lx + ly * ly + lz * lz);
  lx /= pair.distance;
  ly /= pair.distance;
  lz /= pair.distance;
  Lanes nx = both(n.x), ny = both(n.y), nz = both(n.z);
  pair.cosine = lx * nx + ly * ny + lz * nz;
  // glm::reflect(i, n): i - n * dot(n, i) * 2, for i = -l.
  Lanes ix = -lx, iy = -ly, iz = -lz;
  Lanes along = nx * ix + ny * iy + nz * iz;
  Lanes rx = ix - nx * along * 2.0;
  Lanes ry = iy - ny * along * 2.0;
  Lanes rz = iz - nz * along * 2.0;
  pair.highlight =
      atLeastZero(rx * both(toViewer.x) + ry * both(toViewer.y) + rz * both(toViewer.z));
  return pair;
}

// Takes a reflected or refracted ray from the sample's allowance, or counts
// it as cut when none is left.
bool takeRay(TraceContext& context) {
  if (context.allowance == 0) {
    ++context.counts.cut;
    return false;
  }
  --context.allowance;
  ++context.counts.secondary;
  return true;
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
  return size_ == 0 ? 1.0 : scene.material(objects_[size_ - 1]).ri;
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

bool Tracer::shadowed(const Hit& hit, std::size_t lightIndex, TraceContext& context,
                      std::uint32_t* lastOccluder) const {
  ++context.counts.shadow;
  // The light's grid cell for the hit point: where it lists nothing and no
  // other plane could block, the ray is clear before it is even made; else
  // the cell serves the ray's search.
  std::uint32_t cell = scene_.shadowCell(lightIndex, hit.point, hit.pointError);
  if (cell != DirectionGrid::kNoCell && scene_.lightGrid(lightIndex)->items(cell).empty() &&
      scene_.noPlaneBut(hit.object)) {
    if (lastOccluder) *lastOccluder = RaySource::kNone;
    return false;
  }
  Ray ray;
  RaySource source;
  double tMax = 0.0;
  if (!shadowRay(hit, lightIndex, ray, source, tMax)) return false;
  return scene_.anyHitTowardLight(lightIndex, ray, source, tMax, lastOccluder, cell);
}

bool Tracer::shadowRay(const Hit& hit, std::size_t lightIndex, Ray& ray, RaySource& source,
                       double& tMax) const {
  const glm::dvec3& light = scene_.lights()[lightIndex].position;
  glm::dvec3 toLight = light - hit.point;
  ray.origin = offsetRayOrigin(hit.point, hit.pointError, hit.normal, toLight);
  ray.direction = light - ray.origin;
  source = RaySource{hit.object, glm::dot(ray.direction, hit.normal) < 0.0};
  // The open segment ends just short of the light by the rounding a hit
  // there could carry, so that a light lying on a surface is not hidden by
  // that surface.
  double extent =
      std::max({std::abs(light.x), std::abs(light.y), std::abs(light.z), std::abs(ray.origin.x),
                std::abs(ray.origin.y), std::abs(ray.origin.z)});
  double length =
      std::max({std::abs(ray.direction.x), std::abs(ray.direction.y), std::abs(ray.direction.z)});
  if (length == 0.0) return false;
  tMax = 1.0 - gamma(32) * extent / length;
  return tMax > 0.0;
}

void Tracer::primaryShadows(const Ray* rays, const std::optional<Hit>* hits, int count,
                            TraceContext& context, ShadowAnswers* out) const {
  for (int k = 0; k < count; ++k) out[k] = ShadowAnswers{};
  if (0 > maxDepth_) return;
  const std::vector<RenderLight>& lights = scene_.lights();
  std::size_t packed = std::min(lights.size(), ShadowAnswers::kLights);
  constexpr int kBatch = Bvh::kPacketSize;
  for (int first = 0; first < count; first += kBatch) {
    int n = std::min(kBatch, count - first);
    // Each hit's normal facing its ray, as shade finds it.
    glm::dvec3 normals[kBatch], toViewers[kBatch];
    for (int k = 0; k < n; ++k) {
      if (!hits[first + k]) continue;
      glm::dvec3 d = glm::normalize(rays[first + k].direction);
      normals[k] = glm::dot(hits[first + k]->normal, d) > 0.0 ? -hits[first + k]->normal
                                                              : hits[first + k]->normal;
      toViewers[k] = -d;
    }
    for (std::size_t i = 0; i < packed; ++i) {
      if (scene_.lightGrid(i)) continue;
      Ray shadowRays[kBatch];
      RaySource sources[kBatch];
      double tMaxes[kBatch];
      int at[kBatch];
      int traced = 0;
      for (int k = 0; k < n; ++k) {
        if (!hits[first + k]) continue;
        const Hit& hit = *hits[first + k];
        // shadeSurface's test, on the lane of its pair that light i takes
        // (each lane's arithmetic is its own, so the same bits).
        LightPair pair =
            lightPair(lights[i].position, lights[i].position, hit.point, normals[k], toViewers[k]);
        if (!(pair.distance[0] > 0.0 && !(pair.cosine[0] <= 0.0))) continue;
        out[first + k].known |= 1u << i;
        if (shadowRay(hit, i, shadowRays[traced], sources[traced], tMaxes[traced])) {
          at[traced++] = first + k;
        }
      }
      bool blocked[kBatch];
      scene_.anyHits(shadowRays, sources, tMaxes, traced, blocked,
                     &context.lastOccluder[i % TraceContext::kOccluderSlots]);
      for (int t = 0; t < traced; ++t) {
        if (blocked[t]) out[at[t]].blocked |= 1u << i;
      }
    }
  }
}

glm::dvec3 Tracer::shadeSurface(const Hit& hit, const glm::dvec3& normal,
                                const glm::dvec3& toViewer, TraceContext& context) const {
  const scene::Material& m = scene_.material(hit.object);
  glm::dvec3 colour(0.0);
  const std::vector<RenderLight>& lights = scene_.lights();
  const ShadowAnswers shadows = std::exchange(context.shadows, ShadowAnswers{});
  for (std::size_t first = 0; first < lights.size(); first += 2) {
    // Two lights side by side (the last light twice when their number is
    // odd): their geometry, then their shadow rays, then the highlights
    // that count, and their terms added in the lights' order.
    std::size_t lanes = std::min<std::size_t>(2, lights.size() - first);
    LightPair pair = lightPair(lights[first].position, lights[first + lanes - 1].position,
                               hit.point, normal, toViewer);
    bool lit[2] = {false, false};
    bool highlights = false;
    for (std::size_t lane = 0; lane < lanes; ++lane) {
      std::size_t i = first + lane;
      // As the scalar tests were written: a cosine that is not a number
      // still has its shadow ray traced.
      if (!(pair.distance[lane] > 0.0 && !(pair.cosine[lane] <= 0.0))) {
        lit[lane] = false;
      } else if (i < ShadowAnswers::kLights && (shadows.known >> i & 1u)) {
        ++context.counts.shadow;
        lit[lane] = !(shadows.blocked >> i & 1u);
      } else {
        lit[lane] =
            !shadowed(hit, i, context, &context.lastOccluder[i % TraceContext::kOccluderSlots]);
      }
      highlights |= lit[lane] && pair.highlight[lane] > 0.0;
    }
    Lanes power{0.0, 0.0};
    if (highlights && m.specular > 0.0) power = specularPowers(pair.highlight, m.shininess);
    for (std::size_t lane = 0; lane < lanes; ++lane) {
      const RenderLight& light = lights[first + lane];
      colour += m.colour * light.colour * m.ambient;
      if (!lit[lane]) continue;
      colour += m.colour * light.colour * (m.diffuse * pair.cosine[lane]);
      if (pair.highlight[lane] > 0.0 && m.specular > 0.0) {
        colour += light.colour * (m.specular * power[lane]);
      }
    }
  }
  return colour;
}

bool Tracer::worthTracing(double weight, int bounce, double tolerance,
                          double& childTolerance) const {
  childTolerance = tolerance;
  double bound = bound_.at(bounce + 1);
  // Without a bound, every branch is traced, as it always was.
  if (!(bound < RadianceBound::kUnbounded)) return true;
  // A child brings back at most `bound`, so leaving all of them out moves
  // this colour by at most weight * bound (docs/RENDERING.md, "Cost").
  if (weight * bound <= tolerance) return false;
  // Shares in proportion to the weights: child i may make an error of
  // tolerance / weight, which its weight w_i turns into w_i / weight of
  // this one's tolerance, and the shares add up to it.
  childTolerance = tolerance / weight;
  return true;
}

template <bool kRefraction>
glm::dvec3 Tracer::traceWith(const Ray& ray, const RaySource& source, int bounce,
                             MediumStack& media, TraceContext& context, double tolerance) const {
  if (bounce > maxDepth_) return glm::dvec3(0.0);
  return shade<kRefraction>(ray, scene_.closestHit(ray, source), bounce, media, context, tolerance);
}

template <bool kRefraction>
glm::dvec3 Tracer::shade(const Ray& ray, const std::optional<Hit>& found, int bounce,
                         MediumStack& media, TraceContext& context, double tolerance) const {
  if (bounce == 0) {
    context.primaryHit = found.has_value();
    context.primaryObject = found ? found->object : RaySource::kNone;
  }
  if (!found) return glm::dvec3(0.0);
  const Hit& hit = *found;
  const scene::Material& m = scene_.material(hit.object);

  glm::dvec3 d = glm::normalize(ray.direction);
  // The normal that faces the incoming ray.
  glm::dvec3 n = glm::dot(hit.normal, d) > 0.0 ? -hit.normal : hit.normal;
  glm::dvec3 colour = shadeSurface(hit, n, -d, context);

  if constexpr (kRefraction) {
    if (m.transparency > 0.0) {
      return colour + reflectAndRefract(hit, d, n, bounce, media, context, tolerance);
    }
  }
  glm::dvec3 reflected(0.0);
  double childTolerance = 0.0;
  if (m.reflectivity > 0.0) {
    if (!worthTracing(m.reflectivity, bounce, tolerance, childTolerance)) {
      ++context.counts.pruned;
      context.slack += m.reflectivity * bound_.at(bounce + 1);
    } else if (takeRay(context)) {
      double outer = std::exchange(context.slack, 0.0);
      glm::dvec3 r = glm::reflect(d, n);
      reflected =
          m.reflectivity * traceWith<kRefraction>(spawnFrom(hit, r), leaving(hit, r), bounce + 1,
                                                  media, context, childTolerance);
      context.slack = outer + m.reflectivity * context.slack;
    } else {
      context.slack += m.reflectivity * bound_.at(bounce + 1);
    }
  }
  return colour + reflected;
}

glm::dvec3 Tracer::reflectAndRefract(const Hit& hit, const glm::dvec3& d, const glm::dvec3& n,
                                     int bounce, MediumStack& media, TraceContext& context,
                                     double tolerance) const {
  const RenderObject& object = scene_.objects()[hit.object];
  const scene::Material& m = scene_.material(hit.object);

  // Where the refracted ray goes, and the share of each part, come first:
  // they are what the branches are weighed by before either is traced.
  MediumStack after = media;
  glm::dvec3 t = d;
  bool passes = true;
  double reflectance = 1.0;
  if (object.kind == scene::ObjectKind::Plane) {
    // A plane is a sheet, not a solid: light passes it without bending.
    reflectance = 0.0;
  } else {
    // The innermost solid the ray is in gives n1; entering this one, n2 is
    // its own index, and leaving it, the index of what contains it.
    bool entering = !hit.fromInside;
    double n1 = entering ? media.refractiveIndex(scene_) : m.ri;
    if (entering) {
      after.push(hit.object);
    } else {
      after.remove(hit.object);
    }
    double n2 = entering ? m.ri : after.refractiveIndex(scene_);
    reflectance = schlickReflectance(n1, n2, -glm::dot(d, n));
    passes = refractDirection(d, n, n1, n2, t);
  }
  bool reflects = m.reflectivity > 0.0;
  // With both, Schlick's reflectance shares the light between them.
  double reflectedWeight = reflects ? reflectance * m.reflectivity : 0.0;
  double refractedWeight = passes ? (reflects ? 1.0 - reflectance : 1.0) * m.transparency : 0.0;
  double childTolerance = 0.0;
  bool worth = worthTracing(std::abs(reflectedWeight) + std::abs(refractedWeight), bounce,
                            tolerance, childTolerance);
  // A part of weight 0 adds exactly 0 when the bound says what it brings
  // is finite (a plane's reflection, refraction at R = 1).
  bool bounded = bound_.at(bounce + 1) < RadianceBound::kUnbounded;

  bool traceReflected = reflects && worth && !(bounded && reflectedWeight == 0.0);
  bool traceRefracted = passes && worth && !(bounded && refractedWeight == 0.0);
  context.counts.pruned +=
      (reflects && !traceReflected ? 1 : 0) + (passes && !traceRefracted ? 1 : 0);

  // A part not traced leaves out at most its weight times the bound; a part
  // traced, its weight times what its own branches left out.
  double childBound = bound_.at(bounce + 1);
  auto leftOut = [&](double weight) { context.slack += std::abs(weight) * childBound; };
  glm::dvec3 reflected(0.0);
  auto traceReflection = [&] {
    if (!reflects) return;
    if (!traceReflected || !takeRay(context)) return leftOut(reflectedWeight);
    double outer = std::exchange(context.slack, 0.0);
    glm::dvec3 r = glm::reflect(d, n);
    reflected = m.reflectivity * traceWith<true>(spawnFrom(hit, r), leaving(hit, r), bounce + 1,
                                                 media, context, childTolerance);
    context.slack = outer + std::abs(reflectedWeight) * context.slack;
  };
  glm::dvec3 refracted(0.0);
  auto traceRefraction = [&] {
    if (!passes) return;
    if (!traceRefracted || !takeRay(context)) return leftOut(refractedWeight);
    double outer = std::exchange(context.slack, 0.0);
    refracted = m.transparency * traceWith<true>(spawnFrom(hit, t), leaving(hit, t), bounce + 1,
                                                 after, context, childTolerance);
    context.slack = outer + std::abs(refractedWeight) * context.slack;
  };
  // The heavier part first: when the sample's allowance runs out, it is the
  // lighter that is cut. The order changes no value.
  if (std::abs(refractedWeight) > std::abs(reflectedWeight)) {
    traceRefraction();
    traceReflection();
  } else {
    traceReflection();
    traceRefraction();
  }
  if (reflects) return reflectance * reflected + (1.0 - reflectance) * refracted;
  return refracted;
}

template glm::dvec3 Tracer::shade<true>(const Ray&, const std::optional<Hit>&, int, MediumStack&,
                                        TraceContext&, double) const;
template glm::dvec3 Tracer::shade<false>(const Ray&, const std::optional<Hit>&, int, MediumStack&,
                                         TraceContext&, double) const;
template glm::dvec3 Tracer::traceWith<true>(const Ray&, const RaySource&, int, MediumStack&,
                                            TraceContext&, double) const;
template glm::dvec3 Tracer::traceWith<false>(const Ray&, const RaySource&, int, MediumStack&,
                                             TraceContext&, double) const;

}  // namespace render
