// A BVH's node and the block that holds a tree's nodes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>

namespace render {

// 32 bytes: the box in float, rounded outward from the double bounds so that
// it still contains them (a ray can only meet more boxes, never fewer), which
// puts twice as many nodes in each cache line as double boxes did.
struct BvhNode {
  // The low corner (x, y, z), then the high one: one array, so that a ray
  // picks the planes it meets first and last on each axis by an index
  // worked out once from its direction's signs (Bvh::NodeRay).
  float planes[6] = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  // Interior: index of the second child (the first follows this node).
  // Leaf: its first item (its items are numbered in a row).
  std::uint32_t offset = 0;
  std::uint16_t count = 0;  // items in a leaf; 0 for an interior node
  std::uint8_t axis = 0;    // split axis of an interior node
  // Zero: every byte of a node is a member's, so a node written whole
  // leaves none unset (BvhNodes' room is never cleared).
  std::uint8_t unused = 0;
};
static_assert(sizeof(BvhNode) == 32);

// The nodes of a Bvh, in one block from malloc, so that a build can reserve
// room for the most nodes a tree can have, write only those it makes (a
// page never written is never memory) and give back the rest with
// realloc, which moves no node where the block was mapped on its own.
class BvhNodes {
 public:
  BvhNodes() = default;
  /// Room for `room` nodes, none written.
  explicit BvhNodes(std::size_t room);
  BvhNodes(const BvhNodes& other);
  BvhNodes(BvhNodes&& other) noexcept { *this = std::move(other); }
  BvhNodes& operator=(const BvhNodes& other);
  BvhNodes& operator=(BvhNodes&& other) noexcept;
  ~BvhNodes();

  /// Keeps the first `size` nodes (all written), giving back the rest.
  void shrink(std::size_t size);
  BvhNode* data() { return data_; }
  std::span<const BvhNode> span() const { return {data_, size_}; }

 private:
  BvhNode* data_ = nullptr;
  std::size_t size_ = 0;
};

// Room for the nodes of a tree over `boxes` boxes whose leaves (but a lone
// box's) hold at least `minLeafItems` (1 or 2): 2n - 1 or n - 1
// (Bvh::mostNodes).
constexpr std::uint64_t mostBvhNodes(std::uint64_t boxes, std::uint32_t minLeafItems) {
  return boxes > 1 ? boxes * (2 / minLeafItems) - 1 : boxes;
}

}  // namespace render
