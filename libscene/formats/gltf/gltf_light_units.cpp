#include "libscene/formats/gltf/gltf_light_units.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "scenefile/srgb.h"

namespace scene::gltf {

namespace {

// srgbToLinear(a) / srgbToLinear(b) for 0 <= a <= b, b > 0, also where
// srgbToLinear(b) underflows or overflows (a light colour of 1e300): the ratio of the
// curve's bases, raised to its power, never does.
double linearRatio(double a, double b) {
  // On the straight segment the ratio is a / b, also where a / 12.92
  // underflows.
  if (b <= kSrgbDisplayKnee) return std::clamp(a / b, 0.0, 1.0);
  double lb = srgbToLinear(b);
  if (std::isfinite(lb)) return std::clamp(srgbToLinear(a) / lb, 0.0, 1.0);
  if (a <= kSrgbDisplayKnee) return 0.0;
  return std::clamp(std::pow((a + 0.055) / (b + 0.055), 2.4), 0.0, 1.0);
}

}  // namespace

glm::dvec3 illuminanceFromColour(const glm::dvec3& colour) {
  glm::dvec3 lux;
  for (int c = 0; c < 3; ++c) {
    lux[c] = srgbToLinear(kReferenceSurface * colour[c]) / kReferenceSurface * kLuxPerUnit;
  }
  return lux;
}

glm::dvec3 colourFromIlluminance(const glm::dvec3& lux) {
  glm::dvec3 colour;
  for (int c = 0; c < 3; ++c) {
    colour[c] = linearToSrgb(lux[c] / kLuxPerUnit * kReferenceSurface) / kReferenceSurface;
  }
  return colour;
}

PointLight pointLightFromColour(const glm::dvec3& colour, double distance) {
  double peak = std::max({colour.x, colour.y, colour.z});
  if (!(peak > 0.0)) return {glm::dvec3(1.0), 0.0};
  PointLight light;
  for (int c = 0; c < 3; ++c) {
    light.color[c] =
        linearRatio(kReferenceSurface * std::max(colour[c], 0.0), kReferenceSurface * peak);
  }
  double lux = srgbToLinear(kReferenceSurface * peak) / kReferenceSurface * kLuxPerUnit;
  light.intensity = lux * distance * distance;
  return withinFloats(light);
}

PointLight withinFloats(PointLight light) {
  // Readers hold the intensity as a float: one beyond (or a positive one
  // below) the floats would become infinite (or black) there.
  if (!(light.intensity <= kLargestIntensity)) {
    light.intensity = kLargestIntensity;
    light.clamped = true;
  } else if (light.intensity > 0.0 && light.intensity < kSmallestIntensity) {
    light.intensity = kSmallestIntensity;
    light.clamped = true;
  }
  return light;
}

glm::dvec3 colourFromPointLight(const PointLight& light, double distance) {
  // Divided by the distance twice, not by its square, which underflows
  // sooner.
  return colourFromIlluminance(light.color * light.intensity / distance / distance);
}

glm::dvec3 colourFromDirectionalLight(const PointLight& light) {
  return colourFromIlluminance(light.color * light.intensity);
}

PointLight unscaledPointLightFromColour(const glm::dvec3& colour) {
  double peak = std::max({colour.x, colour.y, colour.z});
  if (!(peak > 0.0)) return {glm::dvec3(1.0), 0.0};
  PointLight light;
  light.intensity = peak;
  light.color = glm::clamp(colour / peak, 0.0, 1.0);
  return light;
}

}  // namespace scene::gltf
