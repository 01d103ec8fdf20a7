// Handing a render's work to its threads: parts taken in turn, and the
// square tiles of a region (cpu_render.cpp's passes).
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "renderer/image.h"
#include "renderer/render_progress.h"

namespace render {

// The tiles of `region`: squares of kRenderTileSize from its top-left corner.
inline int tileCount(const PixelRegion& region) {
  return ((region.width() + kRenderTileSize - 1) / kRenderTileSize) *
         ((region.height() + kRenderTileSize - 1) / kRenderTileSize);
}

// Calls perPart(worker, part) for each part in [0, total) on `threads`
// threads, each taking the next part left; progress(done, total) after each.
template <typename PerPart>
void forEachPart(int total, int threads, PerPart&& perPart, const ProgressCallback& progress) {
  std::atomic<int> next{0};
  std::atomic<int> done{0};
  std::mutex progressMutex;
  // An exception must not leave a thread's function (that ends the
  // program): the first one (std::bad_alloc, say) stops the handing out of
  // parts and is thrown again once every thread has been joined.
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto work = [&](int worker) {
    try {
      for (int part = next++; part < total; part = next++) {
        perPart(worker, part);
        int finished = ++done;
        if (progress) {
          std::lock_guard<std::mutex> lock(progressMutex);
          progress(finished, total);
        }
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure) failure = std::current_exception();
      next = total;
    }
  };
  std::vector<std::thread> pool;
  try {
    for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  } catch (...) {
    // A thread that cannot start (std::system_error): the running ones
    // finish their part and are joined before the caller hears of it.
    next = total;
    for (std::thread& t : pool) t.join();
    throw;
  }
  work(0);
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

// Calls perTile(worker, tile) for each tile of `region` (squares of
// kRenderTileSize from its top-left corner, cut at its edges) on `threads` threads.
template <typename PerTile>
void forEachTile(const PixelRegion& region, int threads, PerTile&& perTile,
                 const ProgressCallback& progress) {
  int tilesX = (region.width() + kRenderTileSize - 1) / kRenderTileSize;
  forEachPart(
      tileCount(region), threads,
      [&](int worker, int tile) {
        int x0 = region.x0 + (tile % tilesX) * kRenderTileSize;
        int y0 = region.y0 + (tile / tilesX) * kRenderTileSize;
        perTile(worker, PixelRegion{x0, y0, std::min(x0 + kRenderTileSize, region.x1),
                                    std::min(y0 + kRenderTileSize, region.y1)});
      },
      progress);
}

}  // namespace render
