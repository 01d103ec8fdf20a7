// The BVH build gives the same tree, node for node and item for item,
// whatever the number of threads that share it.
#include "renderer/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace render {
namespace {

std::vector<Bounds> randomBoxes(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  std::vector<Bounds> boxes;
  for (int i = 0; i < count; ++i) {
    glm::dvec3 centre(uniform(-100, 100), uniform(-100, 100), uniform(-100, 100));
    // A few share one centre, so that median splits of equal centres occur.
    if (i % 50 == 0) centre = glm::dvec3(1.0, -0.0, 0.0);
    glm::dvec3 half(uniform(0.01, 2), uniform(0.01, 2), uniform(0.01, 2));
    boxes.push_back(Bounds{centre - half, centre + half});
  }
  return boxes;
}

// A box rounded outward to floats, as the build keeps it.
Bounds floatBox(const Bounds& box) {
  float planes[6];
  floatPlanesAround(box, planes);
  return Bounds{glm::dvec3(planes[0], planes[1], planes[2]),
                glm::dvec3(planes[3], planes[4], planes[5])};
}

// Boxes farther and farther out along x from the origin, each 17 times as
// far as the last (more than the bins, so the next falls in the first bin),
// all tiny, from the smallest floats to the largest: wherever they end up,
// the surface area heuristic finds the farthest alone in its last bin and
// the others in the first, so it peels them off one by one, and the tree
// reaches the depth past which the build makes leaves of many boxes. Being
// tiny, they share a subtree with the few boxes about the origin, below the
// top of the tree.
void addOutliers(std::vector<Bounds>& boxes, int count) {
  for (int i = 0; i < count; ++i) {
    double x = 1e-44 * std::pow(17.0, i);
    glm::dvec3 half(0.1 * x);
    boxes.push_back(Bounds{glm::dvec3(x, 0, 0) - half, glm::dvec3(x, 0, 0) + half});
  }
}

void expectSameTree(const Bvh& a, const Bvh& b, int threads) {
  ASSERT_EQ(a.order(), b.order()) << threads << " threads";
  ASSERT_EQ(a.nodes().size(), b.nodes().size()) << threads << " threads";
  for (std::size_t i = 0; i < a.nodes().size(); ++i) {
    const BvhNode& x = a.nodes()[i];
    const BvhNode& y = b.nodes()[i];
    // The planes' bits, so that -0 and +0 differ.
    ASSERT_EQ(std::memcmp(x.planes, y.planes, sizeof x.planes), 0)
        << threads << " threads, node " << i;
    ASSERT_EQ(x.offset, y.offset) << threads << " threads, node " << i;
    ASSERT_EQ(x.count, y.count) << threads << " threads, node " << i;
    ASSERT_EQ(x.axis, y.axis) << threads << " threads, node " << i;
  }
}

// Every item in exactly one leaf, every box one item's, every second child
// after its sibling.
void expectWellFormed(const Bvh& bvh, std::size_t boxes) {
  std::vector<int> seen(boxes, 0);
  std::span<const BvhNode> nodes = bvh.nodes();
  ASSERT_EQ(bvh.itemCount(), boxes);
  std::vector<std::uint32_t> order = bvh.order();
  std::sort(order.begin(), order.end());
  for (std::size_t item = 0; item < boxes; ++item) ASSERT_EQ(order[item], item);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const BvhNode& node = nodes[i];
    if (node.count > 0) {
      for (std::uint32_t k = 0; k < node.count; ++k) ++seen[node.offset + k];
    } else {
      ASSERT_GT(node.offset, i + 1);
      ASSERT_LT(node.offset, nodes.size());
    }
  }
  for (std::size_t item = 0; item < boxes; ++item) ASSERT_EQ(seen[item], 1) << "item " << item;
}

TEST(BvhBuild, TheTreeIsTheSameWhateverTheThreadCount) {
  for (int count : {1, 2, 17, 1000, 40000}) {
    std::vector<Bounds> boxes = randomBoxes(count, count);
    Bvh one(boxes, 1);
    expectWellFormed(one, boxes.size());
    EXPECT_LE(one.nodes().size(), 2 * boxes.size() - 1);
    // 64 threads split the top of the tree into more subtrees than its
    // list may hold: the top stops at the budget, the tree stays the same.
    for (int threads : {2, 4, 64}) expectSameTree(one, Bvh(boxes, threads), threads);
  }
  // Enough boxes that the root bins them on several threads and partitions
  // them in blocks, side by side; with leaves of one box and of several.
  std::vector<Bounds> boxes = randomBoxes(300000, 300000);
  for (double nodeCost : {Bvh::kNodeCost, Bvh::kCompactNodeCost}) {
    Bvh one(boxes, 1, nodeCost);
    expectWellFormed(one, boxes.size());
    for (int threads : {2, 3}) {
      expectSameTree(one, Bvh(boxes, threads, nodeCost), threads);
    }
  }
}

// Past the greatest depth the build makes leaves of many boxes, which take
// fewer nodes than the threads' subtrees kept for them: the gaps are closed
// and the second children renumbered, to the one-thread tree exactly.
TEST(BvhBuild, DeepTreesWithLeavesOfManyBoxesAreTheSameWhateverTheThreadCount) {
  std::vector<Bounds> boxes = randomBoxes(7, 30000);
  addOutliers(boxes, 67);
  Bvh one(boxes, 1);
  expectWellFormed(one, boxes.size());
  bool manyInALeaf = false;
  for (const BvhNode& node : one.nodes()) manyInALeaf |= node.count > Bvh::kMaxLeafItems;
  ASSERT_TRUE(manyInALeaf) << "the scene no longer reaches the greatest depth";
  EXPECT_LT(one.nodes().size(), 2 * boxes.size() - 1);
  for (int threads : {2, 3, 4}) expectSameTree(one, Bvh(boxes, threads), threads);
}

// Boxes handed over one by one build the tree built over the list, each
// asked for once, on one thread and on several.
TEST(BvhBuild, BoxesMadeOnTheFlyBuildTheSameTree) {
  for (int threads : {1, 3}) {
    std::vector<Bounds> boxes = randomBoxes(11, 40000);
    Bvh fromList(boxes, threads);
    std::vector<std::atomic<int>> asked(boxes.size());
    Bvh onTheFly(
        static_cast<std::uint32_t>(boxes.size()),
        [&](std::uint32_t i) {
          ++asked[i];
          return boxes[i];
        },
        threads);
    expectSameTree(fromList, onTheFly, threads);
    for (std::size_t i = 0; i < boxes.size(); ++i) ASSERT_EQ(asked[i], 1) << "box " << i;
  }
}

// A node over two items that is split (these are, being far apart for
// their size) splits them on the widest axis of their centres (the lowest
// on a tie), the lower centre first and equal centres in their order, as
// the surface area heuristic's bins and the median's sort order them.
TEST(BvhBuild, TwoItemsGoLowerCentreFirstOnTheirWidestAxis) {
  auto box = [](glm::dvec3 centre, double half) {
    return Bounds{centre - glm::dvec3(half), centre + glm::dvec3(half)};
  };
  Bvh swapped(std::vector<Bounds>{box({0, 5, 1}, 1), box({0, 2, 1}, 3)}, 1);
  EXPECT_EQ(swapped.order(), (std::vector<std::uint32_t>{1, 0}));
  EXPECT_EQ(swapped.nodes()[0].axis, 1);
  Bvh kept(std::vector<Bounds>{box({-3, 0, 0}, 1), box({4, 0, 1}, 1)}, 1);
  EXPECT_EQ(kept.order(), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(kept.nodes()[0].axis, 0);
  Bvh equal(std::vector<Bounds>{box({1, 1, 1}, 2), box({1, 1, 1}, 1)}, 1);
  EXPECT_EQ(equal.order(), (std::vector<std::uint32_t>{0, 1}));

  // The same in every pair of leaves of a larger tree.
  std::vector<Bounds> boxes = randomBoxes(5, 5000);
  Bvh bvh(boxes, 1);
  std::span<const BvhNode> nodes = bvh.nodes();
  int pairs = 0;
  for (std::size_t i = 0; i + 2 < nodes.size(); ++i) {
    const BvhNode& node = nodes[i];
    if (node.count > 0 || node.offset != i + 2) continue;
    if (nodes[i + 1].count != 1 || nodes[i + 2].count != 1) continue;
    glm::dvec3 a = floatBox(boxes[bvh.order()[nodes[i + 1].offset]]).centre();
    glm::dvec3 b = floatBox(boxes[bvh.order()[nodes[i + 2].offset]]).centre();
    glm::dvec3 extent = glm::max(a, b) - glm::min(a, b);
    int widest =
        extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
    ASSERT_EQ(node.axis, widest) << "node " << i;
    ASSERT_LE(a[widest], b[widest]) << "node " << i;
    ++pairs;
  }
  EXPECT_GT(pairs, 500);
}

// The build's rule written the plain way, as a reference, over the boxes
// rounded outward to floats: every split bins the centres of its items in
// 16 bins along the widest axis of their centres, prices the split after
// each of bins 0 to 14 by the surface area heuristic, takes the first of
// the cheapest (std::min_element) when it leaves items on both sides and
// costs less than a leaf would (at most Bvh::kMaxLeafItems items: their
// count times the node's area, against nodeCost times the area plus the
// split's price), makes a leaf of at most that many otherwise, and else
// halves the list at the median. Two items are priced as split apart.
struct ReferenceBuild {
  std::vector<Bounds> boxes;
  std::vector<std::uint32_t> items;
  std::vector<BvhNode> nodes;
  double nodeCost;

  bool leafIsCheaper(std::uint32_t count, double area, double splitCost) {
    return count <= Bvh::kMaxLeafItems && count * area <= nodeCost * area + splitCost;
  }

  std::uint32_t leaf(std::uint32_t at, std::uint32_t begin, std::uint32_t end) {
    nodes.resize(std::max<std::size_t>(nodes.size(), at + 1));
    nodes[at].offset = begin;
    nodes[at].count = static_cast<std::uint16_t>(end - begin);
    return at + 1;
  }

  std::uint32_t build(std::uint32_t at, std::uint32_t begin, std::uint32_t end) {
    Bounds bounds, centres;
    for (std::uint32_t i = begin; i < end; ++i) {
      bounds.extend(boxes[items[i]]);
      centres.extend(boxes[items[i]].centre());
    }
    nodes.resize(std::max<std::size_t>(nodes.size(), at + 1));
    for (int i = 0; i < 3; ++i) {
      nodes[at].planes[i] = floatAtOrBelow(bounds.lo[i]);
      nodes[at].planes[3 + i] = floatAtOrAbove(bounds.hi[i]);
    }
    std::uint32_t count = end - begin;
    const std::uint32_t minLeaf = Bvh::minLeafItemsFor(nodeCost);
    if (count < 2 * minLeaf) return leaf(at, begin, end);
    glm::dvec3 e = centres.hi - centres.lo;
    int axis = e.x > e.y ? (e.x > e.z ? 0 : 2) : (e.y > e.z ? 1 : 2);
    auto centre = [&](std::uint32_t item) { return boxes[item].centre()[axis]; };
    std::uint32_t mid = begin + count / 2;
    bool split = false;
    if (count == 2) {
      double cost = boxes[items[begin]].surfaceArea() + boxes[items[begin + 1]].surfaceArea();
      if (leafIsCheaper(count, bounds.surfaceArea(), cost)) return leaf(at, begin, end);
      if (centre(items[begin + 1]) < centre(items[begin])) {
        std::swap(items[begin], items[begin + 1]);
      }
      split = true;
    } else if (e[axis] > 0.0) {
      double scale = 16 / e[axis];
      auto binOf = [&](std::uint32_t item) {
        return std::clamp(static_cast<int>((centre(item) - centres.lo[axis]) * scale), 0, 15);
      };
      std::array<Bounds, 16> binBounds;
      std::array<std::uint32_t, 16> counts{};
      for (std::uint32_t i = begin; i < end; ++i) {
        binBounds[binOf(items[i])].extend(boxes[items[i]]);
        ++counts[binOf(items[i])];
      }
      std::array<double, 15> cost;
      std::array<std::uint32_t, 15> lefts;
      for (int b = 0; b < 15; ++b) {
        Bounds left, right;
        std::uint32_t l = 0, r = 0;
        for (int k = 0; k < 16; ++k) {
          (k <= b ? left : right).extend(binBounds[k]);
          (k <= b ? l : r) += counts[k];
        }
        cost[b] = (l ? l * left.surfaceArea() : 0.0) + (r ? r * right.surfaceArea() : 0.0);
        lefts[b] = l;
      }
      int best = -1;
      for (int b = 0; b < 15; ++b) {
        bool candidate = minLeaf < 2 || (lefts[b] >= minLeaf && count - lefts[b] >= minLeaf);
        if (candidate && (best < 0 || cost[b] < cost[best])) best = b;
      }
      if (best >= 0 && lefts[best] != 0 && lefts[best] != count &&
          !leafIsCheaper(count, bounds.surfaceArea(), cost[best])) {
        std::partition(items.begin() + begin, items.begin() + end,
                       [&](std::uint32_t item) { return binOf(item) <= best; });
        mid = begin + lefts[best];
        split = true;
      }
    }
    if (!split && count <= Bvh::kMaxLeafItems) return leaf(at, begin, end);
    if (!split) {
      std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                       [&](std::uint32_t a, std::uint32_t b) { return centre(a) < centre(b); });
    }
    nodes[at].axis = static_cast<std::uint8_t>(axis);
    std::uint32_t second = build(at + 1, begin, mid);
    nodes[at].offset = second;
    return build(second, mid, end);
  }
};

// Boxes on a coarse grid, of a few sizes: most bins of a split are empty
// and many splits price the same, so the order in which the build picks
// among equal prices shows.
std::vector<Bounds> gridBoxes(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::vector<Bounds> boxes;
  for (int i = 0; i < count; ++i) {
    glm::dvec3 centre(static_cast<double>(rng() % 7), static_cast<double>(rng() % 3),
                      static_cast<double>(rng() % 5) * 0.5);
    glm::dvec3 half(0.25 * static_cast<double>(1 + rng() % 2));
    boxes.push_back(Bounds{centre - half, centre + half});
  }
  return boxes;
}

// The build (which sets up only the bins its items fall in for small
// splits, and works each child's extent out from its bins) makes the
// reference's tree, node for node and item for item.
TEST(BvhBuild, SplitsAsThePlainBinnedSurfaceAreaRuleDoes) {
  for (double nodeCost : {Bvh::kNodeCost, Bvh::kCompactNodeCost}) {
    for (std::uint64_t seed = 1; seed <= 400; ++seed) {
      int count = 2 + static_cast<int>(seed % 90);
      std::vector<Bounds> boxes = seed % 2 ? gridBoxes(seed, count) : randomBoxes(seed, count);
      if (seed % 6 == 0) {
        // Near the end of the float range.
        for (Bounds& box : boxes) box = Bounds{box.lo * 1e36, box.hi * 1e36};
      }
      ReferenceBuild reference{{}, {}, {}, nodeCost};
      for (const Bounds& box : boxes) reference.boxes.push_back(floatBox(box));
      for (std::uint32_t i = 0; i < boxes.size(); ++i) reference.items.push_back(i);
      reference.build(0, 0, static_cast<std::uint32_t>(boxes.size()));
      Bvh bvh(boxes, 1, nodeCost);
      ASSERT_EQ(bvh.order(), reference.items) << "seed " << seed << ", cost " << nodeCost;
      ASSERT_EQ(bvh.nodes().size(), reference.nodes.size())
          << "seed " << seed << ", cost " << nodeCost;
      ASSERT_EQ(std::memcmp(bvh.nodes().data(), reference.nodes.data(),
                            reference.nodes.size() * sizeof(BvhNode)),
                0)
          << "seed " << seed << ", cost " << nodeCost;
    }
  }
}

// Boxes for the compact tree's bound: random, on a grid, all one box, and
// all on a line (centres in a row, and the same centre half the time).
std::vector<Bounds> compactTrialBoxes(std::uint64_t seed, int count) {
  switch (seed % 4) {
    case 0:
      return randomBoxes(seed, count);
    case 1:
      return gridBoxes(seed, count);
    case 2:
      return std::vector<Bounds>(count, Bounds{glm::dvec3(-1.0), glm::dvec3(1.0)});
    default: {
      std::vector<Bounds> boxes;
      for (int i = 0; i < count; ++i) {
        glm::dvec3 centre(static_cast<double>(seed % 8 == 3 ? i / 2 : i), 0.0, 0.0);
        boxes.push_back(Bounds{centre - 0.25, centre + 0.25});
      }
      return boxes;
    }
  }
}

// At the compact price every leaf holds two items or more, so a tree over
// n boxes has at most n / 2 leaves and n - 1 nodes: what Bvh::bytesFor
// counts from Bvh::kCompactFromBoxes boxes.
TEST(BvhBuild, CompactTreesHaveLeavesOfTwoItemsOrMoreAndFewerNodesThanBoxes) {
  auto expectCompact = [](const Bvh& bvh, std::size_t count, const std::string& what) {
    expectWellFormed(bvh, count);
    ASSERT_LE(bvh.nodes().size(), std::max<std::size_t>(count - 1, 1)) << what;
    for (const BvhNode& node : bvh.nodes()) {
      if (node.count > 0) {
        ASSERT_GE(node.count, count >= 2 ? 2u : 1u) << what;
      }
    }
  };
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    int count = 1 + static_cast<int>(seed % 120);
    std::vector<Bounds> boxes = compactTrialBoxes(seed, count);
    expectCompact(Bvh(boxes, 1, Bvh::kCompactNodeCost), boxes.size(),
                  "seed " + std::to_string(seed));
  }
  // On threads, whose subtrees keep the room of the compact bound.
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    std::vector<Bounds> boxes = compactTrialBoxes(seed, 50000);
    Bvh one(boxes, 1, Bvh::kCompactNodeCost);
    expectCompact(one, boxes.size(), "seed " + std::to_string(seed));
    expectSameTree(one, Bvh(boxes, 3, Bvh::kCompactNodeCost), 3);
  }
  // From kMinMortonTopBoxes boxes, with the top split in the Morton order
  // (of one centre, a line and a grid too, where it splits little).
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    std::vector<Bounds> boxes =
        compactTrialBoxes(seed, static_cast<int>(Bvh::kMinMortonTopBoxes) + 3001);
    Bvh one(boxes, 1, Bvh::kCompactNodeCost);
    expectCompact(one, boxes.size(), "Morton top, seed " + std::to_string(seed));
    expectSameTree(one, Bvh(boxes, 3, Bvh::kCompactNodeCost), 3);
  }
  // The bound the estimate counts: 64 bytes of nodes a box below the
  // compact price, 32 from it.
  const std::uint64_t from = Bvh::kCompactFromBoxes;
  EXPECT_EQ(Bvh::bytesFor(from + 2) - Bvh::bytesFor(from), 2 * 32 + 2 * 36);
  EXPECT_EQ(Bvh::bytesFor(from - 1) - Bvh::bytesFor(from - 3), 2 * 64 + 2 * 36);
  EXPECT_EQ(Bvh::mostNodes(from, Bvh::minLeafItemsFor(Bvh::nodeCostFor(from))), from - 1);
}

// The surface area heuristic's price of a tree: each node's area (a
// fraction of the root's) times kCompactNodeCost, and each leaf's times its
// items.
double treePrice(const Bvh& bvh) {
  auto area = [](const BvhNode& node) {
    double x = node.planes[3] - node.planes[0], y = node.planes[4] - node.planes[1],
           z = node.planes[5] - node.planes[2];
    return x * y + y * z + z * x;
  };
  double price = 0.0;
  for (const BvhNode& node : bvh.nodes()) {
    price += area(node) * (node.count > 0 ? node.count : Bvh::kCompactNodeCost);
  }
  return price / area(bvh.nodes()[0]);
}

// A floor of boxes of a few sizes, 2,000 wide and 20 high (as sfgen lays
// them out). The top of its compact tree split in the Morton order prices
// within 2% of the tree the heuristic splits alone: the same boxes but one,
// too few for the Morton top.
TEST(BvhBuild, AMortonTopPricesTheTreeAsTheHeuristicAlone) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> across(-1000.0, 1000.0), up(0.0, 20.0), size(0.5, 6.0);
  std::vector<Bounds> boxes;
  for (std::uint64_t i = 0; i < Bvh::kMinMortonTopBoxes; ++i) {
    glm::dvec3 centre(across(rng), up(rng), across(rng));
    glm::dvec3 half(size(rng), size(rng), size(rng));
    boxes.push_back(Bounds{centre - half, centre + half});
  }
  const double withMorton = treePrice(Bvh(boxes, 2, Bvh::kCompactNodeCost));
  boxes.pop_back();
  const double heuristicAlone = treePrice(Bvh(boxes, 2, Bvh::kCompactNodeCost));
  EXPECT_LT(withMorton, 1.02 * heuristicAlone);
  EXPECT_GT(withMorton, 0.98 * heuristicAlone);
}

// With the whole image's samples known, a tree is compact from
// kMinCompactBoxes boxes where the image takes fewer than
// kFullTreeSamplesPerBox samples a box, and from kCompactFromBoxes boxes
// whatever it takes.
TEST(BvhBuild, FewSamplesABoxPriceTheCompactTree) {
  const std::uint64_t least = Bvh::kMinCompactBoxes;
  const std::uint64_t rate = Bvh::kFullTreeSamplesPerBox;
  EXPECT_EQ(Bvh::nodeCostFor(least - 1, 0), Bvh::kNodeCost);
  EXPECT_EQ(Bvh::nodeCostFor(least, rate * least - 1), Bvh::kCompactNodeCost);
  EXPECT_EQ(Bvh::nodeCostFor(least, rate * least), Bvh::kNodeCost);
  EXPECT_EQ(Bvh::nodeCostFor(1'000'000, 1920 * 1080), Bvh::kCompactNodeCost);
  EXPECT_EQ(Bvh::nodeCostFor(1'000'000, 1920 * 1080 * 8), Bvh::kNodeCost);
  EXPECT_EQ(Bvh::nodeCostFor(Bvh::kCompactFromBoxes, UINT64_MAX), Bvh::kCompactNodeCost);
  EXPECT_EQ(Bvh::nodeCostFor(Bvh::kCompactFromBoxes - 1, UINT64_MAX), Bvh::kNodeCost);
}

// The outward rounding of box planes to float is std::nextafter's step from
// the nearest float, for doubles of every magnitude, at and between floats,
// at zeros, at the ends of the float range and past them, and NaN.
TEST(FloatPlanes, RoundOutwardAsNextafterDoes) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  auto below = [](double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) > v ? std::nextafter(f, -kInf) : f;
  };
  auto above = [](double v) {
    float f = static_cast<float>(v);
    return static_cast<double>(f) < v ? std::nextafter(f, kInf) : f;
  };
  auto check = [&](double v) {
    float b = floatAtOrBelow(v);
    float a = floatAtOrAbove(v);
    ASSERT_EQ(std::bit_cast<std::uint32_t>(b), std::bit_cast<std::uint32_t>(below(v))) << v;
    ASSERT_EQ(std::bit_cast<std::uint32_t>(a), std::bit_cast<std::uint32_t>(above(v))) << v;
    if (!std::isnan(v)) {
      ASSERT_LE(static_cast<double>(b), v);
      ASSERT_GE(static_cast<double>(a), v);
    }
  };
  const double denorm = std::numeric_limits<float>::denorm_min();
  const double most = std::numeric_limits<float>::max();
  for (double v : {0.0, -0.0, denorm, -denorm, 0.5 * denorm, -0.5 * denorm, 1e-300, -1e-300, most,
                   -most, most * (1 + 1e-9), -most * (1 + 1e-9), 1e300, -1e300,
                   std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity(), std::nan("")}) {
    check(v);
  }
  std::mt19937_64 rng(17);
  for (int i = 0; i < 200000; ++i) {
    // A float, the doubles just beside it, and a double of any magnitude.
    float f = std::bit_cast<float>(static_cast<std::uint32_t>(rng()));
    if (std::isnan(f)) continue;
    double d = f;
    check(d);
    check(std::nextafter(d, 1e308));
    check(std::nextafter(d, -1e308));
    check(std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng),
                     static_cast<int>(rng() % 300) - 150));
  }
}

// A box's six planes rounded at once are the planes rounded one by one,
// for every mix of the values above across the six.
TEST(FloatPlanes, ABoxsPlanesRoundedTogetherAreEachRoundedAlone) {
  const double denorm = std::numeric_limits<float>::denorm_min();
  const double most = std::numeric_limits<float>::max();
  std::vector<double> special = {
      0.0,   -0.0,   denorm,    -denorm,    0.5 * denorm, 1e-300, -1e-300, most, -most * (1 + 1e-9),
      1e300, -1e300, 1.0 / 3.0, -1.0 / 3.0, std::nan("")};
  std::mt19937_64 rng(23);
  auto value = [&] {
    if (rng() % 3 == 0) return special[rng() % special.size()];
    float f = std::bit_cast<float>(static_cast<std::uint32_t>(rng()));
    double d = std::isnan(f) ? 1.5 : f;
    switch (rng() % 3) {
      case 0:
        return d;
      case 1:
        return std::nextafter(d, rng() % 2 ? 1e308 : -1e308);
      default:
        return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng),
                          static_cast<int>(rng() % 300) - 150);
    }
  };
  for (int i = 0; i < 300000; ++i) {
    Bounds box{glm::dvec3(value(), value(), value()), glm::dvec3(value(), value(), value())};
    float planes[6];
    floatPlanesAround(box, planes);
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(std::bit_cast<std::uint32_t>(planes[k]),
                std::bit_cast<std::uint32_t>(floatAtOrBelow(box.lo[k])))
          << box.lo[k];
      ASSERT_EQ(std::bit_cast<std::uint32_t>(planes[3 + k]),
                std::bit_cast<std::uint32_t>(floatAtOrAbove(box.hi[k])))
          << box.hi[k];
    }
  }
}

// hitsBox's test of all three slabs answers as the test that stops at the
// first slab that empties the interval, for rays along the axes (infinite
// inverse components), from the boxes' planes (0 * infinity), and at
// random.
TEST(BoxTest, AllThreeSlabsAnswerAsStoppingAtTheFirstMissDoes) {
  auto stopping = [](const Bounds& b, const BoxRay& r, double tMin, double tMax) {
    for (int i = 0; i < 3; ++i) {
      double tNear = (b.lo[i] - r.origin[i]) * r.inverseDirection[i];
      double tFar = (b.hi[i] - r.origin[i]) * r.inverseDirection[i];
      if (tNear > tFar) std::swap(tNear, tFar);
      tFar *= 1.0 + 2.0 * gamma(3);
      tMin = tNear > tMin ? tNear : tMin;
      tMax = tFar < tMax ? tFar : tMax;
      if (tMin > tMax) return false;
    }
    return true;
  };
  std::mt19937_64 rng(29);
  auto coordinate = [&] {
    // Often a plane of the box, or zero, so that slabs are grazed.
    switch (rng() % 4) {
      case 0:
        return static_cast<double>(static_cast<int>(rng() % 5) - 2);
      default:
        return std::uniform_real_distribution<double>(-3, 3)(rng);
    }
  };
  int hits = 0;
  for (int i = 0; i < 500000; ++i) {
    glm::dvec3 lo(coordinate(), coordinate(), coordinate());
    Bounds box{lo, lo + glm::dvec3(std::abs(coordinate()), std::abs(coordinate()),
                                   std::abs(coordinate()))};
    glm::dvec3 direction(coordinate(), coordinate(), coordinate());
    BoxRay ray{glm::dvec3(coordinate(), coordinate(), coordinate()), 1.0 / direction};
    double tMax = rng() % 3 == 0 ? std::numeric_limits<double>::infinity() : std::abs(coordinate());
    bool expected = stopping(box, ray, 0.0, tMax);
    ASSERT_EQ(hitsBox(box, ray, 0.0, tMax), expected) << i;
    hits += expected;
  }
  // Both answers, many times.
  EXPECT_GT(hits, 10000);
  EXPECT_LT(hits, 490000);
}

TEST(BvhBuild, NoBoxesMakeAnEmptyTree) {
  EXPECT_TRUE(Bvh(std::vector<Bounds>{}, 4).empty());
}

}  // namespace
}  // namespace render
