#include "tools/sfbuild/progressive_render.h"

#include <algorithm>
#include <exception>
#include <optional>
#include <utility>

#include "renderer/image.h"

namespace sfbuild {

std::vector<RenderLevel> defaultRenderLevels() {
  return {{8, 1, 0.0}, {4, 1, 0.0}, {2, 1, 0.0}, {1, 1, 0.0}, {1, 16, 0.03}};
}

namespace {

// The settings of one level of a job's render: its size and sampling.
render::RenderSettings levelSettings(const render::RenderSettings& job, const RenderLevel& level) {
  render::RenderSettings settings = job;
  int divisor = std::max(level.divisor, 1);
  settings.width = std::max(1, (job.width + divisor - 1) / divisor);
  settings.height = std::max(1, (job.height + divisor - 1) / divisor);
  settings.samplesPerPixel = level.samplesPerPixel;
  settings.adaptiveThreshold = level.adaptiveThreshold;
  return settings;
}

}  // namespace

ProgressiveRender::ProgressiveRender(std::vector<RenderLevel> levels, int threads)
    : levels_(std::move(levels)), threads_(threads), worker_([this] { run(); }) {}

ProgressiveRender::~ProgressiveRender() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    if (cancel_) cancel_->request();
  }
  wake_.notify_one();
  worker_.join();
}

void ProgressiveRender::start(scene::Scene scene, const render::RenderSettings& settings) {
  {
    std::lock_guard lock(mutex_);
    ++generation_;
    if (cancel_) cancel_->request();
    pending_ = Job{std::move(scene), settings, generation_};
    slot_.reset();
  }
  wake_.notify_one();
}

void ProgressiveRender::stop() {
  std::lock_guard lock(mutex_);
  ++generation_;
  if (cancel_) cancel_->request();
  pending_.reset();
  slot_.reset();
}

std::optional<RenderedFrame> ProgressiveRender::takeFrame() {
  std::lock_guard lock(mutex_);
  std::optional<RenderedFrame> frame = std::move(slot_);
  slot_.reset();
  return frame;
}

std::uint64_t ProgressiveRender::cancelledRenders() const {
  std::lock_guard lock(mutex_);
  return cancelled_;
}

void ProgressiveRender::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return quit_ || pending_.has_value(); });
      if (quit_) return;
      job = std::move(*pending_);
      pending_.reset();
      cancel_ = std::make_shared<render::CancelFlag>();
    }
    renderJob(job);
  }
}

void ProgressiveRender::renderJob(const Job& job) {
  std::shared_ptr<render::CancelFlag> cancel;
  {
    std::lock_guard lock(mutex_);
    cancel = cancel_;
  }
  auto cancelled = [&] {
    std::lock_guard lock(mutex_);
    ++cancelled_;
  };
  try {
    // Building the BVH cannot be cancelled: a scene of 100,000 objects
    // takes tens of milliseconds, during which a newer job waits. Its kind
    // is the one sfrender chooses for the last level's image, so that the
    // last image is sfrender's.
    std::optional<std::uint64_t> imageSamples;
    if (!levels_.empty()) {
      imageSamples = render::fullImageSampleCount(levelSettings(job.settings, levels_.back()));
    }
    render::RenderScene compiled(job.scene, 0, true, imageSamples);
    for (std::size_t i = 0; i < levels_.size(); ++i) {
      if (cancel->requested()) return cancelled();
      const RenderLevel& level = levels_[i];
      render::RenderSettings settings = levelSettings(job.settings, level);
      settings.threads = threads_;
      render::Image image = render::renderImage(compiled, settings, nullptr, {}, cancel.get());
      RenderedFrame frame;
      frame.width = image.width;
      frame.height = image.height;
      frame.rgb.resize(image.rgb.size());
      render::eightBitLevels(image.rgb.data(), image.rgb.size(), frame.rgb.data());
      frame.level = static_cast<int>(i);
      frame.levelCount = static_cast<int>(levels_.size());
      frame.settings = level;
      frame.generation = job.generation;
      if (!deliver(std::move(frame))) return cancelled();
    }
  } catch (const render::RenderCancelled&) {
    cancelled();
  } catch (const std::exception& e) {
    // Out of memory, or threads that would not start: said in the status
    // line instead of a picture.
    RenderedFrame failure;
    failure.generation = job.generation;
    failure.levelCount = static_cast<int>(levels_.size());
    failure.error = e.what();
    deliver(std::move(failure));
  }
}

bool ProgressiveRender::deliver(RenderedFrame frame) {
  std::lock_guard lock(mutex_);
  if (frame.generation != generation_) return false;
  slot_ = std::move(frame);
  return true;
}

}  // namespace sfbuild
