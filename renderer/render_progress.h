// How a render reports its progress and hears that it is to stop: the
// progress callback, the cancel flag and what a cancelled render throws.
#pragma once

#include <atomic>

#include "scenefile/render.h"

namespace render {

// Called after each finished tile with the tiles done and the total.
using ProgressCallback = scene::RenderProgress;

// Asks a render to stop before it is done: set from any thread, or from a
// signal handler (the atomic is lock-free), and read by the render before
// each row of pixels, so that a render stops within a row's time whatever
// the image's size (the Python module's Ctrl+C). Once set it stays set.
class CancelFlag {
 public:
  void request() noexcept { requested_.store(true, std::memory_order_relaxed); }
  bool requested() const noexcept { return requested_.load(std::memory_order_relaxed); }

 private:
  static_assert(std::atomic<bool>::is_always_lock_free);
  std::atomic<bool> requested_{false};
};

// What renderImage throws when its CancelFlag is set (scenefile/render.h).
using RenderCancelled = scene::RenderCancelled;

}  // namespace render
