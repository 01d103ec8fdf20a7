// What a BVH build moves and writes: its items and its nodes' writes,
// shared by the build (bvh.cpp) and its Morton top (bvh_morton.h).
#pragma once

#include <cstdint>

#include "renderer/bounds.h"
#include "renderer/bvh_node.h"

namespace render::bvh_build {

// An item as the build moves it: its box beside its index, so that each
// pass over a node's items reads memory in order. With the indices alone,
// every pass gathered boxes from all over the list, and at 1,000,000 boxes
// the cache misses of the top levels made most of the build's time. The box
// is in float, rounded outward as the nodes' are (every node's box, a union
// of its items', comes out the same): 32 bytes, not 56.
struct BuildItem {
  float planes[6];
  std::uint32_t index;
  // The item's bin in its node's split, set by the binning pass for the
  // partition after it, which would work it out again (and before that,
  // under a Morton top, its Morton code).
  std::uint32_t bin;
  Bounds box() const {
    return Bounds{glm::dvec3(planes[0], planes[1], planes[2]),
                  glm::dvec3(planes[3], planes[4], planes[5])};
  }
  // Bounds::centre's value of box(), bit for bit, but 0 where that is NaN
  // (a box from -infinity to infinity, of planes past the float range),
  // so that the centres order.
  double centre(int axis) const {
    double c = 0.5 * (static_cast<double>(planes[axis]) + static_cast<double>(planes[3 + axis]));
    return c == c ? c : 0.0;
  }
  glm::dvec3 centre() const { return glm::dvec3(centre(0), centre(1), centre(2)); }
};

// A node's box: its bounds rounded outward to floats. The first write of
// every node, which clears it whole (the node's room was never written, or
// held a Morton top's sort).
inline void writeBox(BvhNode& node, const Bounds& bounds) {
  node = BvhNode{};
  floatPlanesAround(bounds, node.planes);
}

inline void writeLeaf(BvhNode& node, std::uint32_t begin, std::uint32_t count,
                      const Bounds& bounds) {
  writeBox(node, bounds);
  node.offset = begin;
  node.count = static_cast<std::uint16_t>(count);
  node.axis = 0;
}

}  // namespace render::bvh_build
