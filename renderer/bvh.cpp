#include "renderer/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "renderer/saturating.h"

namespace render {

namespace {

constexpr int kBins = 16;
// One object a leaf: a leaf's box then bounds its object alone, so the box
// test, in two lanes of SSE2 with its sibling, culls before the exact object
// test (several times its cost) runs; leaves of up to 4 objects made 8% more
// instructions on floor-1000 (docs/PERFORMANCE.md, "Where the time goes").
constexpr std::uint32_t kMaxLeafItems = 1;
// Past this depth only balanced median splits are made, which keeps the
// tree within the traversal stack (Bvh::kStackSize) for any item count.
constexpr int kMaxDepth = 64;

// The nearest floats at or beyond a double, outward.
float roundDown(double v) {
  float f = static_cast<float>(v);
  return static_cast<double>(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                    : f;
}
float roundUp(double v) {
  float f = static_cast<float>(v);
  return static_cast<double>(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace

std::uint64_t Bvh::bytesFor(std::uint64_t boxes) {
  // The vectors of the constructor below, each sized or reserved once.
  std::uint64_t perBox =
      kNodesPerBox * sizeof(BvhNode) + sizeof(std::uint32_t) + sizeof(glm::dvec3);
  return saturatingProduct(boxes, perBox);
}

Bvh::Bvh(const std::vector<Bounds>& boxes) {
  if (boxes.empty()) return;
  items_.resize(boxes.size());
  std::vector<glm::dvec3> centres(boxes.size());
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    items_[i] = i;
    centres[i] = boxes[i].centre();
  }
  nodes_.reserve(kNodesPerBox * boxes.size());
  build(boxes, centres, 0, static_cast<std::uint32_t>(boxes.size()), 0);
}

std::uint32_t Bvh::build(const std::vector<Bounds>& boxes, std::vector<glm::dvec3>& centres,
                         std::uint32_t begin, std::uint32_t end, int depth) {
  std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Bounds bounds;
  Bounds centreBounds;
  for (std::uint32_t i = begin; i < end; ++i) {
    bounds.extend(boxes[items_[i]]);
    centreBounds.extend(centres[items_[i]]);
  }
  for (int i = 0; i < 3; ++i) {
    nodes_[index].planes[i] = roundDown(bounds.lo[i]);
    nodes_[index].planes[3 + i] = roundUp(bounds.hi[i]);
  }
  std::uint32_t count = end - begin;

  auto makeLeaf = [&] {
    nodes_[index].offset = begin;
    nodes_[index].count = static_cast<std::uint16_t>(count);
    return index;
  };
  if (count <= kMaxLeafItems || depth >= kMaxDepth) {
    if (count <= 0xFFFF) return makeLeaf();
  }

  // Step 1: the widest axis of the centres; all centres equal means no split
  // can help, so halve the list.
  glm::dvec3 extent = centreBounds.hi - centreBounds.lo;
  int axis = extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
  std::uint32_t mid = begin + count / 2;
  bool median = true;
  if (extent[axis] > 0.0 && depth < kMaxDepth) {
    // Step 2: bin the centres and price every split between bins by the
    // surface area heuristic.
    std::array<Bounds, kBins> binBounds;
    std::array<std::uint32_t, kBins> binCounts{};
    double scale = kBins / extent[axis];
    auto binOf = [&](std::uint32_t item) {
      int b = static_cast<int>((centres[item][axis] - centreBounds.lo[axis]) * scale);
      return std::clamp(b, 0, kBins - 1);
    };
    for (std::uint32_t i = begin; i < end; ++i) {
      int b = binOf(items_[i]);
      ++binCounts[b];
      binBounds[b].extend(boxes[items_[i]]);
    }
    std::array<double, kBins - 1> cost{};
    Bounds left;
    std::uint32_t leftCount = 0;
    for (int b = 0; b < kBins - 1; ++b) {
      left.extend(binBounds[b]);
      leftCount += binCounts[b];
      cost[b] = leftCount ? leftCount * left.surfaceArea() : 0.0;
    }
    Bounds right;
    std::uint32_t rightCount = 0;
    for (int b = kBins - 1; b > 0; --b) {
      right.extend(binBounds[b]);
      rightCount += binCounts[b];
      cost[b - 1] += rightCount ? rightCount * right.surfaceArea() : 0.0;
    }
    int best = static_cast<int>(std::min_element(cost.begin(), cost.end()) - cost.begin());
    std::uint32_t* split = std::partition(items_.data() + begin, items_.data() + end,
                                          [&](std::uint32_t item) { return binOf(item) <= best; });
    std::uint32_t at = static_cast<std::uint32_t>(split - items_.data());
    if (at != begin && at != end) {
      mid = at;
      median = false;
    }
  }
  if (median) {
    std::nth_element(
        items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
        [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
  }
  nodes_[index].axis = static_cast<std::uint8_t>(axis);
  build(boxes, centres, begin, mid, depth + 1);
  nodes_[index].offset = build(boxes, centres, mid, end, depth + 1);
  nodes_[index].count = 0;
  return index;
}

}  // namespace render
