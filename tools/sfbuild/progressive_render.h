// The ray-traced view's renders (T): the renderer draws the builder's scene
// on a thread of its own, coarse first, then finer, each level handed over
// as 8-bit levels the way sfrender's PNG and PPM writer stores them. A new
// scene or size cancels the render under way (render::CancelFlag) and
// starts again, without waiting for it: the window never waits for a
// render.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "renderer/render.h"
#include "scenefile/scene.h"

namespace sfbuild {

// One level of the progression: the image at 1/divisor of the size asked
// for (each side rounded up), with these samples.
struct RenderLevel {
  int divisor = 1;
  int samplesPerPixel = 1;
  double adaptiveThreshold = 0.0;
};

// 1/8, 1/4 and 1/2 of the size at 1 spp, the full size at 1 spp, then the
// full size at 16 spp with --adaptive 0.03: the first image of 640x480 is
// 80x60, 77 times fewer rays than the last.
std::vector<RenderLevel> defaultRenderLevels();

// A finished level, 8 bits a channel, rows from the top.
struct RenderedFrame {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgb;
  int level = 0;  // 0 is the first (coarsest)
  int levelCount = 0;
  RenderLevel settings;
  // Which start() it belongs to: a frame of an older one is never handed over.
  std::uint64_t generation = 0;
  // Why the render failed (out of memory, no threads), with no picture.
  std::string error;
  bool last() const { return level + 1 == levelCount; }
};

class ProgressiveRender {
 public:
  // `threads` as RenderSettings::threads (0: every core).
  explicit ProgressiveRender(std::vector<RenderLevel> levels = defaultRenderLevels(),
                             int threads = 0);
  // Cancels the render under way and joins the thread.
  ~ProgressiveRender();
  ProgressiveRender(const ProgressiveRender&) = delete;
  ProgressiveRender& operator=(const ProgressiveRender&) = delete;

  // Renders `scene` as `settings` say (the size, the field of view, the
  // depth), level by level; cancels the render under way, if any. Returns
  // at once: the thread takes the new job when the old one has stopped
  // (within a row of pixels).
  void start(scene::Scene scene, const render::RenderSettings& settings);
  // Cancels the render under way, and forgets any frame not taken.
  void stop();
  // The newest finished level of the last start() not taken yet, if any.
  std::optional<RenderedFrame> takeFrame();
  // Renders cancelled before their last level (a test's window into the
  // restart).
  std::uint64_t cancelledRenders() const;

 private:
  struct Job {
    scene::Scene scene;
    render::RenderSettings settings;
    std::uint64_t generation = 0;
  };
  void run();
  void renderJob(const Job& job);
  // Hands a level over; false once the job has been superseded.
  bool deliver(RenderedFrame frame);

  std::vector<RenderLevel> levels_;
  int threads_ = 0;

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Job> pending_;         // the next job, guarded by mutex_
  std::optional<RenderedFrame> slot_;  // the newest frame, guarded by mutex_
  std::uint64_t generation_ = 0;       // of the last start() or stop()
  std::uint64_t cancelled_ = 0;
  bool quit_ = false;
  // The running job's flag: a CancelFlag stays set once set, so each job
  // gets a new one; replaced only under mutex_.
  std::shared_ptr<render::CancelFlag> cancel_;
  // Last, so that it starts once everything above is ready.
  std::thread worker_;
};

}  // namespace sfbuild
