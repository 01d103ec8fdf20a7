// A render's camera rays and their closest hits, found as the CPU renderer
// finds them: through the eye's direction grid where one pays, else as
// packets down the BVH (docs/TRACING.md, "Packets" and "Direction grids").
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <optional>

#include "renderer/camera.h"
#include "renderer/render_scene.h"
#include "renderer/render_settings.h"

namespace render {

class CameraTrace {
 public:
  /// Builds the eye's grid where RenderSettings::eyeGrid and ::packets ask
  /// for it and it pays (at least 4 samples a bounded object).
  CameraTrace(const RenderScene& scene, const RenderSettings& settings);

  const PinholeCamera& camera() const { return camera_; }
  bool hasEyeGrid() const { return eyeGrid_.has_value(); }

  /// The camera ray through image position `at` (pixels from the top-left
  /// corner), written member by member (PinholeCamera::directionThrough).
  void makeRay(const glm::dvec2& at, Ray& ray) const {
    ray.origin = camera_.eye();
    ray.direction = camera_.directionThrough(at.x, at.y);
  }
  /// The closest hits of `count` camera rays, out[k] for rays[k]: the same,
  /// bit for bit, as RenderScene::closestHit of each ray alone.
  void closestHits(const Ray* rays, int count, std::optional<Hit>* out) const;

 private:
  void buildEyeGrid(const RenderSettings& settings);

  const RenderScene& scene_;
  PinholeCamera camera_;
  std::optional<EyeGrid> eyeGrid_;
};

/// The first sample of every pixel of the image, traced as a uniform render
/// traces its camera rays (tiles on settings.threads threads, a tile's row
/// at a time through CameraTrace), shading left out: onRow(y, x0, count,
/// rays, hits) hears of each row of a tile, on the thread that traced it.
using CameraRowCallback =
    std::function<void(int y, int x0, int count, const Ray* rays, const std::optional<Hit>* hits)>;
void traceCameraRays(const RenderScene& scene, const RenderSettings& settings,
                     const CameraRowCallback& onRow);

}  // namespace render
