// The top of a large BVH from the Morton order of its items' centres: one
// sort, then each split where a range's codes first differ, in place of the
// top levels of the surface area heuristic's splits, each a pass over every
// item (bvh.cpp builds the ranges left below it as before).
#pragma once

#include <cstdint>
#include <exception>
#include <vector>

#include "renderer/bvh_build_item.h"

namespace render::bvh_build {

// Orders the n `items` by the Morton code of their centres, 10 bits an
// axis, the cells cubes a 1,024th of the widest extent of `centres` (the box
// of all their centres), items of one code in the order they had: the same
// order on any number of threads. `scratch` is room for n items, written
// and left as it falls. Leaves each item's `bin` set to its code.
void sortByMortonCode(BuildItem* items, std::uint32_t n, const Bounds& centres, int threads,
                      BuildItem* scratch);
// What the sort holds a thread beside its lists: a part's places of 256
// digits, and runParts' slot for its exception.
inline constexpr std::size_t kSortBytesPerThread =
    256 * sizeof(std::uint32_t) + sizeof(std::exception_ptr);

// A range of items the top leaves to the build below it, whose node is at
// `at`, at `depth`.
struct MortonRange {
  std::uint32_t at = 0;
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  int depth = 0;
};

// The top of the tree over the n items of `sorted` (sortByMortonCode's
// order): a range of more than `most` items is split where its first and
// last codes' highest differing bit changes, unless a side would hold
// fewer than `least` (or every code is the same). Each split's node is written at its place, as
// the build lays out a tree whose subtrees each take all the room
// mostBvhNodes(count, minLeafItems) gives them (the first child next, the
// second past the first's room), with its axis, its second child, and no
// box. Returns the ranges left, in order; `splits` gets the places of the
// split nodes, each before its children's.
std::vector<MortonRange> mortonTop(const BuildItem* sorted, std::uint32_t n, std::uint32_t most,
                                   std::uint32_t least, std::uint32_t minLeafItems, BvhNode* nodes,
                                   std::vector<std::uint32_t>& splits);

// The split nodes' boxes, the unions of their children's, from the last
// split to the first (every child's box written before its parent's).
void boxSplits(const std::vector<std::uint32_t>& splits, BvhNode* nodes);

}  // namespace render::bvh_build
