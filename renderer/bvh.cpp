#include "renderer/bvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <new>
#include <numeric>
#include <optional>
#include <thread>
#include <vector>

#include "renderer/bvh_build_item.h"
#include "renderer/bvh_morton.h"
#include "renderer/huge_pages.h"
#include "renderer/parallel_parts.h"
#include "renderer/saturating.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace render {

namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafItems = Bvh::kMaxLeafItems;
// Past this depth only balanced median splits are made, which keeps the
// tree within the traversal stack (Bvh::kStackSize) for any item count.
constexpr int kMaxDepth = 64;

using bvh_build::BuildItem;
using bvh_build::writeBox;
using bvh_build::writeLeaf;

// What a node's split works with: the items and the nodes being written,
// shared by every thread of a build (each writes only its own range of
// items and of nodes), the price of a node (Bvh::nodeCostFor) and the
// fewest items a leaf holds (Bvh::minLeafItemsFor).
struct BuildInput {
  BuildItem* items;
  BvhNode* nodes;
  double nodeCost;
  std::uint32_t minLeafItems;
  // The nodes a range of `count` items may take (Bvh::mostNodes).
  std::uint32_t mostNodes(std::uint32_t count) const {
    return static_cast<std::uint32_t>(Bvh::mostNodes(count, minLeafItems));
  }
};

// A node's box and the box of its items' centres: what its split needs
// before it reads an item. The split works out its children's from its bins
// (the union of the bins each side takes), so each level of the build
// passes over its items twice (bin, partition) rather than three times.
struct NodeExtent {
  Bounds bounds;
  Bounds centres;
  void extend(const BuildItem& item) {
    bounds.extend(item.box());
    centres.extend(item.centre());
  }
  void extend(const NodeExtent& other) {
    bounds.extend(other.bounds);
    centres.extend(other.centres);
  }
};

NodeExtent extentOf(const BuildItem* items, std::uint32_t begin, std::uint32_t end) {
  NodeExtent extent;
  for (std::uint32_t i = begin; i < end; ++i) extent.extend(items[i]);
  return extent;
}

// Which of kBins bins along `axis` a centre falls in.
struct BinRule {
  int axis;
  double lo;
  double scale;
  int operator()(const glm::dvec3& centre) const {
    return std::clamp(static_cast<int>((centre[axis] - lo) * scale), 0, kBins - 1);
  }
};

// Bins of a split, in the order of their numbers: each one's number, the
// extent of its items and their count. Bins that no item falls in may be
// left out: they change no cost (see cheapestSplit).
struct Bins {
  int size = 0;
  std::array<int, kBins> number;
  std::array<NodeExtent, kBins> extent;
  std::array<std::uint32_t, kBins> count;
};

// One bin's extent as manyItemsBins gathers it: with SSE2 the box's planes
// stay floats (their minimum and maximum are those of the planes as
// doubles, which they convert to exactly) and the centre's three doubles
// go through two at a time, each compare keeping the bin's value on a tie
// as Bounds::extend does (the first operand of MINPS and MAXPS is taken
// only where it is strictly past the second), so the extent is the same,
// bit for bit. With the doubles one at a time the build took about a ninth
// more user time at floor-1000000 and floor-10000000.
#if defined(__SSE2__)
struct BinExtent {
  __m128 lo;
  // Lanes 1 to 3: the high planes (lane 0 the low z plane, left unused).
  __m128 hi;
  __m128d centreLoXY, centreHiXY, centreLoZ, centreHiZ;

  // No item's: set up only where a bin is used (most splits use few).
  void clear() {
    lo = _mm_set1_ps(std::numeric_limits<float>::infinity());
    hi = _mm_set1_ps(-std::numeric_limits<float>::infinity());
    centreLoXY = centreLoZ = _mm_set1_pd(std::numeric_limits<double>::infinity());
    centreHiXY = centreHiZ = _mm_set1_pd(-std::numeric_limits<double>::infinity());
  }
  // An item's centre, BuildItem::centre's: x and y in `xy`, z in the low
  // lane of `z`; returns the one along `axis`, for its bin.
  static double centreAlong(const BuildItem& item, int axis, __m128d& xy, __m128d& z) {
    const float* p = item.planes;
    const __m128d half = _mm_set1_pd(0.5);
    __m128 lo = _mm_loadu_ps(p);
    // The high x and y planes as one 8-byte load, copied: they lie on a
    // float's alignment, not a double's.
    double highXY;
    std::memcpy(&highXY, p + 3, sizeof highXY);
    __m128 hiXY = _mm_castpd_ps(_mm_set_sd(highXY));
    xy = _mm_mul_pd(_mm_add_pd(_mm_cvtps_pd(lo), _mm_cvtps_pd(hiXY)), half);
    z = _mm_mul_sd(_mm_add_sd(_mm_cvtss_sd(_mm_setzero_pd(), _mm_movehl_ps(lo, lo)),
                              _mm_cvtss_sd(_mm_setzero_pd(), _mm_load_ss(p + 5))),
                   half);
    // NaN (a box from -infinity to infinity) to 0.
    xy = _mm_and_pd(xy, _mm_cmpeq_pd(xy, xy));
    z = _mm_and_pd(z, _mm_cmpeq_pd(z, z));
    alignas(16) double c[4];
    _mm_store_pd(c, xy);
    _mm_store_pd(c + 2, z);
    return c[axis];
  }
  void add(const BuildItem& item, __m128d xy, __m128d z) {
    lo = _mm_min_ps(_mm_loadu_ps(item.planes), lo);
    hi = _mm_max_ps(_mm_loadu_ps(item.planes + 2), hi);
    centreLoXY = _mm_min_pd(xy, centreLoXY);
    centreHiXY = _mm_max_pd(xy, centreHiXY);
    centreLoZ = _mm_min_sd(z, centreLoZ);
    centreHiZ = _mm_max_sd(z, centreHiZ);
  }
  NodeExtent extent() const {
    alignas(16) float l[4], h[4];
    alignas(16) double cl[2], ch[2];
    _mm_store_ps(l, lo);
    _mm_store_ps(h, hi);
    NodeExtent e;
    e.bounds = Bounds{glm::dvec3(l[0], l[1], l[2]), glm::dvec3(h[1], h[2], h[3])};
    _mm_store_pd(cl, centreLoXY);
    _mm_store_pd(ch, centreHiXY);
    e.centres.lo = glm::dvec3(cl[0], cl[1], _mm_cvtsd_f64(centreLoZ));
    e.centres.hi = glm::dvec3(ch[0], ch[1], _mm_cvtsd_f64(centreHiZ));
    return e;
  }
};
#endif

// All kBins bins, filled in one pass over the items, each item's bin kept
// in it for the partition.
Bins manyItemsBins(BuildItem* items, std::uint32_t begin, std::uint32_t end, const BinRule& rule) {
  Bins bins;
  bins.size = kBins;
  for (int b = 0; b < kBins; ++b) bins.number[b] = b;
  bins.count.fill(0);
#if defined(__SSE2__)
  std::array<BinExtent, kBins> extent;
  for (BinExtent& e : extent) e.clear();
  for (std::uint32_t i = begin; i < end; ++i) {
    __m128d xy, z;
    double c = BinExtent::centreAlong(items[i], rule.axis, xy, z);
    int b = std::clamp(static_cast<int>((c - rule.lo) * rule.scale), 0, kBins - 1);
    items[i].bin = static_cast<std::uint32_t>(b);
    ++bins.count[b];
    extent[b].add(items[i], xy, z);
  }
  for (int b = 0; b < kBins; ++b) bins.extent[b] = extent[b].extent();
#else
  bins.extent.fill(NodeExtent{});
  for (std::uint32_t i = begin; i < end; ++i) {
    glm::dvec3 centre = items[i].centre();
    int b = rule(centre);
    items[i].bin = static_cast<std::uint32_t>(b);
    ++bins.count[b];
    bins.extent[b].bounds.extend(items[i].box());
    bins.extent[b].centres.extend(centre);
  }
#endif
  return bins;
}

// From this many items, a split at the top of the tree that has threads to
// itself (the root's) bins its items on them, each a share, into bins of
// its own that it then merges: the same bins, since a bin's box is a union
// and its count a sum.
constexpr std::uint32_t kMinItemsBinnedInParts = std::uint32_t{1} << 18;

Bins manyItemsBinsInParts(BuildItem* items, std::uint32_t begin, std::uint32_t end,
                          const BinRule& rule, int threads) {
  const std::uint32_t count = end - begin;
  if (threads < 2 || count < kMinItemsBinnedInParts) {
    return manyItemsBins(items, begin, end, rule);
  }
  const std::size_t parts = static_cast<std::size_t>(threads);
  std::vector<Bins> shares(parts);
  runParts(parts, threads, [&](std::size_t k) {
    shares[k] = manyItemsBins(items, static_cast<std::uint32_t>(begin + count * k / parts),
                              static_cast<std::uint32_t>(begin + count * (k + 1) / parts), rule);
  });
  Bins bins = shares[0];
  for (std::size_t k = 1; k < parts; ++k) {
    for (int b = 0; b < kBins; ++b) {
      bins.extent[b].extend(shares[k].extent[b]);
      bins.count[b] += shares[k].count[b];
    }
  }
  return bins;
}

// From this many items a split partitions them in blocks of
// kPartitionBlock, side by side on the threads it has, then swaps the items
// left on the wrong side, also side by side. The blocks' bounds do not
// depend on the threads, so neither does the order the items are left in,
// nor the tree.
constexpr std::uint32_t kPartitionBlock = std::uint32_t{1} << 16;
constexpr std::uint32_t kMinItemsPartitionedInBlocks = std::uint32_t{1} << 18;

// A stretch of items on the wrong side of a split, one block's.
struct Stretch {
  std::uint32_t at;
  std::uint32_t length;
};

// What partitionInBlocks holds a block: its left count, its two stretches
// and its swaps (at most two a block), and runParts' exception slots.
constexpr std::uint64_t kPartitionBytesPerBlock = sizeof(std::uint32_t) + 2 * sizeof(Stretch) +
                                                  2 * 2 * sizeof(Stretch) +
                                                  2 * sizeof(std::exception_ptr);

// Items [begin, end) with those of bins up to `last` first, on `threads`
// threads; returns where the others begin.
std::uint32_t partitionInBlocks(BuildItem* items, std::uint32_t begin, std::uint32_t end,
                                std::uint32_t last, int threads) {
  auto isLeft = [last](const BuildItem& item) { return item.bin <= last; };
  const std::uint32_t blocks = (end - begin + kPartitionBlock - 1) / kPartitionBlock;
  auto blockBegin = [&](std::uint32_t b) { return begin + b * kPartitionBlock; };
  auto blockEnd = [&](std::uint32_t b) { return std::min(end, blockBegin(b) + kPartitionBlock); };
  std::vector<std::uint32_t> lefts(blocks);
  runParts(blocks, threads, [&](std::size_t b) {
    BuildItem* first = items + blockBegin(static_cast<std::uint32_t>(b));
    lefts[b] = static_cast<std::uint32_t>(
        std::partition(first, items + blockEnd(static_cast<std::uint32_t>(b)), isLeft) - first);
  });
  const std::uint32_t mid = begin + std::accumulate(lefts.begin(), lefts.end(), std::uint32_t{0});
  // The items of the right before `mid` and those of the left after it, in
  // place order: the k-th of one list swaps with the k-th of the other.
  std::vector<Stretch> misplacedRight, misplacedLeft;
  for (std::uint32_t b = 0; b < blocks; ++b) {
    const std::uint32_t split = blockBegin(b) + lefts[b];
    if (split < mid) misplacedRight.push_back({split, std::min(blockEnd(b), mid) - split});
    const std::uint32_t from = std::max(blockBegin(b), mid);
    if (from < split) misplacedLeft.push_back({from, split - from});
  }
  // Each swap a pair of stretches of one length, cut where either list's
  // stretch ends.
  std::vector<std::array<Stretch, 2>> swaps;
  std::size_t r = 0, l = 0;
  std::uint32_t doneR = 0, doneL = 0;
  while (r < misplacedRight.size() && l < misplacedLeft.size()) {
    const std::uint32_t length =
        std::min(misplacedRight[r].length - doneR, misplacedLeft[l].length - doneL);
    swaps.push_back({Stretch{misplacedRight[r].at + doneR, length},
                     Stretch{misplacedLeft[l].at + doneL, length}});
    doneR += length;
    doneL += length;
    if (doneR == misplacedRight[r].length) ++r, doneR = 0;
    if (doneL == misplacedLeft[l].length) ++l, doneL = 0;
  }
  runParts(swaps.size(), threads, [&](std::size_t k) {
    BuildItem* a = items + swaps[k][0].at;
    std::swap_ranges(a, a + swaps[k][0].length, items + swaps[k][1].at);
  });
  return mid;
}

// Below this many items a split sets up only the bins its items fall in:
// setting up and sweeping all kBins was most of the time of the small
// splits, and most splits are small.
constexpr std::uint32_t kFewItems = 16;

// The bins that hold an item, for at most kFewItems items: one pass finds
// them, a second fills them.
Bins fewItemsBins(BuildItem* items, std::uint32_t begin, std::uint32_t end, const BinRule& rule) {
  std::uint32_t held = 0;
  for (std::uint32_t i = begin; i < end; ++i) {
    int b = rule(items[i].centre());
    items[i].bin = static_cast<std::uint32_t>(b);
    held |= 1u << b;
  }
  Bins bins;
  std::array<int, kBins> slot;
  for (; held != 0; held &= held - 1) {
    int b = std::countr_zero(held);
    slot[b] = bins.size;
    bins.number[bins.size] = b;
    bins.extent[bins.size] = NodeExtent{};
    bins.count[bins.size] = 0;
    ++bins.size;
  }
#if defined(__SSE2__)
  std::array<BinExtent, kBins> extent;
  for (int j = 0; j < bins.size; ++j) extent[j].clear();
  for (std::uint32_t i = begin; i < end; ++i) {
    int j = slot[items[i].bin];
    ++bins.count[j];
    __m128d xy, z;
    BinExtent::centreAlong(items[i], 0, xy, z);
    extent[j].add(items[i], xy, z);
  }
  for (int j = 0; j < bins.size; ++j) bins.extent[j] = extent[j].extent();
#else
  for (std::uint32_t i = begin; i < end; ++i) {
    int j = slot[items[i].bin];
    ++bins.count[j];
    bins.extent[j].extend(items[i]);
  }
#endif
  return bins;
}

// The split of least cost by the surface area heuristic, as the index in
// `bins` of the last bin on the left. The splits are those after bins 0 to
// kBins - 2, priced as left count * left area + right count * right area,
// and the first of the cheapest is taken. With leaves of at least two
// items, a split leaving either side fewer is no candidate (one leaving a
// side none is left to the caller, as it always was). The split after a
// bin with no item prices and counts the same as the split after the bin
// before it, so leaving the bin out changes neither the price of any split
// nor which is first of the cheapest. Bin 0, which holds the lowest
// centre, is never left out. Returns the bin (-1 where no split is a
// candidate) and the price.
std::pair<int, double> cheapestSplit(const Bins& bins, std::uint32_t minLeafItems) {
  // Right to left: what the bins after each one cost.
  std::array<double, kBins> rightCost;
  std::array<std::uint32_t, kBins> rightCounts;
  Bounds right;
  std::uint32_t rightCount = 0;
  for (int j = bins.size - 1; j >= 0; --j) {
    rightCost[j] = rightCount ? rightCount * right.surfaceArea() : 0.0;
    rightCounts[j] = rightCount;
    right.extend(bins.extent[j].bounds);
    rightCount += bins.count[j];
  }
  int cheapest = -1;
  double least = 0.0;
  Bounds left;
  std::uint32_t leftCount = 0;
  for (int j = 0; j < bins.size && bins.number[j] <= kBins - 2; ++j) {
    left.extend(bins.extent[j].bounds);
    leftCount += bins.count[j];
    if (minLeafItems > 1 && (leftCount < minLeafItems || rightCounts[j] < minLeafItems)) continue;
    double cost = (leftCount ? leftCount * left.surfaceArea() : 0.0) + rightCost[j];
    if (cheapest < 0 || cost < least) {
      cheapest = j;
      least = cost;
    }
  }
  return {cheapest, least};
}

// Whether `count` items of a node of surface area `area` cost less as a
// leaf than split at `splitCost` (the children's counts times their areas):
// the surface area heuristic with a leaf cost. Equal costs make the leaf.
bool leafIsCheaper(const BuildInput& in, std::uint32_t count, double area, double splitCost) {
  return count <= kMaxLeafItems && count * area <= in.nodeCost * area + splitCost;
}

// Fills in the node over items [begin, end), of the given extent: its box,
// and either a leaf's items or a split, for which it orders the items (those
// of the first child first), sets the children's extents, and returns where
// the second child's begin. Many items are binned on `threads` threads.
std::optional<std::uint32_t> splitNode(const BuildInput& in, BvhNode& node, std::uint32_t begin,
                                       std::uint32_t end, int depth, const NodeExtent& extentIn,
                                       std::array<NodeExtent, 2>& children, int threads = 1) {
  BuildItem* items = in.items;
  const Bounds& centreBounds = extentIn.centres;
  std::uint32_t count = end - begin;
  if (depth >= kMaxDepth && count <= 0xFFFF) {
    writeLeaf(node, begin, count, extentIn.bounds);
    return std::nullopt;
  }
  if (count < 2 * in.minLeafItems) {
    // No split leaves each side a leaf's fewest items.
    writeLeaf(node, begin, count, extentIn.bounds);
    return std::nullopt;
  }
  writeBox(node, extentIn.bounds);

  // Step 1: the widest axis of the centres; all centres equal means no split
  // can help, so halve the list.
  glm::dvec3 extent = centreBounds.hi - centreBounds.lo;
  int axis = extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
  std::uint32_t mid = begin + count / 2;
  node.axis = static_cast<std::uint8_t>(axis);
  node.count = 0;
  if (count == 2) {
    // What the bins below give two items, without them (two in five of
    // the splits, where the bins' set-up was most of the work): whatever the
    // split, the cost is the same (the two apart), so unless a leaf is
    // cheaper, the item with the lower centre goes first, and equal centres
    // keep their order, as the median's sort of two does.
    double splitCost = items[begin].box().surfaceArea() + items[begin + 1].box().surfaceArea();
    if (leafIsCheaper(in, count, extentIn.bounds.surfaceArea(), splitCost)) {
      writeLeaf(node, begin, count, extentIn.bounds);
      return std::nullopt;
    }
    if (items[begin + 1].centre(axis) < items[begin].centre(axis)) {
      std::swap(items[begin], items[begin + 1]);
    }
    children = {NodeExtent{}, NodeExtent{}};
    children[0].extend(items[begin]);
    children[1].extend(items[begin + 1]);
    return mid;
  }
  if (extent[axis] > 0.0 && depth < kMaxDepth) {
    // Step 2: bin the centres and price every split between bins by the
    // surface area heuristic.
    BinRule rule{axis, centreBounds.lo[axis], kBins / extent[axis]};
    Bins bins = count <= kFewItems ? fewItemsBins(items, begin, end, rule)
                                   : manyItemsBinsInParts(items, begin, end, rule, threads);
    auto [cheapest, splitCost] = cheapestSplit(bins, in.minLeafItems);
    std::uint32_t leftCount = 0;
    for (int j = 0; j <= cheapest; ++j) leftCount += bins.count[j];
    if (leftCount != 0 && leftCount != count &&
        !leafIsCheaper(in, count, extentIn.bounds.surfaceArea(), splitCost)) {
      // Step 3: the split, and the children's extents, the unions of their
      // bins'.
      std::uint32_t last = static_cast<std::uint32_t>(bins.number[cheapest]);
      if (count >= kMinItemsPartitionedInBlocks) {
        partitionInBlocks(items, begin, end, last, threads);
      } else {
        std::partition(items + begin, items + end,
                       [&](const BuildItem& item) { return item.bin <= last; });
      }
      children = {NodeExtent{}, NodeExtent{}};
      for (int j = 0; j < bins.size; ++j) children[j <= cheapest ? 0 : 1].extend(bins.extent[j]);
      return begin + leftCount;
    }
  }
  if (count <= kMaxLeafItems) {
    // No split of these few (all centres in one bin, or one place, or no
    // split leaving each side a leaf's fewest) beats them together.
    writeLeaf(node, begin, count, extentIn.bounds);
    return std::nullopt;
  }
  // The median: more than kMaxLeafItems items leave each side two or more.
  static_assert(kMaxLeafItems >= 3);
  std::nth_element(
      items + begin, items + mid, items + end,
      [&](const BuildItem& a, const BuildItem& b) { return a.centre(axis) < b.centre(axis); });
  children = {extentOf(items, begin, mid), extentOf(items, mid, end)};
  return mid;
}

// Builds the subtree over items [begin, end), of the given extent, depth
// first into the nodes from `at` on; returns the index past its last node.
std::uint32_t buildSubtree(const BuildInput& in, std::uint32_t at, std::uint32_t begin,
                           std::uint32_t end, int depth, const NodeExtent& extent) {
  BvhNode& node = in.nodes[at];
  if (end - begin == 1) {
    // A leaf, the node of half the calls, without the split's set-up.
    writeLeaf(node, begin, 1, extent.bounds);
    return at + 1;
  }
  std::array<NodeExtent, 2> children;
  std::optional<std::uint32_t> mid = splitNode(in, node, begin, end, depth, extent, children);
  if (!mid) return at + 1;
  std::uint32_t second = buildSubtree(in, at + 1, begin, *mid, depth + 1, children[0]);
  node.offset = second;
  return buildSubtree(in, second, *mid, end, depth + 1, children[1]);
}

// A subtree left to the threads: items [begin, end) at `depth`, built into
// the nodes from `at`, where BuildInput::mostNodes(end - begin) nodes, the
// most it can take, are kept for it; `used` is how many it took.
struct Subtree {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  int depth = 0;
  std::uint32_t at = 0;
  std::uint32_t used = 0;
  NodeExtent extent;
};

// Past this many subtrees the top of the tree stops splitting, which bounds
// the list (Bvh::bytesFor).
constexpr std::size_t kMaxSubtrees = Bvh::kTasksPerThread * Bvh::kMaxBuildThreads * 2;
// Below this many boxes one thread builds it all: starting threads would
// cost more than they save.
constexpr std::uint32_t kMinParallelBoxes = 16384;
// planTop's ranges hold more than a leaf's items, so each is split.
static_assert(kMinParallelBoxes / (Bvh::kTasksPerThread * Bvh::kMaxBuildThreads) > kMaxLeafItems);

// A range of items at the top of the tree, waiting for its node at `at`.
struct TopRange {
  std::uint32_t at = 0;
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  int depth = 0;
  NodeExtent extent;
};

// The top of the tree from the ranges of `level` down, above the subtrees
// of at most `largest` items (and above kMaxDepth, where buildSubtree makes
// the leaves), built a level at a time, the splits of a level side by side
// on `threads` threads. Each node sits where it would if every subtree took
// all it may: a range of c items keeps in.mostNodes(c), so the second child
// of a split at `at` is at at + 1 + in.mostNodes(mid - begin). Leaves
// `subtrees` in node order.
void planTop(const BuildInput& in, std::uint32_t largest, std::vector<Subtree>& subtrees,
             std::vector<TopRange> level, int threads) {
  std::vector<TopRange> splitting, next;
  std::vector<std::uint32_t> mids;
  std::vector<std::array<NodeExtent, 2>> children;
  while (!level.empty()) {
    // A split adds a range: at most kMaxSubtrees of them in all.
    bool room = subtrees.size() + 2 * level.size() <= kMaxSubtrees;
    splitting.clear();
    for (const TopRange& r : level) {
      if (!room || r.end - r.begin <= largest || r.depth >= kMaxDepth) {
        subtrees.push_back(Subtree{r.begin, r.end, r.depth, r.at, 0, r.extent});
      } else {
        splitting.push_back(r);
      }
    }
    // More than a leaf's items below kMaxDepth: splitNode splits, never a
    // leaf.
    mids.assign(splitting.size(), 0);
    children.resize(splitting.size());
    // A split alone on its level (the root's) bins on every thread.
    int binThreads = splitting.size() == 1 ? threads : 1;
    runParts(splitting.size(), threads, [&](std::size_t k) {
      const TopRange& r = splitting[k];
      mids[k] = *splitNode(in, in.nodes[r.at], r.begin, r.end, r.depth, r.extent, children[k],
                           binThreads);
    });
    next.clear();
    for (std::size_t k = 0; k < splitting.size(); ++k) {
      const TopRange& r = splitting[k];
      std::uint32_t second = r.at + 1 + in.mostNodes(mids[k] - r.begin);
      in.nodes[r.at].offset = second;
      next.push_back(TopRange{r.at + 1, r.begin, mids[k], r.depth + 1, children[k][0]});
      next.push_back(TopRange{second, mids[k], r.end, r.depth + 1, children[k][1]});
    }
    level.swap(next);
  }
  std::sort(subtrees.begin(), subtrees.end(),
            [](const Subtree& a, const Subtree& b) { return a.at < b.at; });
}

// Builds the subtrees on `threads` threads (this one among them), largest
// first, each taking the next one left.
void buildSubtrees(const BuildInput& in, std::vector<Subtree>& subtrees, int threads) {
  std::vector<std::uint32_t> order(subtrees.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  // Largest first, ties by place: std::sort, which needs no buffer of its
  // own (Bvh::bytesFor).
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    std::uint32_t sizeA = subtrees[a].end - subtrees[a].begin;
    std::uint32_t sizeB = subtrees[b].end - subtrees[b].begin;
    return sizeA != sizeB ? sizeA > sizeB : a < b;
  });
  runParts(order.size(), threads, [&](std::size_t k) {
    Subtree& s = subtrees[order[k]];
    s.used = buildSubtree(in, s.at, s.begin, s.end, s.depth, s.extent) - s.at;
  });
}

// Closes the gaps that subtrees taking fewer nodes than kept for them left
// (leaves of several items make them): moves each
// stretch of nodes down and renumbers the second children. Returns the
// node count.
std::uint32_t closeGaps(const BuildInput& in, const std::vector<Subtree>& subtrees,
                        std::uint32_t reserved) {
  BvhNode* nodes = in.nodes;
  // shifts[k]: how far nodes past subtree k's reserved nodes move down.
  std::vector<std::uint32_t> gapEnds(subtrees.size());
  std::vector<std::uint32_t> shifts(subtrees.size());
  std::uint32_t shift = 0;
  for (std::size_t k = 0; k < subtrees.size(); ++k) {
    const Subtree& s = subtrees[k];
    std::uint32_t kept = in.mostNodes(s.end - s.begin);
    shift += kept - s.used;
    gapEnds[k] = s.at + kept;
    shifts[k] = shift;
  }
  if (shift == 0) return reserved;
  auto moved = [&](std::uint32_t index) {
    auto k = std::upper_bound(gapEnds.begin(), gapEnds.end(), index) - gapEnds.begin();
    return k == 0 ? index : index - shifts[k - 1];
  };
  std::uint32_t out = 0;
  std::uint32_t index = 0;
  // The nodes of the top of the tree from `index` to `end`: their second
  // children may lie past any gap.
  auto moveTop = [&](std::uint32_t end) {
    for (; index < end; ++index) {
      BvhNode node = nodes[index];
      if (node.count == 0) node.offset = moved(node.offset);
      nodes[out++] = node;
    }
  };
  for (std::size_t k = 0; k < subtrees.size(); ++k) {
    const Subtree& s = subtrees[k];
    moveTop(s.at);
    // A subtree's second children lie in it, and move as far as it does.
    const std::uint32_t down = s.at - out;
    for (std::uint32_t i = s.at; i < s.at + s.used; ++i) {
      BvhNode node = nodes[i];
      if (node.count == 0) node.offset -= down;
      nodes[out++] = node;
    }
    index = gapEnds[k];  // past the gap
  }
  moveTop(reserved);
  return out;
}

}  // namespace

std::uint64_t Bvh::bytesFor(std::uint64_t boxes) {
  // The vectors of the constructor below, each sized or reserved once. With
  // more than one thread the build also holds its list of subtrees, with the
  // order it builds them in and closeGaps's two lists (at most
  // kMaxSubtrees each) and its threads (at most kMaxBuildThreads), and only
  // for kMinParallelBoxes boxes or more: at most kParallelBytes in all.
  constexpr std::uint64_t kSubtreeBytes = sizeof(Subtree) + 3 * sizeof(std::uint32_t);
  // planTop's levels: at most 2 kMaxSubtrees ranges in each of its three
  // lists, a split point and the children's extents for each, and
  // runParts' slot for a part's exception.
  constexpr std::uint64_t kLevelBytes =
      2 * kMaxSubtrees *
      (3 * sizeof(TopRange) + sizeof(std::uint32_t) + sizeof(std::array<NodeExtent, 2>) +
       sizeof(std::exception_ptr));
  // The root's bins, a set a thread.
  constexpr std::uint64_t kRootBinBytes =
      kMaxBuildThreads * (sizeof(Bins) + sizeof(std::exception_ptr));
  constexpr std::uint64_t kParallelBytes = kMaxSubtrees * kSubtreeBytes + kLevelBytes +
                                           kRootBinBytes + kMaxBuildThreads * sizeof(std::thread);
  // A Morton top's ranges and splits (at most kMaxSubtrees each), the
  // ranges it has yet to split (at most two a level of its 30), and its
  // sort's places, a set a thread; its second list is the nodes' room.
  constexpr std::uint64_t kMortonBytes =
      kMaxSubtrees * (sizeof(bvh_build::MortonRange) + sizeof(std::uint32_t)) +
      64 * sizeof(bvh_build::MortonRange) + kMaxBuildThreads * bvh_build::kSortBytesPerThread;
  std::uint64_t perBox = sizeof(std::uint32_t) + sizeof(BuildItem);
  // The nodes' room (mostNodes, and a node over).
  std::uint64_t nodeRoom =
      saturatingProduct(boxes, (2 / minLeafItemsFor(nodeCostFor(boxes))) * sizeof(BvhNode));
  // A split partitioning in blocks (one at a time on a thread).
  std::uint64_t partitionBytes =
      boxes >= kMinItemsPartitionedInBlocks
          ? kMaxBuildThreads * (boxes / kPartitionBlock + 1) * kPartitionBytesPerBlock
          : 0;
  return saturatingSum(
      saturatingSum(saturatingSum(saturatingProduct(boxes, perBox), nodeRoom), partitionBytes),
      (boxes >= kMinParallelBoxes ? kParallelBytes : 0) +
          (boxes >= kMinMortonTopBoxes ? kMortonBytes : 0));
}

Bvh::Bvh(const std::vector<Bounds>& boxes, int threads)
    : Bvh(boxes, threads, nodeCostFor(boxes.size())) {}

Bvh::Bvh(const std::vector<Bounds>& boxes, int threads, double nodeCost)
    : Bvh(
          static_cast<std::uint32_t>(boxes.size()), [&](std::uint32_t i) { return boxes[i]; },
          threads, nodeCost) {}

Bvh::Bvh(std::uint32_t n, const std::function<Bounds(std::uint32_t)>& boxOf, int threads)
    : Bvh(n, boxOf, threads, nodeCostFor(n)) {}

Bvh::Bvh(std::uint32_t n, const std::function<Bounds(std::uint32_t)>& boxOf, int threads,
         double nodeCost) {
  if (n == 0) return;
  threads = std::min(resolveThreads(threads), kMaxBuildThreads);
  if (n < kMinParallelBoxes) threads = 1;
  // The list in parts side by side, each part's extent merged after (a
  // union of boxes, the same whatever the parts): most of it is the first
  // touch of its fresh pages. The nodes' room is only reserved: a page
  // becomes memory when a node is first written in it (or, under a Morton
  // top, when its sort writes there).
  std::vector<BuildItem> items;
  allocateHere(items, n);
  const std::uint32_t minLeafItems = minLeafItemsFor(nodeCost);
  const bool mortonTop = minLeafItems >= 2 && n >= kMinMortonTopBoxes;
  // A Morton top's sort takes the nodes' room, before any node is written,
  // for its second list: one node more than the tree may take.
  static_assert(sizeof(BuildItem) == sizeof(BvhNode));
  nodes_ = BvhNodes(mortonTop ? n : mostNodes(n, minLeafItems));
  // Both on 2 MiB pages where the system has them: a 512th of the faults as
  // they are first written, and fewer TLB misses in the passes over them
  // (the build took about a sixth less CPU time at floor-1000000 and
  // floor-10000000).
  adviseHugePages(items.data(), items.data() + n);
  adviseHugePages(nodes_.data(), nodes_.data() + nodes_.span().size());
  items.resize(n);
  const std::size_t parts = static_cast<std::size_t>(threads);
  std::vector<NodeExtent> extents(parts);
  runParts(parts, threads, [&](std::size_t part) {
    const std::uint32_t end = static_cast<std::uint32_t>(n * (part + 1) / parts);
    for (std::uint32_t i = static_cast<std::uint32_t>(n * part / parts); i < end; ++i) {
      BuildItem& item = items[i];
      floatPlanesAround(boxOf(i), item.planes);
      item.index = i;
      item.bin = 0;
      extents[part].extend(item);
    }
  });
  NodeExtent extent;
  for (const NodeExtent& part : extents) extent.extend(part);
  BuildInput in{items.data(), nodes_.data(), nodeCost, minLeafItems};
  itemCount_ = n;
  // The boxes' numbers in the order the build left them, which the leaves'
  // items follow; then the build's list goes. (The nodes have given back
  // the room past those made.)
  auto keepOrder = [&] {
    order_.resize(n);
    runParts(parts, threads, [&](std::size_t part) {
      const std::uint32_t end = static_cast<std::uint32_t>(n * (part + 1) / parts);
      for (std::uint32_t i = static_cast<std::uint32_t>(n * part / parts); i < end; ++i) {
        order_[i] = items[i].index;
      }
    });
    std::vector<BuildItem>().swap(items);
  };
  if (threads == 1 && !mortonTop) {
    nodes_.shrink(buildSubtree(in, 0, 0, n, 0, extent));
    keepOrder();
    return;
  }
  // The top of the tree is split here until its parts are small enough to
  // share out; every part is then built as the one-thread build above would
  // have built it, at the place it would have had, so the tree does not
  // depend on the thread count.
  std::uint32_t largest = std::max<std::uint32_t>(n / (kTasksPerThread * threads), 1);
  std::vector<Subtree> subtrees;
  subtrees.reserve(kMaxSubtrees);
  // The ranges the heuristic's top starts from: the root, or under a
  // Morton top its ranges, on any thread count, of at most four times
  // `least` items, at least `least` each: at most kMaxSubtrees of them.
  std::vector<TopRange> level{TopRange{0, 0, n, 0, extent}};
  std::vector<std::uint32_t> splits;
  if (mortonTop) {
    bvh_build::sortByMortonCode(items.data(), n, extent.centres, threads,
                                reinterpret_cast<BuildItem*>(nodes_.data()));
    const std::uint32_t least = static_cast<std::uint32_t>((n + kMaxSubtrees - 1) / kMaxSubtrees);
    std::vector<bvh_build::MortonRange> ranges = bvh_build::mortonTop(
        items.data(), n, 4 * least, least, minLeafItems, nodes_.data(), splits);
    level.resize(ranges.size());
    runParts(ranges.size(), threads, [&](std::size_t k) {
      const bvh_build::MortonRange& r = ranges[k];
      level[k] = TopRange{r.at, r.begin, r.end, r.depth, extentOf(items.data(), r.begin, r.end)};
    });
  }
  planTop(in, largest, subtrees, std::move(level), threads);
  buildSubtrees(in, subtrees, threads);
  // The Morton splits' boxes, once their children's are written.
  bvh_build::boxSplits(splits, nodes_.data());
  nodes_.shrink(closeGaps(in, subtrees, in.mostNodes(n)));
  keepOrder();
}

std::vector<std::uint32_t> Bvh::takeOrder() {
  std::vector<std::uint32_t> order;
  order.swap(order_);
  return order;
}

std::vector<std::uint32_t> Bvh::visitRanks(std::uint8_t signs) const {
  std::vector<std::uint32_t> rank(itemCount_, 0);
  if (empty()) return rank;
  std::vector<std::uint32_t> stack{0};
  std::uint32_t next = 0;
  while (!stack.empty()) {
    std::uint32_t current = stack.back();
    stack.pop_back();
    const BvhNode& node = nodes()[current];
    if (node.count > 0) {
      for (std::uint32_t i = 0; i < node.count; ++i) rank[node.offset + i] = next++;
      continue;
    }
    std::uint32_t nearChild = current + 1;
    std::uint32_t farChild = node.offset;
    if (signs >> node.axis & 1) std::swap(nearChild, farChild);
    stack.push_back(farChild);
    stack.push_back(nearChild);
  }
  return rank;
}

}  // namespace render
