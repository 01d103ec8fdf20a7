#include "renderer/radiance_bound.h"

#include <algorithm>
#include <cmath>

namespace render {

namespace {

// The table holds the depths sfrender allows (--depth up to 1000); a
// deeper library call uses the limit S / (1 - K) past it.
constexpr int kTableSize = 4097;

// Dot products of unit vectors, the diffuse cosine and the highlight's
// base, come out at most this far above 1 (a few ulps of normalisation).
constexpr double kUnitDotMax = 1.0 + 1e-14;
// Rounding of the tracer's sums and products stays far below these
// relative margins: a sum of n terms errs by at most n * 2^-53, and a
// surface term has a few dozen operations per light, so the surface margin
// covers up to about 10^8 lights; the weight margin is taken once a bounce.
constexpr double kSurfaceMargin = 1.0 + 1e-6;
constexpr double kWeightMargin = 1.0 + 1e-9;

bool nonNegative(double v) {
  return std::isfinite(v) && v >= 0.0;
}

bool inRange(const scene::Material& m) {
  return nonNegative(m.colour.r) && nonNegative(m.colour.g) && nonNegative(m.colour.b) &&
         nonNegative(m.ambient) && nonNegative(m.diffuse) && nonNegative(m.specular) &&
         nonNegative(m.shininess) && nonNegative(m.reflectivity) && nonNegative(m.transparency);
}

// The most the weights of a hit's reflected and refracted rays add up to
// (RENDERING.md): R * REFLECTIVITY + (1 - R) * TRANSPARENCY with R in
// [0, 1] when a solid has both, TRANSPARENCY alone for a plane with both
// (its R is 0), and their plain sum when one of them is 0.
double branchWeightOf(scene::ObjectKind kind, const scene::Material& m) {
  if (m.reflectivity > 0.0 && m.transparency > 0.0) {
    if (kind == scene::ObjectKind::Plane) return m.transparency;
    return std::max(m.reflectivity, m.transparency);
  }
  return m.reflectivity + m.transparency;
}

}  // namespace

RadianceBound::RadianceBound(const RenderScene& scene, int maxDepth) : maxDepth_(maxDepth) {
  glm::dvec3 lights(0.0);
  for (const RenderLight& light : scene.lights()) {
    for (int c = 0; c < 3; ++c) {
      if (!nonNegative(light.colour[c])) return;
    }
    lights += light.colour;
  }
  double surface = 0.0;
  double weight = 0.0;
  // The last shininess and its highlight: objects mostly share a few, and
  // std::pow for each of 1,000,000 objects took 20 ms of one thread.
  double shininess = std::numeric_limits<double>::quiet_NaN();
  double highlight = 0.0;
  for (std::uint32_t i = 0; i < scene.objects().size(); ++i) {
    const RenderObject& object = scene.objects()[i];
    const scene::Material& m = scene.material(i);
    if (!inRange(m)) return;
    // max(0, x)^SHININESS for x up to kUnitDotMax.
    if (!(m.shininess == shininess)) {
      shininess = m.shininess;
      highlight = std::pow(kUnitDotMax, shininess);
    }
    for (int c = 0; c < 3; ++c) {
      double term = lights[c] *
                    (m.colour[c] * (m.ambient + m.diffuse * kUnitDotMax) + m.specular * highlight);
      surface = std::max(surface, term);
    }
    weight = std::max(weight, branchWeightOf(object.kind, m));
  }
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
