// runParts: independent parts of one job (a range of a scene's objects, one
// light's grid) on a few threads, for the work before the first pixel.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace render {

// The threads a `threads` setting asks for: itself where positive, else
// every core (at least one).
inline int resolveThreads(int threads) {
  if (threads > 0) return threads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// Runs work(k) for every k in [0, parts) on at most `threads` threads, this
// one among them, each thread taking the next part left. A thread that
// cannot be started leaves its share to the others, so every part runs
// whatever the system allows. An exception from a part does not stop the
// others; the first part's (in part order) is rethrown here once all have
// ended.
template <typename Work>
void runParts(std::size_t parts, int threads, Work&& work) {
  std::vector<std::exception_ptr> failures(parts);
  std::atomic<std::size_t> next{0};
  auto take = [&] {
    for (std::size_t k = next++; k < parts; k = next++) {
      try {
        work(k);
      } catch (...) {
        failures[k] = std::current_exception();
      }
    }
  };
  std::size_t helpersWanted =
      std::min(parts, static_cast<std::size_t>(std::max(threads, 1))) - (parts > 0 ? 1 : 0);
  std::vector<std::thread> helpers;
  helpers.reserve(helpersWanted);
  for (std::size_t t = 0; t < helpersWanted; ++t) {
    try {
      helpers.emplace_back(take);
    } catch (const std::system_error&) {
      break;  // fewer threads: the ones running take what it would have
    }
  }
  take();
  for (std::thread& helper : helpers) helper.join();
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
}

// Reserves room for `count` elements of `v` on the calling thread, for
// other threads to fill. glibc serves a thread from an arena of its own,
// and a big block of a helper thread's arena is mapped apart and unmapped
// when freed, while the main thread's (where sfrender keeps freed memory,
// tools/sfrender/main.cpp) is handed out again: a big array taken here may
// reuse memory already touched, which a helper's must zero afresh.
template <typename T>
void allocateHere(std::vector<T>& v, std::size_t count) {
  v.reserve(count);
}

}  // namespace render
