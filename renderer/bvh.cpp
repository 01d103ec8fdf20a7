#include "renderer/bvh.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <system_error>
#include <thread>
#include <vector>

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

}  // namespace

std::uint64_t Bvh::bytesFor(std::uint64_t boxes) {
  // The vectors of the constructor below, each sized or reserved once. With
  // more than one thread the build also holds its list of subtrees, with the
  // order it builds them in and closeGaps's two lists (at most
  // kMaxSubtrees each) and its threads (at most kMaxBuildThreads), and only
  // for kMinParallelBoxes boxes or more, so a share of a few bytes a box
  // covers them.
  constexpr std::uint64_t kSubtreeBytes = sizeof(Subtree) + 3 * sizeof(std::uint32_t);
  constexpr std::uint64_t kParallelBytes =
      kMaxSubtrees * kSubtreeBytes + kMaxBuildThreads * sizeof(std::thread);
  constexpr std::uint64_t kSubtreeShare =
      (kParallelBytes + kMinParallelBoxes - 1) / kMinParallelBoxes;
  std::uint64_t perBox =
      kNodesPerBox * sizeof(BvhNode) + sizeof(std::uint32_t) + sizeof(glm::dvec3) + kSubtreeShare;
  return saturatingProduct(boxes, perBox);
}

Bvh::Bvh(const std::vector<Bounds>& boxes, int threads) {
  if (boxes.empty()) return;
  if (threads <= 0) threads = static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, kMaxBuildThreads);
  const std::uint32_t n = static_cast<std::uint32_t>(boxes.size());
  if (n < kMinParallelBoxes) threads = 1;
  items_.resize(n);
  std::vector<glm::dvec3> centres(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    items_[i] = i;
    centres[i] = boxes[i].centre();
  }
  nodes_.reserve(kNodesPerBox * n);
  nodes_.resize(2 * static_cast<std::size_t>(n) - 1);
  BuildInput in{boxes, centres, items_.data(), nodes_.data()};
  if (threads == 1) {
    nodes_.resize(buildSubtree(in, 0, 0, n, 0));
    return;
  }
  // The top of the tree is split here until its parts are small enough to
  // share out; every part is then built as the one-thread build above would
  // have built it, at the place it would have had, so the tree does not
  // depend on the thread count.
  std::uint32_t largest = std::max<std::uint32_t>(n / (kTasksPerThread * threads), 1);
  std::vector<Subtree> subtrees;
  subtrees.reserve(kMaxSubtrees);
  std::uint32_t reserved = planTop(in, largest, subtrees, 0, 0, n, 0);
  buildSubtrees(in, subtrees, threads);
  nodes_.resize(closeGaps(nodes_, subtrees, reserved));
}

}  // namespace render
