// Whitted ray tracing with the Phong model of RENDERING.md.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <optional>

#include "renderer/radiance_bound.h"
#include "renderer/render_scene.h"

namespace render {

// The transparent solids a ray is inside, innermost last; the medium it
// travels in is the innermost (RENDERING.md), or empty space, index 1.
class MediumStack {
 public:
  static constexpr int kCapacity = 64;

  MediumStack() = default;
  // Copies carry the solids on the stack and nothing past them, which is
  // never read: a copy is made per camera sample (of the camera's media,
  // mostly none) and per refraction, and copying the whole array cost a
  // tenth of the render of the default scene.
  MediumStack(const MediumStack& other) : size_(other.size_) {
    std::copy_n(other.objects_.begin(), size_, objects_.begin());
  }
  MediumStack& operator=(const MediumStack& other) {
    size_ = other.size_;
    std::copy_n(other.objects_.begin(), size_, objects_.begin());
    return *this;
  }

  void push(std::uint32_t object) {
    if (size_ < kCapacity) objects_[size_++] = object;
  }
  // Removes `object` wherever it stands (solids may overlap in any order).
  void remove(std::uint32_t object);
  double refractiveIndex(const RenderScene& scene) const;
  int size() const { return size_; }

 private:
  std::array<std::uint32_t, kCapacity> objects_{};
  int size_ = 0;
};

struct RayCounts {
  std::uint64_t primary = 0;
  std::uint64_t secondary = 0;  // reflected and refracted
  std::uint64_t shadow = 0;
  // Reflected and refracted rays not traced: what they could bring back
  // fits the error allowed (Tracer::trace), or they would pass the depth
  // limit, where they bring black.
  std::uint64_t pruned = 0;
  // Reflected and refracted rays not traced because their sample had spent
  // its allowance (TraceContext::allowance): only these can move a pixel by
  // more than the tolerance.
  std::uint64_t cut = 0;
  RayCounts& operator+=(const RayCounts& o) {
    primary += o.primary;
    secondary += o.secondary;
    shadow += o.shadow;
    pruned += o.pruned;
    cut += o.cut;
    return *this;
  }
};

// The answers of a hit's shadow rays toward the first 32 lights, found
// ahead of its shading: bit i of `known` set where light i's is in bit i of
// `blocked`.
struct ShadowAnswers {
  static constexpr std::size_t kLights = 32;
  std::uint32_t known = 0;
  std::uint32_t blocked = 0;
};

// What one thread carries from ray to ray: its ray counts, the reflected
// and refracted rays the current sample may still trace, and per light
// (light index modulo kOccluderSlots) the object that last blocked a shadow
// ray toward it, tried first on the next (RenderScene::anyHit). Neighbouring
// pixels mostly lie in the same object's shadow, so the hint often ends a
// shadow ray after one object test instead of a walk down the hierarchy.
// Aligned to a cache line: the threads' contexts lie side by side in one
// vector, and each thread writes its own on every ray.
struct alignas(64) TraceContext {
  static constexpr std::size_t kOccluderSlots = 8;
  RayCounts counts;
  // Set before each primary ray (renderImage); once it is spent, the
  // sample's remaining branches are cut, the heaviest having gone first.
  std::uint64_t allowance = std::numeric_limits<std::uint64_t>::max();
  // A bound on what the branches left out of the colour last traced would
  // have added to any channel (never negative: what is left out is not), so
  // that the full colour lies between that colour and it plus this. Reset
  // by the caller.
  double slack = 0.0;
  // Whether the last camera ray traced (bounce 0) met an object: its
  // sample's share of the pixel's coverage (Image::coverage).
  bool primaryHit = false;
  // The object that camera ray met first, or RaySource::kNone: what adaptive
  // anti-aliasing compares between neighbouring pixels (an edge between two
  // objects of one colour).
  std::uint32_t primaryObject = RaySource::kNone;
  std::array<std::uint32_t, kOccluderSlots> lastOccluder = filledWithNone();
  // The answers of the next shaded hit's shadow rays, found beforehand for a
  // packet of camera rays' hits (Tracer::primaryShadows): bit i of `known`
  // for light i (i < 32) whose answer is in bit i of `blocked`. Spent by the
  // next shadeSurface, which traces the others.
  ShadowAnswers shadows;

 private:
  static constexpr std::array<std::uint32_t, kOccluderSlots> filledWithNone() {
    std::array<std::uint32_t, kOccluderSlots> slots{};
    slots.fill(RaySource::kNone);
    return slots;
  }
};

// Reflectance by Schlick's approximation for a ray going from index n1 into
// n2 at incidence cosine cosIncident; 1 under total internal reflection.
double schlickReflectance(double n1, double n2, double cosIncident);

// The refracted direction of the unit vector d at the normal n facing it, or
// nothing under total internal reflection (Snell: n1 sin i = n2 sin t).
bool refractDirection(const glm::dvec3& d, const glm::dvec3& n, double n1, double n2,
                      glm::dvec3& refracted);

class Tracer {
 public:
  // maxDepth: the number of bounces traced; the ray that would make one more
  // returns black.
  Tracer(const RenderScene& scene, int maxDepth)
      : scene_(scene), maxDepth_(maxDepth), bound_(scene, maxDepth) {}

  // The colour seen along `ray`, which left `source` after `bounce` bounces
  // and travels through `media`, to within `tolerance` in each channel:
  // adaptive depth control (docs/RENDERING.md, "Cost") leaves out the
  // reflected and refracted rays that cannot move it by more, all of them
  // together. With 0 every ray is traced but those whose weight is 0 or that
  // would pass the depth limit, which change nothing.
  glm::dvec3 trace(const Ray& ray, const RaySource& source, int bounce, MediumStack& media,
                   TraceContext& context, double tolerance = 0.0) const {
    return scene_.hasTransparency()
               ? traceWith<true>(ray, source, bounce, media, context, tolerance)
               : traceWith<false>(ray, source, bounce, media, context, tolerance);
  }

  // trace for a camera ray (bounce 0, leaving no surface) whose closest hit
  // is already found (RenderScene::closestHits, for a packet of them):
  // `found` is scene.closestHit(ray, RaySource{}), and the colour is the one
  // trace gives.
  glm::dvec3 traceFromHit(const Ray& ray, const std::optional<Hit>& found, MediumStack& media,
                          TraceContext& context, double tolerance = 0.0) const {
    if (0 > maxDepth_) return glm::dvec3(0.0);
    return scene_.hasTransparency() ? shade<true>(ray, found, 0, media, context, tolerance)
                                    : shade<false>(ray, found, 0, media, context, tolerance);
  }

  // The shadow rays that traceFromHit's shading of each of `count` camera
  // rays' hits (rays[k], hits[k]) traces toward each light without a
  // direction grid, traced ahead as packets (RenderScene::anyHits): out[k]
  // for hits[k], for context.shadows before its traceFromHit. The same
  // answers, and colours, as tracing each alone (docs/TRACING.md, "Packets").
  void primaryShadows(const Ray* rays, const std::optional<Hit>* hits, int count,
                      TraceContext& context, ShadowAnswers* out) const;

  const RadianceBound& bound() const { return bound_; }

  // The Phong surface term at a hit (ambient per light, diffuse and specular
  // for each light with a clear path), for the viewer along `toViewer`;
  // `normal` faces the viewer.
  glm::dvec3 shadeSurface(const Hit& hit, const glm::dvec3& normal, const glm::dvec3& toViewer,
                          TraceContext& context) const;

  // Whether anything lies on the open segment from the hit to the scene's
  // light `light`; `lastOccluder` is RenderScene::anyHit's hint, when the
  // caller keeps one.
  bool shadowed(const Hit& hit, std::size_t light, TraceContext& context,
                std::uint32_t* lastOccluder = nullptr) const;

 private:
  // A scene without transparency is traced with no refraction code at all.
  template <bool kRefraction>
  glm::dvec3 traceWith(const Ray& ray, const RaySource& source, int bounce, MediumStack& media,
                       TraceContext& context, double tolerance) const;

  // traceWith after the search: the colour from the closest hit `found`
  // along `ray` (black where there is none).
  template <bool kRefraction>
  glm::dvec3 shade(const Ray& ray, const std::optional<Hit>& found, int bounce, MediumStack& media,
                   TraceContext& context, double tolerance) const;

  // The reflected and refracted parts of a hit on a transparent object,
  // weighed against each other by Schlick's approximation when it has both.
  glm::dvec3 reflectAndRefract(const Hit& hit, const glm::dvec3& d, const glm::dvec3& n, int bounce,
                               MediumStack& media, TraceContext& context, double tolerance) const;

  // Whether the children of a hit at `bounce`, whose weights in its colour
  // add up to `weight` in size, can move it by more than `tolerance`; if so,
  // `childTolerance` is the error each child may make, their share of it.
  bool worthTracing(double weight, int bounce, double tolerance, double& childTolerance) const;

  // The shadow ray from the hit toward light `light`, as shadowed traces it:
  // false where it is clear without being traced.
  bool shadowRay(const Hit& hit, std::size_t light, Ray& ray, RaySource& source,
                 double& tMax) const;

  const RenderScene& scene_;
  int maxDepth_;
  RadianceBound bound_;
};

}  // namespace render
