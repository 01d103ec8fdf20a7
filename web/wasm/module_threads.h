// The threads the module's work may use: the threaded module (pthreads)
// every core the page's hardwareConcurrency reports, the other its caller's
// thread alone, which it must never try to leave: without pthreads a thread
// cannot start.
#pragma once

#include <algorithm>
#include <thread>

#include "scenefile/read.h"

namespace web {

#ifdef __EMSCRIPTEN_PTHREADS__
inline constexpr bool kModuleHasThreads = true;
#else
inline constexpr bool kModuleHasThreads = false;
#endif

// The threads the module has: 1 without pthreads.
inline int moduleThreads() {
  if (!kModuleHasThreads) return 1;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// The tools' read options (every limit at its default), on the threads the
// module has.
inline scene::ReadOptions moduleReadOptions() {
  scene::ReadOptions options;
  options.threads = kModuleHasThreads ? 0 : 1;
  return options;
}

}  // namespace web
