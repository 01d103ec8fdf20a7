// A single-precision tracer of primary and shadow rays, for the float
// experiment of docs/PERFORMANCE.md ("Single precision"): what sfrender
// would be if it traced in float as most tracers do. It is a benchmark, not
// a renderer: nothing in sfrender uses it.
//
// Per object, the ray goes to object space in float (the inverse matrix and
// translation rounded to float), meets the unit shape in float (the same
// formulas as renderer/unit_shapes.h, in float), and the hit point is the
// float o + t d in world space. A shadow ray leaves the hit point moved
// along the normal by an offset, either a fixed epsilon or a float error
// bound, and is not told which object it left: like most float tracers, it
// relies on the offset alone. Shading is the direct Phong term of
// docs/RENDERING.md (ambient per light, diffuse and specular for each
// light with a clear path), in float.
//
// The search uses the project's own BVH (render::RenderScene::bvh, whose
// boxes are float already) with the float ray widened to double for its
// box tests: only the object tests, hit points, normals, offsets and
// shading differ from the double renderer, which is what the experiment
// measures.
#pragma once

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "renderer/render_scene.h"

namespace bench {

struct FloatRay {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};
};

struct FloatHit {
  float t = 0.0f;
  std::uint32_t object = render::RaySource::kNone;
  glm::vec3 point{0.0f};
  glm::vec3 normal{0.0f};  // unit, outward
};

// How a shadow ray's origin is moved off the surface.
enum class ShadowOffset {
  // A fixed distance in world units (1e-4 by default), as most float
  // tracers do.
  Fixed,
  // A bound on the float error of the hit point o + t d: 32 float steps of
  // the largest of |o| and |t d|.
  ErrorBound,
};

// What one thread counts while shading.
struct FloatCounts {
  std::uint64_t primary = 0;
  std::uint64_t shadow = 0;
  // Lit points (facing a light) whose shadow ray meets their own object:
  // acne by self-intersection. Counted only when asked for.
  std::uint64_t litPoints = 0;
  std::uint64_t selfShadowed = 0;
};

class FloatTracer {
 public:
  FloatTracer(const render::RenderScene& scene, ShadowOffset offset, float epsilon = 1e-4f);

  // The nearest surface with t > 0.
  bool closestHit(const FloatRay& ray, FloatHit& hit) const;
  // Whether a surface lies at 0 < t < tMax; `hint` as RenderScene::anyHit's.
  bool anyHit(const FloatRay& ray, float tMax, std::uint32_t& hint) const;
  // The direct Phong colour at `hit`, seen along `ray`. With `measureSelf`,
  // each lit point's shadow ray is also tested against its own object.
  glm::vec3 shade(const FloatHit& hit, const FloatRay& ray, std::vector<std::uint32_t>& hints,
                  FloatCounts& counts, bool measureSelf) const;

 private:
  struct Object {
    scene::ObjectKind kind = scene::ObjectKind::Sphere;
    glm::mat3 toLocal{1.0f};
    glm::vec3 translation{0.0f};
    glm::mat3 normalToWorld{1.0f};
    glm::vec3 colour{1.0f};
    float ambient = 0.0f, diffuse = 0.0f, specular = 0.0f, shininess = 0.0f;
  };
  struct Light {
    glm::vec3 position{0.0f};
    glm::vec3 colour{1.0f};
  };
  // The nearest end of the object's span in (0, tMax), or a negative value;
  // `face` as render::SpanFace.
  float distance(std::uint32_t index, const FloatRay& ray, float tMax, int& face) const;
  glm::vec3 shadowOrigin(const FloatHit& hit, const FloatRay& ray, const glm::vec3& side) const;

  const render::RenderScene& scene_;
  std::vector<Object> objects_;
  std::vector<std::uint32_t> bounded_;  // BVH item -> object, as RenderScene orders them
  std::vector<std::uint32_t> planes_;
  std::vector<Light> lights_;
  ShadowOffset offset_;
  float epsilon_;
};

}  // namespace bench
