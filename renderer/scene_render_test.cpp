// The public render API (scenefile/render.h): the renderer's image for the
// same settings, its progress, a stop, and the two value conversions.
#include <gtest/gtest.h>

#include <stop_token>

#include "renderer/default_scene.h"
#include "renderer/render.h"
#include "scenefile/render.h"

namespace scene {
namespace {

RenderSettings small() {
  RenderSettings settings;
  settings.width = 48;
  settings.height = 32;
  settings.samplesPerPixel = 4;
  settings.seed = 5;
  settings.threads = 2;
  return settings;
}

TEST(SceneRender, IsTheRenderersImageForTheSameSettings) {
  RenderSettings settings = small();
  render::RenderSettings full;
  static_cast<RenderSettings&>(full) = settings;
  render::Image expected = render::renderImage(render::RenderScene(render::defaultScene()), full);
  int calls = 0;
  int last = -1;
  RenderControl control;
  control.progress = [&](int done, int total) {
    ++calls;
    last = done == total ? total : -1;
  };
  RenderedImage image = renderScene(render::defaultScene(), settings, control);
  EXPECT_EQ(image.width, 48);
  EXPECT_EQ(image.height, 32);
  EXPECT_EQ(image.rgb, expected.rgb);
  EXPECT_GT(calls, 0);
  EXPECT_GT(last, 0);
}

TEST(SceneRender, AStopRequestedThrowsRenderCancelled) {
  std::stop_source stop;
  stop.request_stop();
  RenderControl control;
  control.stop = stop.get_token();
  EXPECT_THROW(renderScene(render::defaultScene(), small(), control), RenderCancelled);
}

TEST(SceneRender, LevelsAndLinearValuesAreTheRenderersConversions) {
  RenderedImage image;
  image.width = 2;
  image.height = 1;
  image.rgb = {0.0f, 0.5f, 1.0f, -1.0f, 2.0f, 0.2f};
  EXPECT_EQ(eightBitLevels(image), (std::vector<std::uint8_t>{0, 128, 255, 0, 255, 51}));
  std::vector<float> linear = linearValues(image);
  ASSERT_EQ(linear.size(), 6u);
  EXPECT_FLOAT_EQ(linear[2], 1.0f);
  EXPECT_NEAR(linear[1], 0.21404f, 1e-4);
  EXPECT_FLOAT_EQ(linear[3], -1.0f);
}

TEST(SceneRender, TheScenesViewFillsWhatTheCallerLeavesOpen) {
  Scene withView;
  withView.view = View{};
  withView.view->verticalFovDegrees = 45.0;
  withView.view->aspectRatio = 2.0;
  RenderSettings settings;  // 640 x 480 at 60 degrees
  applySceneView(withView, std::nullopt, std::nullopt, false, settings);
  EXPECT_EQ(settings.verticalFovDegrees, 45.0);
  EXPECT_EQ(settings.width, 640);
  EXPECT_EQ(settings.height, 320);
  RenderSettings given;
  applySceneView(withView, 100, 100, true, given);
  EXPECT_EQ(given.verticalFovDegrees, 60.0);
  EXPECT_EQ(given.height, 480);
  RenderSettings untouched;
  applySceneView(Scene{}, std::nullopt, std::nullopt, false, untouched);
  EXPECT_EQ(untouched.height, 480);
}

}  // namespace
}  // namespace scene
