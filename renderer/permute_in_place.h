// permuteInPlace: arrays laid out in a new order without a second copy of
// them, on a few threads (the records of a scene put in its BVH's order).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <tuple>
#include <vector>

#include "renderer/parallel_parts.h"

namespace render {

namespace permute_detail {

// Every kStride-th place is a station (below). At 32, the stations' copies
// are a 32nd of the arrays, and a cycle that meets none is short.
inline constexpr std::size_t kStride = 32;
// Walks that one thread keeps going at once, so that their reads from
// memory overlap: one walk alone waits for each read before the next.
inline constexpr int kLanes = 8;
// Parts for the threads to share: enough that they end together.
inline constexpr std::size_t kPartsPerThread = 16;

template <typename T>
void prefetch(const T* element) {
  __builtin_prefetch(element);
  __builtin_prefetch(reinterpret_cast<const char*>(element) + sizeof(T) - 1);
}

}  // namespace permute_detail

// Lays out `arrays` (each of order.size() elements) so that element i of
// each becomes the one that was at order[i], `order` being a permutation,
// on at most `threads` threads; the result is the same whatever their
// number.
//
// Following a cycle (place `at` takes the element at order[at], whose place
// takes the next one, until the cycle closes) waits on memory at every step,
// and a random order makes one long cycle. So every kStride-th place is a
// station whose element is set aside first; the walk from each station
// along its cycle up to the next station (which takes the element set
// aside there) is then independent of the others, and these walks run on
// the threads, kLanes at a time on each, the next step's reads prefetched.
// Cycles that meet no station are walked whole afterwards, one by one. Beyond the
// arrays it holds a byte a place and the stations' elements.
template <typename... T>
void permuteInPlace(std::span<const std::uint32_t> order, int threads, std::span<T>... arrays) {
  using namespace permute_detail;
  const std::size_t count = order.size();
  if (count == 0) return;
  const std::size_t stations = (count + kStride - 1) / kStride;
  std::tuple<std::vector<T>...> saved{std::vector<T>(stations)...};
  // f(array, its stations' copies), for each array.
  auto eachArray = [&](auto&& f) { std::apply([&](auto&... s) { (f(arrays, s), ...); }, saved); };
  for (std::size_t s = 0; s < stations; ++s) {
    eachArray([&](auto& a, auto& copies) { copies[s] = a[s * kStride]; });
  }
  std::vector<std::uint8_t> placed(count, 0);
  const std::size_t parts =
      std::min(stations, static_cast<std::size_t>(std::max(threads, 1)) * kPartsPerThread);
  runParts(parts, threads, [&](std::size_t part) {
    std::size_t next = stations * part / parts;
    const std::size_t end = stations * (part + 1) / parts;
    // A walk's place and the place of the element it takes, read ahead.
    struct Lane {
      std::size_t at;
      std::size_t from;
    };
    auto start = [&](Lane& lane) {
      for (; next < end; ++next) {
        std::size_t at = next * kStride;
        if (order[at] == at) {
          placed[at] = 1;
          continue;
        }
        lane = Lane{at, order[at]};
        eachArray([&](auto& a, auto&) { prefetch(&a[lane.from]); });
        prefetch(&order[lane.from]);
        ++next;
        return true;
      }
      return false;
    };
    Lane lanes[kLanes];
    int active = 0;
    while (active < kLanes && start(lanes[active])) ++active;
    while (active > 0) {
      for (int k = 0; k < active; ++k) {
        Lane& lane = lanes[k];
        placed[lane.at] = 1;
        if (lane.from % kStride == 0) {
          eachArray([&](auto& a, auto& copies) { a[lane.at] = copies[lane.from / kStride]; });
          if (!start(lane)) lane = lanes[--active];
          continue;
        }
        eachArray([&](auto& a, auto&) { a[lane.at] = a[lane.from]; });
        lane = Lane{lane.from, order[lane.from]};
        eachArray([&](auto& a, auto&) { prefetch(&a[lane.from]); });
        prefetch(&order[lane.from]);
      }
    }
  });
  // The cycles that meet no station, one after another: each walk marks
  // its places, so every cycle is walked once, in time linear in its
  // length. (On threads, a cycle would need an owner, such as its smallest
  // place, and finding that costs a walk from each place: quadratic in the
  // length of a long cycle, which an order such as a shift by kStride
  // makes.) In a random order they are few and short.
  for (std::size_t first = 0; first < count; ++first) {
    if (placed[first] != 0 || order[first] == first) continue;
    std::tuple<T...> kept{arrays[first]...};
    for (std::size_t at = first;;) {
      placed[at] = 1;
      std::size_t from = order[at];
      if (from == first) {
        std::apply([&](auto&... k) { ((arrays[at] = k), ...); }, kept);
        break;
      }
      ((arrays[at] = arrays[from]), ...);
      at = from;
    }
  }
}

}  // namespace render
