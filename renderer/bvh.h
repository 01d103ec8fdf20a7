// A bounding volume hierarchy over boxes, built with the surface area
// heuristic in binned form, stored flat in depth-first order.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "renderer/bounds.h"

namespace render {

// 32 bytes: the box in float, rounded outward from the double bounds so that
// it still contains them (a ray can only meet more boxes, never fewer), which
// puts twice as many nodes in each cache line as double boxes did.
struct BvhNode {
  float lo[3] = {0.0f, 0.0f, 0.0f};
  float hi[3] = {0.0f, 0.0f, 0.0f};
  // Interior: index of the second child (the first follows this node).
  // Leaf: index of the first item in `Bvh::items`.
  std::uint32_t offset = 0;
  std::uint16_t count = 0;  // items in a leaf; 0 for an interior node
  std::uint8_t axis = 0;    // split axis of an interior node
};

class Bvh {
 public:
  static constexpr int kStackSize = 128;

  Bvh() = default;
  // Builds over the boxes; items are indices into `boxes`.
  explicit Bvh(const std::vector<Bounds>& boxes);

  bool empty() const { return nodes_.empty(); }
  const std::vector<BvhNode>& nodes() const { return nodes_; }
  const std::vector<std::uint32_t>& items() const { return items_; }

  // Calls visit(item) for every item whose leaf box the ray meets within
  // [0, tMax]; visit returns the new tMax (smaller after a hit, to prune) or
  // a negative value to stop at once (for any-hit queries).
  template <typename Visit>
  void traverse(const BoxRay& ray, double tMax, Visit&& visit) const {
    if (nodes_.empty()) return;
    bool negative[3] = {ray.inverseDirection.x < 0.0, ray.inverseDirection.y < 0.0,
                        ray.inverseDirection.z < 0.0};
    std::uint32_t stack[kStackSize];
    int top = 0;
    std::uint32_t current = 0;
    for (;;) {
      const BvhNode& node = nodes_[current];
      if (hitsNode(node, ray, tMax)) {
        if (node.count > 0) {
          for (std::uint32_t i = 0; i < node.count; ++i) {
            tMax = visit(items_[node.offset + i]);
            if (tMax < 0.0) return;
          }
        } else {
          // Visit the child on the ray's near side first.
          if (negative[node.axis]) {
            stack[top++] = current + 1;
            current = node.offset;
          } else {
            stack[top++] = node.offset;
            current = current + 1;
          }
          continue;
        }
      }
      if (top == 0) return;
      current = stack[--top];
    }
  }

 private:
  // hitsBox for a node's float box; the arithmetic is in double, where each
  // float converts exactly.
  static bool hitsNode(const BvhNode& node, const BoxRay& r, double tMax) {
    double tMin = 0.0;
    for (int i = 0; i < 3; ++i) {
      double tNear = (static_cast<double>(node.lo[i]) - r.origin[i]) * r.inverseDirection[i];
      double tFar = (static_cast<double>(node.hi[i]) - r.origin[i]) * r.inverseDirection[i];
      if (tNear > tFar) std::swap(tNear, tFar);
      tFar *= 1.0 + 2.0 * gamma(3);
      tMin = tNear > tMin ? tNear : tMin;
      tMax = tFar < tMax ? tFar : tMax;
      if (tMin > tMax) return false;
    }
    return true;
  }

  std::uint32_t build(const std::vector<Bounds>& boxes, std::vector<glm::dvec3>& centres,
                      std::uint32_t begin, std::uint32_t end, int depth);

  std::vector<BvhNode> nodes_;
  std::vector<std::uint32_t> items_;
};

}  // namespace render
