// The Morton order of a build's items and the top of the tree split from it.
#include "renderer/bvh_morton.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace render::bvh_build {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Items numbered by their place, of random boxes, some sharing a centre,
// and where asked some with planes past the float range (a centre of
// infinity, or of -infinity to infinity, which orders as 0; the extent of
// the centres is then infinite, and every code 0).
std::vector<BuildItem> randomItems(std::uint64_t seed, std::uint32_t count,
                                   bool infinities = false) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-100.0, 100.0);
  std::vector<BuildItem> items(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    glm::dvec3 centre(uniform(rng), uniform(rng), uniform(rng));
    if (i % 7 == 0) centre = glm::dvec3(3.0, -2.0, 1.0);
    Bounds box{centre - 0.5, centre + 0.5};
    if (infinities && i % 101 == 0) box.hi.x = kInfinity;
    if (infinities && i % 103 == 0) box = Bounds{glm::dvec3(-kInfinity), glm::dvec3(kInfinity)};
    floatPlanesAround(box, items[i].planes);
    items[i].index = i;
    items[i].bin = 0;
  }
  return items;
}

Bounds centresOf(const std::vector<BuildItem>& items) {
  Bounds centres;
  for (const BuildItem& item : items) centres.extend(item.centre());
  return centres;
}

// The code written the plain way: each axis's cell, a cube's side the
// widest extent over 1024, and its bits interleaved one at a time, x's
// highest.
std::uint32_t referenceCode(const BuildItem& item, const Bounds& centres) {
  glm::dvec3 extent = centres.hi - centres.lo;
  double widest = std::max({extent.x, extent.y, extent.z});
  double scale = widest > 0.0 ? 1024.0 / widest : 0.0;
  std::uint32_t cells[3];
  for (int axis = 0; axis < 3; ++axis) {
    double t = (item.centre(axis) - centres.lo[axis]) * scale;
    cells[axis] = std::isnan(t) || t < 0.0 ? 0 : static_cast<std::uint32_t>(std::min(t, 1023.0));
  }
  std::uint32_t code = 0;
  for (int bit = 9; bit >= 0; --bit) {
    for (int axis = 0; axis < 3; ++axis) code = code << 1 | (cells[axis] >> bit & 1);
  }
  return code;
}

std::vector<BuildItem> sorted(std::vector<BuildItem> items, int threads) {
  Bounds centres = centresOf(items);
  std::vector<BuildItem> scratch(items.size());
  sortByMortonCode(items.data(), static_cast<std::uint32_t>(items.size()), centres, threads,
                   scratch.data());
  return items;
}

TEST(SortByMortonCode, OrdersByCodeTiesInTheirOrderTheSameOnAnyThreadCount) {
  for (std::uint32_t count : {1u, 2u, 1000u, 1001u, 70001u}) {
    std::vector<BuildItem> items = randomItems(count, count, count == 1001);
    const Bounds centres = centresOf(items);
    std::vector<BuildItem> one = sorted(items, 1);
    for (std::uint32_t i = 0; i < count; ++i) {
      ASSERT_EQ(one[i].bin, referenceCode(one[i], centres)) << "item " << i;
      if (i > 0) {
        ASSERT_LE(one[i - 1].bin, one[i].bin) << "item " << i;
        if (one[i - 1].bin == one[i].bin) {
          ASSERT_LT(one[i - 1].index, one[i].index);
        }
      }
    }
    std::set<std::uint32_t> indices;
    for (const BuildItem& item : one) indices.insert(item.index);
    ASSERT_EQ(indices.size(), count);
    for (int threads : {2, 3, 7}) {
      std::vector<BuildItem> many = sorted(items, threads);
      ASSERT_EQ(std::memcmp(one.data(), many.data(), count * sizeof(BuildItem)), 0)
          << count << " items, " << threads << " threads";
    }
  }
}

// Boxes spread over a floor 1000 wide and half a cell high: the cells are
// cubes, so every centre lies in the lowest cell along y and the code's y
// bits stay 0, leaving its bits to the axes the boxes spread along.
TEST(SortByMortonCode, AFlatLayoutSpendsNoBitsOnItsThinAxis) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> across(0.0, 1000.0), up(0.0, 0.45);
  std::vector<BuildItem> items(5000);
  for (std::uint32_t i = 0; i < items.size(); ++i) {
    glm::dvec3 centre(across(rng), up(rng), across(rng));
    floatPlanesAround(Bounds{centre - 0.25, centre + 0.25}, items[i].planes);
    items[i].index = i;
  }
  constexpr std::uint32_t kYBits = 0x12492492;  // bits 3k + 1
  std::uint32_t seen = 0;
  for (const BuildItem& item : sorted(items, 2)) seen |= item.bin;
  EXPECT_EQ(seen & kYBits, 0u);
  EXPECT_EQ(seen & ~kYBits, 0x3FFFFFFFu & ~kYBits);
}

// What mortonTop left: `at` of each range and split, and the items each
// node spans, walked from the root.
struct TopWalk {
  const std::vector<BuildItem>& items;
  const std::vector<BvhNode>& nodes;
  std::map<std::uint32_t, MortonRange> ranges;
  std::set<std::uint32_t> splits;
  std::uint32_t minLeafItems;
  int walked = 0;

  // The items [begin, end) under the node at `at`, checked against its
  // split: the first child's codes lack the highest bit in which the
  // span's codes differ, the second's have it, its axis is that bit's,
  // and the second child sits past the first's room.
  std::pair<std::uint32_t, std::uint32_t> walk(std::uint32_t at, int depth) {
    if (auto r = ranges.find(at); r != ranges.end()) {
      EXPECT_EQ(r->second.depth, depth);
      ++walked;
      return {r->second.begin, r->second.end};
    }
    EXPECT_TRUE(splits.count(at)) << "node " << at;
    const BvhNode& node = nodes[at];
    auto [begin, mid] = walk(at + 1, depth + 1);
    auto [second, end] = walk(node.offset, depth + 1);
    EXPECT_EQ(second, mid);
    EXPECT_EQ(node.offset, at + 1 + mostBvhNodes(mid - begin, minLeafItems));
    std::uint32_t differ = items[begin].bin ^ items[end - 1].bin;
    int bit = 31 - std::countl_zero(differ);
    EXPECT_EQ(node.axis, 2 - bit % 3);
    EXPECT_EQ(items[mid - 1].bin >> bit & 1, 0u);
    EXPECT_EQ(items[mid].bin >> bit & 1, 1u);
    return {begin, end};
  }
};

TEST(MortonTop, SplitsWhereTheCodesDifferDownToRangesOfAtLeastTheLeast) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const std::uint32_t count = 20000 + static_cast<std::uint32_t>(seed) * 777;
    std::vector<BuildItem> items = sorted(randomItems(seed, count), 2);
    const std::uint32_t least = 50 * static_cast<std::uint32_t>(seed), most = 4 * least;
    const std::uint32_t minLeafItems = seed % 2 ? 2 : 1;
    std::vector<BvhNode> nodes(mostBvhNodes(count, minLeafItems));
    std::vector<std::uint32_t> splits;
    std::vector<MortonRange> ranges =
        mortonTop(items.data(), count, most, least, minLeafItems, nodes.data(), splits);
    ASSERT_GT(ranges.size(), 1u);
    std::uint32_t next = 0;
    for (const MortonRange& r : ranges) {
      ASSERT_EQ(r.begin, next);
      ASSERT_GE(r.end - r.begin, least);
      next = r.end;
      // A range of more than `most` holds one code, or splitting it at
      // its codes' highest differing bit leaves a side fewer than `least`.
      if (r.end - r.begin > most) {
        std::uint32_t differ = items[r.begin].bin ^ items[r.end - 1].bin;
        if (differ != 0) {
          std::uint32_t bit = std::uint32_t{1} << (31 - std::countl_zero(differ));
          std::uint32_t low = 0;
          for (std::uint32_t i = r.begin; i < r.end; ++i) low += (items[i].bin & bit) == 0;
          ASSERT_TRUE(low < least || r.end - r.begin - low < least);
        }
      }
    }
    ASSERT_EQ(next, count);
    TopWalk top{items, nodes, {}, {splits.begin(), splits.end()}, minLeafItems};
    for (const MortonRange& r : ranges) top.ranges[r.at] = r;
    ASSERT_EQ(top.walk(0, 0), std::make_pair(0u, count));
    EXPECT_EQ(top.walked, static_cast<int>(ranges.size()));
    EXPECT_EQ(splits.size(), ranges.size() - 1);
  }
}

// One code for every item: nothing to split, one range.
TEST(MortonTop, ItemsOfOneCodeStayOneRange) {
  std::vector<BuildItem> items(5000);
  for (std::uint32_t i = 0; i < items.size(); ++i) {
    floatPlanesAround(Bounds{glm::dvec3(-1.0), glm::dvec3(1.0)}, items[i].planes);
    items[i].index = i;
  }
  items = sorted(items, 2);
  std::vector<BvhNode> nodes(items.size());
  std::vector<std::uint32_t> splits;
  std::vector<MortonRange> ranges = mortonTop(items.data(), 5000, 100, 25, 2, nodes.data(), splits);
  ASSERT_EQ(ranges.size(), 1u);
  EXPECT_EQ(ranges[0].end, 5000u);
  EXPECT_TRUE(splits.empty());
}

// A split's box is the union of its children's, bit for bit, whether a
// child is a split or a leaf.
TEST(MortonTop, ASplitsBoxIsItsChildrensUnion) {
  std::vector<BvhNode> nodes(5);
  auto box = [&](std::uint32_t at, float lo, float hi) {
    for (int p = 0; p < 3; ++p) {
      nodes[at].planes[p] = lo + static_cast<float>(p);
      nodes[at].planes[3 + p] = hi - static_cast<float>(p);
    }
  };
  // 0 splits into 1 and 4; 1 into 2 and 3.
  nodes[0].offset = 4;
  nodes[1].offset = 3;
  box(2, -1.5f, 2.0f);
  box(3, 0.25f, 7.0f);
  box(4, -0.0f, 3.0f);
  boxSplits({0, 1}, nodes.data());
  EXPECT_EQ(nodes[1].planes[0], -1.5f);
  EXPECT_EQ(nodes[1].planes[3], 7.0f);
  EXPECT_EQ(nodes[0].planes[0], -1.5f);
  EXPECT_EQ(nodes[0].planes[4], 6.0f);
  EXPECT_EQ(nodes[0].planes[2], 0.5f);
}

}  // namespace
}  // namespace render::bvh_build
