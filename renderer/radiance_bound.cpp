#include "renderer/radiance_bound.h"

#include <algorithm>
#include <cmath>

namespace render {

namespace {

// The table holds the depths sfrender allows (--depth up to 1000); a
// deeper library call uses the limit S / (1 - K) past it.
constexpr int kTableSize = 4097;

// Rounding of the tracer's sums and products stays far below these
// relative margins: a sum of n terms errs by at most n * 2^-53, and a
// surface term has a few dozen operations per light, so the surface margin
// covers up to about 10^8 lights; the weight margin is taken once a bounce.
constexpr double kSurfaceMargin = 1.0 + 1e-6;
constexpr double kWeightMargin = 1.0 + 1e-9;

}  // namespace

RadianceBound::RadianceBound(const RenderScene& scene, int maxDepth) : maxDepth_(maxDepth) {
  glm::dvec3 lights(0.0);
  for (const RenderLight& light : scene.lights()) {
    for (int c = 0; c < 3; ++c) {
      if (!finiteAndNotNegative(light.colour[c])) return;
    }
    lights += light.colour;
  }
  // The materials' largest terms, gathered as the records were made. A
  // product with a light's channel (not negative) keeps their order, so
  // the light times the largest factor is the largest of the light times
  // each object's factor, bit for bit.
  const MaterialMaxima& materials = scene.materialMaxima();
  if (!materials.inRange()) return;
  double surface = 0.0;
  for (int c = 0; c < 3; ++c) {
    surface = std::max(surface, lights[c] * materials.surfaceFactor()[c]);
  }
  double weight = materials.branchWeight();
  surface_ = surface * kSurfaceMargin;
  branchWeight_ = weight * kWeightMargin;
  if (!std::isfinite(surface_) || !std::isfinite(branchWeight_)) return;

  // M(n) = S + K * M(n - 1): a hit adds at most S of its own and at most K
  // times what its children bring, and a ray past the limit brings 0.
  long long rows = std::min<long long>(kTableSize, std::max(0LL, 1LL + maxDepth_) + 1);
  byBouncesLeft_.assign(static_cast<std::size_t>(rows), 0.0);
  for (std::size_t n = 1; n < byBouncesLeft_.size(); ++n) {
    byBouncesLeft_[n] = surface_ + branchWeight_ * byBouncesLeft_[n - 1];
  }
  // Every M(n) is below the sum of the whole series when K < 1.
  if (branchWeight_ < 1.0) beyondTable_ = surface_ / (1.0 - branchWeight_) * kWeightMargin;
  bounded_ = true;
}

}  // namespace render
