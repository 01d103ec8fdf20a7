// A bounding volume hierarchy over boxes, built with the surface area
// heuristic in binned form, stored flat in depth-first order.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "renderer/bounds.h"
#include "renderer/bvh_node.h"

namespace render {

// A direction's signs as the BVH's walk takes them: bit i set where
// component i is negative, -0 included (its inverse is -infinity).
inline std::uint8_t directionSigns(const glm::dvec3& d) {
  return static_cast<std::uint8_t>((std::signbit(d.x) ? 1 : 0) | (std::signbit(d.y) ? 2 : 0) |
                                   (std::signbit(d.z) ? 4 : 0));
}

class Bvh {
 public:
  static constexpr int kStackSize = 128;
  /// The most rays traversePacket walks together: one AVX2 vector of
  /// doubles. Packets of 8 pixels of a row were no quicker (floor-1000000,
  /// camera rays).
  static constexpr int kPacketSize = 4;
  /// The most items a leaf holds where the surface area heuristic (with a
  /// cost for each node) finds them cheaper together than split: fewer
  /// nodes than leaves of one, and no list of items.
  static constexpr std::uint32_t kMaxLeafItems = 4;
  /// What the surface area heuristic prices a node at beside its items'
  /// object tests (1 each), per unit of its area: the two box tests of a
  /// split. Below kCompactFromBoxes, kNodeCost: objects apart from one
  /// another then get leaves of their own, whose boxes cull before the
  /// exact test; leaves of several (kCompactNodeCost, about 0.85 nodes an
  /// object rather than 2 on sfgen's floor) made floor-1000000's shadow
  /// rays a quarter slower (docs/TRACING.md), but hold a scene of
  /// kCompactFromBoxes objects or more in 40 bytes an object less.
  static constexpr double kNodeCost = 0.5;
  static constexpr double kCompactNodeCost = 2.0;
  static constexpr std::uint64_t kCompactFromBoxes = std::uint64_t{1} << 24;
  static constexpr double nodeCostFor(std::uint64_t boxes) {
    return boxes < kCompactFromBoxes ? kNodeCost : kCompactNodeCost;
  }
  /// The price with the camera samples of the whole image known
  /// (fullImageSampleCount): compact also from kMinCompactBoxes boxes where
  /// the image takes fewer than kFullTreeSamplesPerBox samples a box. There
  /// the build outweighs what the full tree saves the walks: at
  /// floor-1000000 in 1080p at 1 spp (2 samples a box) the compact tree
  /// took 0.05 to 0.1 s less to build than it added to the render, at 8 spp
  /// it lost. The light grids start to pay at the same rate
  /// (RenderScene::lightGridsPay). Hits do not depend on the tree, but which
  /// of two equal ones a camera ray takes does (docs/TRACING.md), so the
  /// count is the whole image's, the same for each of its regions.
  static constexpr std::uint64_t kMinCompactBoxes = std::uint64_t{1} << 16;
  static constexpr std::uint64_t kFullTreeSamplesPerBox = 3;
  static constexpr double nodeCostFor(std::uint64_t boxes, std::uint64_t imageSamples) {
    bool fewSamples = boxes >= kMinCompactBoxes && imageSamples / kFullTreeSamplesPerBox < boxes;
    return fewSamples ? kCompactNodeCost : nodeCostFor(boxes);
  }
  /// From this many boxes a compact tree's top levels split where the
  /// Morton codes of the boxes' centres differ (renderer/bvh_morton.h):
  /// one sort in place of a pass over every box at each of those levels.
  static constexpr std::uint64_t kMinMortonTopBoxes = std::uint64_t{1} << 16;
  /// The fewest items a leaf holds in a tree priced at `nodeCost` (a tree
  /// of one box aside): 2 at kCompactNodeCost or more, so that such a tree
  /// has at most n / 2 leaves, so n - 1 nodes, and Bvh::bytesFor need count
  /// only that much room (half of 2n - 1); 1 below it.
  static constexpr std::uint32_t minLeafItemsFor(double nodeCost) {
    return nodeCost >= kCompactNodeCost ? 2 : 1;
  }
  /// Room for the nodes of a tree over `boxes` boxes whose leaves (but a
  /// lone box's) hold at least `minLeafItems` (1 or 2): 2n - 1 or n - 1,
  /// as a tree of L leaves has 2L - 1 nodes. The room of a split is one
  /// node and its children's rooms, exactly, so a build on threads lays
  /// out the top of the tree in it with gaps only where a subtree took
  /// less. The build reserves it, so that the node array never grows (nor
  /// holds twice its size while it moves); only the pages of the nodes made
  /// become memory (BvhNodes).
  static constexpr std::uint64_t mostNodes(std::uint64_t boxes, std::uint32_t minLeafItems) {
    return mostBvhNodes(boxes, minLeafItems);
  }

  /// The most threads a build starts, whatever it is asked for: enough
  /// for any machine this runs on, and what bounds the build's task list.
  static constexpr int kMaxBuildThreads = 64;
  /// Subtrees a build hands out to its threads: about this many per thread,
  /// so that a thread finishing early picks up another.
  static constexpr std::uint32_t kTasksPerThread = 8;

  Bvh() = default;
  /// Builds over `count` boxes, box i being boxOf(i) (called once for each,
  /// from any of the threads, so that the caller need not hold them all).
  /// Items are numbered by their place in the tree's order: a leaf holds
  /// items offset to offset + count - 1, and item k stands for box
  /// order()[k]. `threads` threads share the build (0: the hardware's
  /// count); the tree is the same, node for node and item for item,
  /// whatever their number.
  /// Each node is priced at nodeCostFor(count), or at `nodeCost`.
  Bvh(std::uint32_t count, const std::function<Bounds(std::uint32_t)>& boxOf, int threads);
  Bvh(std::uint32_t count, const std::function<Bounds(std::uint32_t)>& boxOf, int threads,
      double nodeCost);
  /// The same over boxes held in a list.
  explicit Bvh(const std::vector<Bounds>& boxes, int threads = 1);
  Bvh(const std::vector<Bounds>& boxes, int threads, double nodeCost);

  /// The most bytes the build over `boxes` boxes holds at once, priced at
  /// nodeCostFor(boxes): the nodes' room (mostNodes, all of it, as the
  /// smallest leaves may take it: 64 bytes a box, 32 for the compact tree),
  /// a copy of each box in float beside its index that it splits, the
  /// boxes' order, and its list of subtrees for the threads.
  /// The boxes themselves are the caller's. Saturates: a hostile count
  /// gives UINT64_MAX, never a wrapped figure.
  static std::uint64_t bytesFor(std::uint64_t boxes);

  bool empty() const { return nodes().empty(); }
  std::span<const BvhNode> nodes() const { return nodes_.span(); }
  /// The items: one a box.
  std::uint32_t itemCount() const { return itemCount_; }
  /// Per item, the box it stands for, until taken.
  const std::vector<std::uint32_t>& order() const { return order_; }

  /// Hands over order(), leaving it empty: for a caller that lays out its
  /// own records in the BVH's order, so that its records' numbers are the
  /// items'.
  std::vector<std::uint32_t> takeOrder();

  // Calls visit(item) for every item whose leaf box the ray meets within
  // [0, tMax]; visit returns the new tMax (smaller after a hit, to prune) or
  // a negative value to stop at once (for any-hit queries). Items are
  // visited depth first, the child on the ray's near side of the split axis
  // first, whatever boxes are met: the nearest hit and how ties between
  // equal distances fall do not depend on the order in which boxes prune.
  template <typename Visit>
  void traverse(const BoxRay& ray, double tMax, Visit&& visit) const {
    const BvhNode* nodes = nodes_.span().data();
    if (empty()) return;
    NodeRay r(ray);
    double tEntry = 0.0;
    if (!hitsNode(nodes[0], r, tMax, tEntry)) return;
    // Both children are tested at their parent (two independent box tests
    // overlap in the pipeline, and a missed child is never pushed); the far
    // one waits on the stack with its entry distance, and is dropped when
    // popped if a hit found since lies nearer.
    struct Pending {
      std::uint32_t node;
      double tEntry;
    };
    Pending stack[kStackSize];
    int top = 0;
    std::uint32_t current = 0;
    for (;;) {
      const BvhNode& node = nodes[current];
      if (node.count > 0) {
        for (std::uint32_t i = 0; i < node.count; ++i) {
          tMax = visit(node.offset + i);
          if (tMax < 0.0) return;
        }
      } else {
        std::uint32_t nearChild = current + 1;
        std::uint32_t farChild = node.offset;
        if (r.negative[node.axis]) std::swap(nearChild, farChild);
        double tEntries[2];
        int hits = hitsChildren(nodes[nearChild], nodes[farChild], r, tMax, tEntries);
        bool hitNear = hits & 1;
        bool hitFar = hits & 2;
        if (hitNear) {
          if (hitFar) stack[top++] = Pending{farChild, tEntries[1]};
          current = nearChild;
          continue;
        }
        if (hitFar) {
          current = farChild;
          continue;
        }
      }
      for (;;) {
        if (top == 0) return;
        const Pending& next = stack[--top];
        // tEntry is a lower bound on where the ray enters the box (see
        // hitsNode), so a box entered beyond tMax holds nothing nearer.
        if (next.tEntry <= tMax) {
          current = next.node;
          break;
        }
      }
    }
  }

  // traverse for up to kPacketSize rays at once (defined in
  // renderer/bvh_packet.h): visit(lane, item) is called for exactly the
  // items, in exactly the order, that traverse(rays[lane], tMax[lane], ...)
  // would visit, with the same tMax before each, so that every ray ends
  // with the same hit; it returns that ray's new tMax, or a negative value
  // to stop that ray. Rays whose direction signs differ on an axis are
  // traversed one by one.
  template <typename Visit>
  void traversePacket(const BoxRay* rays, int count, const double* tMax, Visit&& visit) const;

  /// Per item, its place in the order in which traverse visits items for a
  /// ray whose direction has the signs `signs` (directionSigns), whatever
  /// boxes it meets: each leaf's items in turn, the near child first. The
  /// nearest hit is the first in this order of the items at the nearest
  /// distance.
  std::vector<std::uint32_t> visitRanks(std::uint8_t signs) const;

 private:
  // traversePacket's walk of rays of the same signs (renderer/bvh_packet.h),
  // and the same built for AVX2.
  template <bool kWide, typename Visit>
  void walkPacket(const BoxRay* rays, int count, const double* tMax, Visit& visit) const;
  template <typename Visit>
  void walkPacketAvx2(const BoxRay* rays, int count, const double* tMax, Visit& visit) const;

  // The ray as the node test wants it, worked out once per ray: per axis,
  // the index in BvhNode::planes of the plane it meets first and last (by
  // the sign of its direction), and with SSE2 the origin and inverse
  // direction in both lanes of a vector.
  struct NodeRay {
    explicit NodeRay(const BoxRay& ray)
        : origin(ray.origin), inverseDirection(ray.inverseDirection) {
      for (int i = 0; i < 3; ++i) {
        negative[i] = ray.inverseDirection[i] < 0.0;
        nearPlane[i] = negative[i] ? 3 + i : i;
        farPlane[i] = negative[i] ? i : 3 + i;
#if defined(__SSE2__)
        originBoth[i] = _mm_set1_pd(ray.origin[i]);
        inverseBoth[i] = _mm_set1_pd(ray.inverseDirection[i]);
#endif
      }
    }
    glm::dvec3 origin;
    glm::dvec3 inverseDirection;
    bool negative[3];
    int nearPlane[3];
    int farPlane[3];
#if defined(__SSE2__)
    __m128d originBoth[3];
    __m128d inverseBoth[3];
#endif
  };

  // hitsBox for a node's float box; the arithmetic is in double, where each
  // float converts exactly. The slab distances are those of hitsBox, with
  // the near and far planes picked by the direction's sign instead of a
  // swap: the same numbers wherever they are not NaN (multiplying by a
  // positive number keeps order, by a negative one reverses it), and a NaN
  // (0 * infinity, a ray in a slab's plane) is ignored. (The swap kept a
  // NaN near distance in place, so a ray with a direction of -0 lying in a
  // box's low plane took the far plane's -infinity and missed the box; here
  // it meets it, as it does with +0: only ever more boxes met.) All three
  // axes are worked out before the one test, rather than a branch per axis:
  // the answer is the same, since tMin only grows and tMax only shrinks.
  // On a hit, tEntry is the ray's entry distance (at least 0), a lower
  // bound, as the far distances alone are widened.
  static bool hitsNode(const BvhNode& node, const NodeRay& r, double tMax, double& tEntry) {
    double tMin = 0.0;
    for (int i = 0; i < 3; ++i) {
      double nearPlane = node.planes[r.nearPlane[i]];
      double farPlane = node.planes[r.farPlane[i]];
      double tNear = (nearPlane - r.origin[i]) * r.inverseDirection[i];
      double tFar = (farPlane - r.origin[i]) * r.inverseDirection[i];
      tFar *= 1.0 + 2.0 * gamma(3);
      tMin = tNear > tMin ? tNear : tMin;
      tMax = tFar < tMax ? tFar : tMax;
    }
    tEntry = tMin;
    return tMin <= tMax;
  }

  // hitsNode for two boxes at once (bit 0: a, bit 1: b; their tEntry in
  // tEntries): with SSE2, in two-lane vectors of doubles, one lane a box,
  // with the same operations on the same numbers as hitsNode, so the same
  // answers, bit for bit. _mm_max_pd(x, m) is x > m ? x : m and
  // _mm_min_pd(x, m) is x < m ? x : m, lane by lane, so a NaN lane of x
  // leaves m as it was, as in hitsNode.
  static int hitsChildren(const BvhNode& a, const BvhNode& b, const NodeRay& r, double tMax,
                          double tEntries[2]) {
#if defined(__SSE2__)
    __m128d tMinV = _mm_setzero_pd();
    __m128d tMaxV = _mm_set1_pd(tMax);
    const __m128d widen = _mm_set1_pd(1.0 + 2.0 * gamma(3));
    for (int i = 0; i < 3; ++i) {
      int n = r.nearPlane[i];
      int f = r.farPlane[i];
      __m128d nearPlanes = _mm_cvtps_pd(_mm_setr_ps(a.planes[n], b.planes[n], 0.0f, 0.0f));
      __m128d farPlanes = _mm_cvtps_pd(_mm_setr_ps(a.planes[f], b.planes[f], 0.0f, 0.0f));
      __m128d tNear = _mm_mul_pd(_mm_sub_pd(nearPlanes, r.originBoth[i]), r.inverseBoth[i]);
      __m128d tFar =
          _mm_mul_pd(_mm_mul_pd(_mm_sub_pd(farPlanes, r.originBoth[i]), r.inverseBoth[i]), widen);
      tMinV = _mm_max_pd(tNear, tMinV);
      tMaxV = _mm_min_pd(tFar, tMaxV);
    }
    _mm_storeu_pd(tEntries, tMinV);
    return _mm_movemask_pd(_mm_cmple_pd(tMinV, tMaxV));
#else
    return (hitsNode(a, r, tMax, tEntries[0]) ? 1 : 0) |
           (hitsNode(b, r, tMax, tEntries[1]) ? 2 : 0);
#endif
  }

  BvhNodes nodes_;
  std::uint32_t itemCount_ = 0;
  std::vector<std::uint32_t> order_;
};

}  // namespace render
