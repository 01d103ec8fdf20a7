#include "renderer/adaptive_sampling.h"

#include <algorithm>
#include <glm/common.hpp>

#include "renderer/saturating.h"

namespace render {

SampleLook lookOf(const glm::dvec3& colour, std::uint32_t object) {
  SampleLook look;
  for (int c = 0; c < 3; ++c) {
    // NaN, which the image stores as 0, compares as 0 here too.
    double v = colour[c] == colour[c] ? colour[c] : 0.0;
    look.colour[c] = static_cast<float>(std::clamp(v, 0.0, 1.0));
  }
  look.object = object;
  return look;
}

bool looksDiffer(const SampleLook& a, const SampleLook& b, double threshold) {
  if (a.object != b.object) return true;
  for (int c = 0; c < 3; ++c) {
    if (std::abs(static_cast<double>(a.colour[c]) - b.colour[c]) > threshold) return true;
  }
  return false;
}

void SampleSpread::add(const SampleLook& look) {
  if (empty_) {
    low_ = high_ = look.colour;
    object_ = look.object;
    empty_ = false;
    return;
  }
  low_ = glm::min(low_, look.colour);
  high_ = glm::max(high_, look.colour);
  mixedObjects_ = mixedObjects_ || look.object != object_;
}

bool SampleSpread::exceeds(double threshold) const {
  if (mixedObjects_) return true;
  for (int c = 0; c < 3; ++c) {
    if (static_cast<double>(high_[c]) - low_[c] > threshold) return true;
  }
  return false;
}

std::vector<int> refinementLevels(int samplesPerPixel, int firstLevel) {
  if (samplesPerPixel <= 1) return {};
  if (firstLevel > 1 && firstLevel < samplesPerPixel) return {firstLevel, samplesPerPixel};
  return {samplesPerPixel};
}

std::uint64_t adaptiveSamplingBytes(int width, int height) {
  auto withApron = [](int side) { return static_cast<std::uint64_t>(side > 0 ? side + 2 : 0); };
  return saturatingProduct(saturatingProduct(withApron(width), withApron(height)),
                           sizeof(SampleLook));
}

}  // namespace render
