#include "renderer/camera.h"

#include <cmath>
#include <numbers>

#include "renderer/sample_sequence.h"
#include "scenefile/matrix.h"

namespace render {

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
  glm::dvec2 offset = PixelSampleSequence(i, j, seed)[static_cast<std::uint32_t>(index)];
  return {i + offset.x, j + offset.y};
}

}  // namespace render
