// permuteInPlace lays arrays out as a copy in the new order would, for any
// permutation and any number of threads.
#include "renderer/permute_in_place.h"

#include <gtest/gtest.h>

#include <array>
#include <numeric>
#include <random>

namespace render {
namespace {

// An element larger than a cache line, as a scene's records are.
struct Record {
  std::array<double, 13> values{};
  bool operator==(const Record&) const = default;
};

Record recordOf(std::uint32_t i) {
  Record r;
  for (std::size_t k = 0; k < r.values.size(); ++k) r.values[k] = i * 100.0 + k;
  return r;
}

void expectPermutedAsACopyWouldBe(const std::vector<std::uint32_t>& order, int threads) {
  std::vector<Record> records(order.size());
  std::vector<std::uint32_t> numbers(order.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) {
    records[i] = recordOf(i);
    numbers[i] = i;
  }
  permuteInPlace(std::span<const std::uint32_t>(order), threads, std::span<Record>(records),
                 std::span<std::uint32_t>(numbers));
  for (std::size_t i = 0; i < order.size(); ++i) {
    ASSERT_EQ(numbers[i], order[i]) << "place " << i << ", " << threads << " threads";
    ASSERT_EQ(records[i], recordOf(order[i])) << "place " << i << ", " << threads << " threads";
  }
}

std::vector<std::uint32_t> shuffled(std::size_t count, std::uint32_t seed) {
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  return order;
}

TEST(PermuteInPlace, RandomOrdersOnAnyNumberOfThreads) {
  for (std::size_t count : {0, 1, 2, 31, 32, 33, 1000, 100003}) {
    std::vector<std::uint32_t> order = shuffled(count, static_cast<std::uint32_t>(count));
    for (int threads : {1, 2, 3}) expectPermutedAsACopyWouldBe(order, threads);
  }
}

TEST(PermuteInPlace, OneCycleThroughEveryPlace) {
  std::vector<std::uint32_t> order(5000);
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = (i + 1) % order.size();
  for (int threads : {1, 2, 3}) expectPermutedAsACopyWouldBe(order, threads);
}

// Swaps and short cycles between the stations (every 32nd place), which
// only the walk of whole cycles places, and places left where they are.
TEST(PermuteInPlace, CyclesThatMeetNoStation) {
  std::vector<std::uint32_t> order(4096);
  std::iota(order.begin(), order.end(), 0u);
  for (std::uint32_t base = 0; base < order.size(); base += 32) {
    std::swap(order[base + 1], order[base + 2]);
    // Places 5, 9, 7 take each other's elements round a cycle of three.
    order[base + 5] = base + 9;
    order[base + 9] = base + 7;
    order[base + 7] = base + 5;
    // A cycle across two stations' spans.
    if (base + 40 < order.size()) {
      order[base + 30] = base + 40;
      order[base + 40] = base + 30;
    }
  }
  for (int threads : {1, 2, 3}) expectPermutedAsACopyWouldBe(order, threads);
}

// A shift by the stations' stride: every place but the stations' lies on
// one of 31 long cycles that meet no station (at 2^20 places, 32,768 places
// each), which a walk from each place to find its cycle's owner would take
// minutes over.
TEST(PermuteInPlace, LongCyclesThatMeetNoStationInLinearTime) {
  std::vector<std::uint32_t> order(std::size_t{1} << 20);
  for (std::uint32_t i = 0; i < order.size(); ++i) {
    order[i] = static_cast<std::uint32_t>((i + permute_detail::kStride) % order.size());
  }
  for (int threads : {1, 2}) expectPermutedAsACopyWouldBe(order, threads);
}

}  // namespace
}  // namespace render
