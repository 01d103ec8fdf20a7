// The most a ray can bring back in a scene, under the shading model of
// RENDERING.md: what adaptive depth control (Tracer, docs/RENDERING.md,
// "Cost") weighs a branch against before it traces it.
#pragma once

#include <limits>
#include <vector>

#include "renderer/render_scene.h"

namespace render {

class RadianceBound {
 public:
  // A ray that would make bounce maxDepth + 1 returns black.
  RadianceBound(const RenderScene& scene, int maxDepth);

  // An upper bound on every channel, in size, of the colour traced at
  // `bounce` (Tracer::trace): 0 past the depth limit, and +inf for every
  // bounce when the scene has no bound (a material or light outside the
  // ranges of FORMATS.md, or a sum that overflows).
  double at(int bounce) const {
    if (!bounded_) return kUnbounded;
    long long left = static_cast<long long>(maxDepth_) - bounce + 1;
    if (left <= 0) return 0.0;
    if (left < static_cast<long long>(byBouncesLeft_.size())) return byBouncesLeft_[left];
    return beyondTable_;
  }
  bool bounded() const { return bounded_; }

  // S: the most one surface term (every light, ambient, diffuse and
  // highlight at their largest) adds to a channel.
  double surface() const { return surface_; }
  // K: the most the weights of one hit's reflected and refracted rays add
  // up to.
  double branchWeight() const { return branchWeight_; }

  static constexpr double kUnbounded = std::numeric_limits<double>::infinity();

 private:
  int maxDepth_;
  bool bounded_ = false;
  double surface_ = 0.0;
  double branchWeight_ = 0.0;
  // [n]: the bound for a ray with n - 1 bounces still allowed after it,
  // M(n) = S + K * M(n - 1), M(0) = 0.
  std::vector<double> byBouncesLeft_;
  double beyondTable_ = kUnbounded;  // S / (1 - K) when K < 1
};

}  // namespace render
