// ProgressiveRender: every level arrives, the last one is sfrender's image
// to the level, and a restart cancels the render under way.
#include "tools/sfbuild/progressive_render.h"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <thread>

#include "renderer/default_scene.h"

namespace sfbuild {
namespace {

using Clock = std::chrono::steady_clock;

render::RenderSettings sized(int width, int height) {
  render::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  return settings;
}

// Frames as they come, until `done` says so or `limit` passes.
template <typename Done>
std::vector<RenderedFrame> framesUntil(ProgressiveRender& renders, Done done,
                                       std::chrono::milliseconds limit) {
  std::vector<RenderedFrame> frames;
  auto end = Clock::now() + limit;
  while (Clock::now() < end) {
    if (std::optional<RenderedFrame> frame = renders.takeFrame()) {
      frames.push_back(std::move(*frame));
      if (done(frames.back())) break;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  return frames;
}

TEST(ProgressiveRender, FinishesWithTheImageSfrenderWrites) {
  std::vector<RenderLevel> levels = {{4, 1, 0.0}, {1, 1, 0.0}, {1, 4, 0.03}};
  ProgressiveRender renders(levels, 2);
  renders.start(render::defaultScene(), sized(64, 48));
  std::vector<RenderedFrame> frames = framesUntil(
      renders, [](const RenderedFrame& f) { return f.last(); }, std::chrono::seconds(60));
  ASSERT_FALSE(frames.empty());
  const RenderedFrame& last = frames.back();
  ASSERT_TRUE(last.last()) << "the render never finished";
  EXPECT_TRUE(last.error.empty()) << last.error;
  EXPECT_EQ(last.width, 64);
  EXPECT_EQ(last.height, 48);
  EXPECT_EQ(last.settings.samplesPerPixel, 4);
  // Levels come in order (one may be overtaken by the next before it is taken).
  for (std::size_t i = 1; i < frames.size(); ++i) EXPECT_LT(frames[i - 1].level, frames[i].level);
  if (frames.front().level == 0) {
    EXPECT_EQ(frames.front().width, 16);
    EXPECT_EQ(frames.front().height, 12);
  }

  render::RenderSettings settings = sized(64, 48);
  settings.samplesPerPixel = 4;
  settings.adaptiveThreshold = 0.03;
  render::Image image = render::renderImage(render::RenderScene(render::defaultScene()), settings);
  ASSERT_EQ(last.rgb.size(), image.rgb.size());
  std::size_t lit = 0;
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    ASSERT_EQ(last.rgb[i], render::eightBitLevel(image.rgb[i])) << "channel " << i;
    lit += last.rgb[i] > 0;
  }
  EXPECT_GT(lit, image.rgb.size() / 4);  // the default scene, not a black image
}

TEST(ProgressiveRender, ARestartCancelsTheRenderUnderWay) {
  // A last level far too slow to finish within the test.
  std::vector<RenderLevel> levels = {{8, 1, 0.0}, {1, 4096, 0.0}};
  ProgressiveRender renders(levels, 2);
  renders.start(render::defaultScene(), sized(320, 240));
  std::vector<RenderedFrame> first = framesUntil(
      renders, [](const RenderedFrame&) { return true; }, std::chrono::seconds(30));
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].level, 0);
  std::uint64_t firstGeneration = first[0].generation;
  EXPECT_EQ(renders.cancelledRenders(), 0u);

  scene::Scene emptied = render::defaultScene();
  emptied.objects.clear();
  renders.start(emptied, sized(320, 240));
  std::vector<RenderedFrame> second = framesUntil(
      renders, [](const RenderedFrame&) { return true; }, std::chrono::seconds(30));
  ASSERT_EQ(second.size(), 1u);
  EXPECT_GT(second[0].generation, firstGeneration);
  EXPECT_EQ(second[0].level, 0);
  // No objects: black, where the first showed the default scene.
  for (unsigned char level : second[0].rgb) ASSERT_EQ(level, 0);
  EXPECT_EQ(renders.cancelledRenders(), 1u);
  // The destructor cancels the second render's slow level and joins.
}

TEST(ProgressiveRender, StopForgetsTheFrameNotTaken) {
  ProgressiveRender renders({{1, 1, 0.0}}, 1);
  renders.start(render::defaultScene(), sized(8, 6));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // 48 pixels: long done
  renders.stop();
  EXPECT_FALSE(renders.takeFrame().has_value());
  // Untaken, the same render's frame is there.
  renders.start(render::defaultScene(), sized(8, 6));
  std::vector<RenderedFrame> frames = framesUntil(
      renders, [](const RenderedFrame&) { return true; }, std::chrono::seconds(30));
  EXPECT_EQ(frames.size(), 1u);
}

// The first image of 640x480 comes within a generous bound (the real time,
// printed, is in docs/TOOLS.md): a restart with the coarsest level first.
TEST(ProgressiveRender, TheFirstImageComesQuickly) {
  ProgressiveRender renders;
  auto begin = Clock::now();
  renders.start(render::defaultScene(), sized(640, 480));
  std::vector<RenderedFrame> frames = framesUntil(
      renders, [](const RenderedFrame&) { return true; }, std::chrono::seconds(10));
  auto elapsed = std::chrono::duration<double, std::milli>(Clock::now() - begin).count();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].width, 80);
  EXPECT_EQ(frames[0].height, 60);
  std::cout << "first image of 640x480 (the default scene) after " << elapsed << " ms\n";
  EXPECT_LT(elapsed, 1000.0);
}

}  // namespace
}  // namespace sfbuild
