// Work shared out to threads of their own, for the readers' big files.
#pragma once

#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace scene {

// Runs work(k) for k in [0, count), k = 0 on the calling thread and each
// other on a thread of its own, and waits for all. False where a thread
// could not start (the others are waited for, and their work is to be
// dropped); the first exception a work threw is thrown again.
template <typename Work>
bool runOnThreads(std::size_t count, Work&& work) {
  std::vector<std::exception_ptr> failures(count);
  auto guarded = [&](std::size_t k) {
    try {
      work(k);
    } catch (...) {
      failures[k] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  bool started = true;
  try {
    for (std::size_t k = 1; k < count; ++k) threads.emplace_back(guarded, k);
  } catch (const std::system_error&) {
    started = false;
  }
  if (started) guarded(0);
  for (std::thread& t : threads) t.join();
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
  return started;
}

}  // namespace scene
