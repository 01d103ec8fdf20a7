#include "renderer/anchor_blocks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace render {

namespace {

// A box's projection is widened by this many pixels on each side: the
// anchors' samples lie at the corners, and a pixel's worth covers the
// rounding of the projection many times over.
constexpr double kMarginPixels = 1.0;
// Box corners nearer the eye plane than this (relative to their distance)
// make the box reach the whole image: its projection is unbounded there.
constexpr double kNearEyePlane = 1e-9;

}  // namespace

namespace {
int blocksAcross(int pixels, int span) {
  return std::max(1, (pixels + span - 1) / span);
}
}  // namespace

std::uint64_t AnchorBlocks::bytesFor(int fullWidth, int fullHeight, int span) {
  span = std::max(2, span);
  return static_cast<std::uint64_t>(blocksAcross(fullWidth, span)) *
         static_cast<std::uint64_t>(blocksAcross(fullHeight, span)) * sizeof(Block);
}

AnchorBlocks::AnchorBlocks(const RenderScene& scene, const PinholeCamera& camera, int fullWidth,
                           int fullHeight, int span)
    : span_(std::max(2, span)),
      columns_(blocksAcross(fullWidth, span_)),
      rows_(blocksAcross(fullHeight, span_)) {
  blocks_.resize(static_cast<std::size_t>(columns_) * rows_);
  const glm::dvec3& eye = camera.eye();
  const double width = fullWidth, height = fullHeight;
  ObjectRange bounded = scene.boundedObjects();
  for (std::size_t k = 0; k < bounded.size(); ++k) {
    std::uint32_t object = bounded[k];
    std::optional<Bounds> box = worldBounds(scene.objects()[object]);
    if (!box) continue;
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    bool whole = false;
    for (int c = 0; c < 8; ++c) {
      glm::dvec3 p((c & 1) ? box->hi.x : box->lo.x, (c & 2) ? box->hi.y : box->lo.y,
                   (c & 4) ? box->hi.z : box->lo.z);
      glm::dvec3 d = p - eye;
      double f = glm::dot(d, camera.forward());
      // Not a number fails the test too.
      if (!(f > kNearEyePlane * glm::length(d))) {
        whole = true;
        break;
      }
      // PinholeCamera::directionThrough, inverted.
      double x = (glm::dot(d, camera.right()) / (f * camera.tanHalfWidth()) + 1.0) * 0.5 * width;
      double y = (1.0 - glm::dot(d, camera.up()) / (f * camera.tanHalfHeight())) * 0.5 * height;
      x0 = std::min(x0, x);
      x1 = std::max(x1, x);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
    if (!whole && !(x0 - kMarginPixels <= width && x1 + kMarginPixels >= 0.0 &&
                    y0 - kMarginPixels <= height && y1 + kMarginPixels >= 0.0)) {
      continue;  // outside the image (or not a number)
    }
    // Block i holds the corners from span * i to span * (i + 1).
    const double perPixel = 1.0 / span_;
    auto first = [&](double v, int count) {
      return whole ? 0 : std::clamp(static_cast<int>(std::floor(v * perPixel)) - 1, 0, count - 1);
    };
    auto last = [&](double v, int count) {
      return whole ? count - 1
                   : std::clamp(static_cast<int>(std::floor(v * perPixel)), 0, count - 1);
    };
    mark(first(std::max(x0 - kMarginPixels, -4.0), columns_),
         last(std::min(x1 + kMarginPixels, width + 4.0), columns_),
         first(std::max(y0 - kMarginPixels, -4.0), rows_),
         last(std::min(y1 + kMarginPixels, height + 4.0), rows_), object);
  }
}

void AnchorBlocks::mark(int i0, int i1, int j0, int j1, std::uint32_t object) {
  for (int j = j0; j <= j1; ++j) {
    Block* row = &blocks_[static_cast<std::size_t>(j) * columns_];
    for (int i = i0; i <= i1; ++i) {
      Block& block = row[i];
      block.count = std::min<std::uint32_t>(block.count + 1, 2);
      block.object = std::min(block.object, object);
    }
  }
}

}  // namespace render
