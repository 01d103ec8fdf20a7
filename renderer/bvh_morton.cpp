#include "renderer/bvh_morton.h"

#include <algorithm>
#include <array>
#include <bit>
#include <utility>

#include "renderer/parallel_parts.h"

namespace render::bvh_build {

namespace {

constexpr int kAxisBits = 10;
// Four passes of 256 buckets: the sort's items end where they began, and a
// part's places fit in the first-level cache.
constexpr int kDigitBits = 8;
constexpr int kPasses = 4;
constexpr std::uint32_t kDigits = std::uint32_t{1} << kDigitBits;
static_assert(kSortBytesPerThread >= kDigits * sizeof(std::uint32_t) + sizeof(std::exception_ptr));

// The bits of a 10-bit value spread to every third place.
std::uint32_t spreadBits(std::uint32_t v) {
  v = (v | (v << 16)) & 0x030000FFu;
  v = (v | (v << 8)) & 0x0300F00Fu;
  v = (v | (v << 4)) & 0x030C30C3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

// A centre's cell along one axis, 0 to 1023: 0 for what is not a number
// (an infinite extent gives a scale of 0, and infinity times 0).
std::uint32_t cellOf(double centre, double lo, double scale) {
  double t = (centre - lo) * scale;
  if (!(t >= 0.0)) return 0;
  return static_cast<std::uint32_t>(std::min(t, static_cast<double>((1 << kAxisBits) - 1)));
}

// The parts of a pass over n items: contiguous ranges, in order.
std::uint32_t partBegin(std::uint32_t n, std::size_t part, std::size_t parts) {
  return static_cast<std::uint32_t>(static_cast<std::uint64_t>(n) * part / parts);
}

// One stable pass of an LSD radix sort on the bits of `bin` from `shift`:
// each part counts its digits, then moves its items to where the digits of
// the parts before it end, so the order is the same for any part count.
void radixPass(const BuildItem* from, BuildItem* to, std::uint32_t n, int shift, int threads) {
  const std::size_t parts = static_cast<std::size_t>(std::max(threads, 1));
  std::vector<std::array<std::uint32_t, kDigits>> places(parts);
  auto digit = [shift](const BuildItem& item) { return (item.bin >> shift) & (kDigits - 1); };
  runParts(parts, threads, [&](std::size_t k) {
    places[k].fill(0);
    for (std::uint32_t i = partBegin(n, k, parts); i < partBegin(n, k + 1, parts); ++i) {
      ++places[k][digit(from[i])];
    }
  });
  std::uint32_t sum = 0;
  for (std::uint32_t d = 0; d < kDigits; ++d) {
    for (std::size_t k = 0; k < parts; ++k) sum += std::exchange(places[k][d], sum);
  }
  runParts(parts, threads, [&](std::size_t k) {
    std::array<std::uint32_t, kDigits>& at = places[k];
    for (std::uint32_t i = partBegin(n, k, parts); i < partBegin(n, k + 1, parts); ++i) {
      to[at[digit(from[i])]++] = from[i];
    }
  });
}

}  // namespace

void sortByMortonCode(BuildItem* items, std::uint32_t n, const Bounds& centres, int threads,
                      BuildItem* scratch) {
  const std::size_t parts = static_cast<std::size_t>(std::max(threads, 1));
  // Cubes, their side a 1024th of the widest extent: cells as thin as the
  // extent along a flat axis would spend the code's bits on that axis, and
  // neighbours in the codes' order would lie far apart along the others
  // (on a floor, four in a row spanned 600 times an object's area, and 25
  // times with cubes). 1024 / infinity is 0, and 1024 / 0 is left out:
  // every centre in one cell.
  const glm::dvec3 extent = centres.hi - centres.lo;
  const double widest = std::max({extent.x, extent.y, extent.z});
  const double scale = widest > 0.0 ? (1 << kAxisBits) / widest : 0.0;
  runParts(parts, threads, [&](std::size_t k) {
    for (std::uint32_t i = partBegin(n, k, parts); i < partBegin(n, k + 1, parts); ++i) {
      BuildItem& item = items[i];
      item.bin = spreadBits(cellOf(item.centre(0), centres.lo.x, scale)) << 2 |
                 spreadBits(cellOf(item.centre(1), centres.lo.y, scale)) << 1 |
                 spreadBits(cellOf(item.centre(2), centres.lo.z, scale));
    }
  });
  static_assert(kPasses * kDigitBits >= 3 * kAxisBits && kPasses % 2 == 0);
  for (int pass = 0; pass < kPasses; pass += 2) {
    radixPass(items, scratch, n, pass * kDigitBits, threads);
    radixPass(scratch, items, n, (pass + 1) * kDigitBits, threads);
  }
}

std::vector<MortonRange> mortonTop(const BuildItem* sorted, std::uint32_t n, std::uint32_t most,
                                   std::uint32_t least, std::uint32_t minLeafItems, BvhNode* nodes,
                                   std::vector<std::uint32_t>& splits) {
  std::vector<MortonRange> ranges;
  std::vector<MortonRange> pending{MortonRange{0, 0, n, 0}};
  while (!pending.empty()) {
    const MortonRange r = pending.back();
    pending.pop_back();
    // The highest bit in which the range's codes differ (its first and
    // last, the items sorted by their codes).
    const int bitIndex = std::bit_width(sorted[r.begin].bin ^ sorted[r.end - 1].bin) - 1;
    std::uint32_t mid = r.begin;
    if (r.end - r.begin > most && bitIndex >= 0) {
      // The first item with the bit set.
      const std::uint32_t bit = std::uint32_t{1} << bitIndex;
      mid = static_cast<std::uint32_t>(
          std::partition_point(sorted + r.begin, sorted + r.end,
                               [bit](const BuildItem& item) { return (item.bin & bit) == 0; }) -
          sorted);
    }
    if (mid - r.begin < least || r.end - mid < least) {
      ranges.push_back(r);
      continue;
    }
    // Bits 3k + 2, 3k + 1 and 3k hold x, y and z: the lower codes of the
    // bit's axis come first, as a split's first child.
    BvhNode& node = nodes[r.at];
    node = BvhNode{};
    node.axis = static_cast<std::uint8_t>(2 - bitIndex % 3);
    node.offset = r.at + 1 + static_cast<std::uint32_t>(mostBvhNodes(mid - r.begin, minLeafItems));
    splits.push_back(r.at);
    // The second child pushed first: the ranges come out in order.
    pending.push_back(MortonRange{node.offset, mid, r.end, r.depth + 1});
    pending.push_back(MortonRange{r.at + 1, r.begin, mid, r.depth + 1});
  }
  return ranges;
}

void boxSplits(const std::vector<std::uint32_t>& splits, BvhNode* nodes) {
  for (auto at = splits.rbegin(); at != splits.rend(); ++at) {
    BvhNode& node = nodes[*at];
    const BvhNode& first = nodes[*at + 1];
    const BvhNode& second = nodes[node.offset];
    for (int p = 0; p < 3; ++p) {
      node.planes[p] = std::min(first.planes[p], second.planes[p]);
      node.planes[3 + p] = std::max(first.planes[3 + p], second.planes[3 + p]);
    }
  }
}

}  // namespace render::bvh_build
