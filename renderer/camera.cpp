#include "renderer/camera.h"

#include <cmath>
#include <numbers>

#include "scenefile/matrix.h"

namespace render {

namespace {

// SplitMix64: a counter-based generator, so each pixel's samples depend on
// the seed and the pixel alone.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

double unitInterval(std::uint64_t bits) {
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

}  // namespace

PinholeCamera::PinholeCamera(const scene::Camera& camera, const RenderSettings& settings)
    : width_(settings.width), height_(settings.height) {
  eye_ = glm::dvec3(camera.matrix[3]);
  // Axes of any finite length are valid (1e-300, 1e300): unitDirection is
  // glm::normalize where that neither underflows nor overflows.
  forward_ = scene::unitDirection(-glm::dvec3(camera.matrix[2]));
  glm::dvec3 up(camera.matrix[1]);
  if (!scene::isModerate(up)) up = scene::unitDirection(up);
  up_ = scene::unitDirection(up - glm::dot(up, forward_) * forward_);
  right_ = glm::cross(forward_, up_);
  tanHalfHeight_ = std::tan(settings.verticalFovDegrees * std::numbers::pi / 360.0);
  tanHalfWidth_ = tanHalfHeight_ * width_ / height_;
}

GridWindow PinholeCamera::imageWindow(int columns, int rows) const {
  GridWindow window;
  window.forward = forward_;
  window.uAxis = right_;
  window.vAxis = up_;
  window.uLow = -tanHalfWidth_;
  window.uHigh = tanHalfWidth_;
  window.vLow = -tanHalfHeight_;
  window.vHigh = tanHalfHeight_;
  window.columns = columns;
  window.rows = rows;
  return window;
}

glm::dvec2 samplePosition(int i, int j, int index, int count, std::uint64_t seed) {
  if (count <= 1) return {i + 0.5, j + 0.5};
  int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  int rows = (count + columns - 1) / columns;
  std::uint64_t state =
      mix(seed ^ mix((static_cast<std::uint64_t>(j) << 32) ^ static_cast<std::uint32_t>(i)) ^
          mix(static_cast<std::uint64_t>(index) + 0x5851F42D4C957F2Dull));
  double u = unitInterval(mix(state));
  double v = unitInterval(mix(state + 1));
  return {i + ((index % columns) + u) / columns, j + ((index / columns) + v) / rows};
}

}  // namespace render
