#include "tools/sfrender/thread_probe.h"

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "renderer/parallel_parts.h"

namespace tools {

int renderThreadCount(int requested) {
  return render::resolveThreads(requested);
}

MaybeFailure threadStartFailure(int threads) {
  std::mutex mutex;
  std::condition_variable released;
  bool go = false;
  std::vector<std::thread> pool;
  // Only remembered here: making the message allocates, which must wait
  // until no thread is left joinable.
  std::error_code failure;
  bool noMemory = false;
  try {
    pool.reserve(static_cast<std::size_t>(std::max(0, threads - 1)));
    for (int t = 1; t < threads; ++t) {
      pool.emplace_back([&] {
        std::unique_lock<std::mutex> lock(mutex);
        released.wait(lock, [&] { return go; });
      });
    }
  } catch (const std::system_error& e) {
    failure = e.code();
  } catch (const std::bad_alloc&) {
    noMemory = true;
  }
  {
    std::lock_guard<std::mutex> lock(mutex);
    go = true;
  }
  released.notify_all();
  for (std::thread& t : pool) t.join();
  if (!noMemory && !failure) return std::nullopt;
  return toolFailure(ExitCode::OutOfResources,
                     "cannot start " + std::to_string(threads) +
                         " threads: " + (noMemory ? "out of memory" : failure.message()) +
                         "; ask for fewer with --threads");
}

}  // namespace tools
