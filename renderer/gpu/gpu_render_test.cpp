// The GPU path against the CPU's on scenes with reflection, refraction
// (nested solids, a camera inside glass), several lights and samples, and
// regions: at least 99.9% of the channels within 1/255, and the number
// identical reported. Runs on any Vulkan device with doubles (lavapipe where
// no GPU is present), skips where there is none.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "renderer/default_scene.h"
#include "renderer/gpu/gpu_scene.h"
#include "renderer/render.h"
#include "renderer/test_scenes.h"

namespace render {
namespace {

using scene::ObjectKind;
using namespace render::testing;

bool skipWithoutGpu() {
  GpuProbe probe = probeGpu();
  if (!probe.available) std::printf("no Vulkan device: %s\n", probe.reason.c_str());
  return !probe.available;
}

// Compares the two images channel by channel.
void expectClose(const Image& gpu, const Image& cpu, const char* what) {
  ASSERT_EQ(gpu.width, cpu.width);
  ASSERT_EQ(gpu.height, cpu.height);
  ASSERT_EQ(gpu.originX, cpu.originX);
  ASSERT_EQ(gpu.originY, cpu.originY);
  ASSERT_EQ(gpu.rgb.size(), cpu.rgb.size());
  ASSERT_EQ(gpu.coverage.size(), cpu.coverage.size());
  std::size_t identical = 0, close = 0;
  for (std::size_t k = 0; k < gpu.rgb.size(); ++k) {
    identical += gpu.rgb[k] == cpu.rgb[k] ? 1 : 0;
    close += std::abs(gpu.rgb[k] - cpu.rgb[k]) <= 1.0f / 255.0f ? 1 : 0;
  }
  std::printf("[ gpu ] %-34s %zu of %zu channels identical, %zu within 1/255\n", what, identical,
              gpu.rgb.size(), close);
  EXPECT_GE(static_cast<double>(close), 0.999 * static_cast<double>(gpu.rgb.size())) << what;
  for (std::size_t k = 0; k < gpu.coverage.size(); ++k) {
    EXPECT_EQ(gpu.coverage[k], cpu.coverage[k]) << what << ", pixel " << k;
  }
}

Image renderOn(const scene::Scene& s, RenderSettings settings, RenderDevice device) {
  settings.device = device;
  RenderScene compiled(s);
  return renderImage(compiled, settings);
}

void compareDevices(const scene::Scene& s, const RenderSettings& settings, const char* what) {
  expectClose(renderOn(s, settings, RenderDevice::Gpu), renderOn(s, settings, RenderDevice::Cpu),
              what);
}

// Glass spheres, one inside another, a mirror cube, a cylinder and a floor
// plane that is partly transparent, lit by two lights.
scene::Scene glassScene() {
  scene::Scene s = sceneLookingAt({0.5, 2.0, 7.0}, {0.0, 0.5, 0.0});
  scene::Material glass;
  glass.colour = {0.9, 0.95, 1.0};
  glass.transparency = 0.8;
  glass.reflectivity = 0.3;
  glass.ri = 1.5;
  scene::Material inner = glass;
  inner.ri = 1.33;
  inner.reflectivity = 0.0;
  scene::Material mirror;
  mirror.colour = {0.8, 0.3, 0.3};
  mirror.reflectivity = 0.6;
  mirror.shininess = 37.5;  // not a whole number: the single-precision pow
  scene::Material floor;
  floor.colour = {0.4, 0.8, 0.4};
  floor.transparency = 0.3;
  floor.reflectivity = 0.2;
  s.objects.push_back(object(ObjectKind::Sphere, {translate(0, 1, 0)}, glass));
  s.objects.push_back(object(ObjectKind::Sphere, {scale(0.5), translate(0, 1, 0)}, inner));
  s.objects.push_back(object(ObjectKind::Cube, {rotateY(0.5), translate(2.2, 0.7, -1)}, mirror));
  s.objects.push_back(
      object(ObjectKind::Cylinder, {scale(0.5, 1.0, 0.5), translate(-2.2, 1, -0.5)}, mirror));
  s.objects.push_back(object(ObjectKind::Plane, {}, floor));
  s.lights.push_back(light({4, 6, 5}));
  s.lights.push_back(light({-5, 3, 2}, {0.4, 0.4, 0.6}));
  return s;
}

TEST(GpuRender, DefaultSceneMatchesTheCpu) {
  if (skipWithoutGpu()) GTEST_SKIP();
  RenderSettings settings;
  settings.width = 96;
  settings.height = 72;
  compareDevices(defaultScene(), settings, "default scene");
}

TEST(GpuRender, GlassAndMirrorsWithSamplesMatchTheCpu) {
  if (skipWithoutGpu()) GTEST_SKIP();
  RenderSettings settings;
  settings.width = 48;
  settings.height = 36;
  settings.samplesPerPixel = 4;
  settings.seed = 7;
  settings.maxDepth = 6;
  settings.coverage = true;
  compareDevices(glassScene(), settings, "glass, 4 spp, depth 6");
}

TEST(GpuRender, CameraInsideGlassMatchesTheCpu) {
  if (skipWithoutGpu()) GTEST_SKIP();
  scene::Scene s = glassScene();
  s.camera.matrix = scene::cameraFromLookAt({0.1, 1.1, 0.2}, {2.2, 0.7, -1});
  RenderSettings settings;
  settings.width = 40;
  settings.height = 30;
  compareDevices(s, settings, "camera inside two spheres");
}

TEST(GpuRender, RegionIsThoseOfTheFullImage) {
  if (skipWithoutGpu()) GTEST_SKIP();
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.region = PixelRegion{10, 7, 41, 30};
  Image region = renderOn(glassScene(), settings, RenderDevice::Gpu);
  compareDevices(glassScene(), settings, "region 10,7,41,30");
  settings.region = PixelRegion{};
  Image full = renderOn(glassScene(), settings, RenderDevice::Gpu);
  ASSERT_EQ(region.width, 31);
  ASSERT_EQ(region.height, 23);
  for (int j = 0; j < region.height; ++j) {
    for (int i = 0; i < region.width; ++i) {
      EXPECT_EQ(region.pixel(i, j), full.pixel(i + 10, j + 7)) << i << ", " << j;
    }
  }
}

// Renders through one device the caller keeps open give the images of
// renders that open their own, and Auto asks that device, not a probe,
// whether it is a real GPU.
TEST(GpuRender, OneDeviceServesManyRenders) {
  if (skipWithoutGpu()) GTEST_SKIP();
  GpuDevice device;
  RenderSettings settings;
  settings.width = 48;
  settings.height = 36;
  settings.samplesPerPixel = 2;
  settings.maxDepth = 6;
  Image alone = renderOn(glassScene(), settings, RenderDevice::Gpu);
  settings.gpu = &device;
  for (int k = 0; k < 3; ++k) {
    Image shared = renderOn(glassScene(), settings, RenderDevice::Gpu);
    EXPECT_EQ(shared.rgb, alone.rgb) << "render " << k;
  }
  settings.device = RenderDevice::Auto;
  settings.threads = 1;
  settings.width = 1000;
  settings.height = 1000;
  EXPECT_EQ(chooseDevice(settings), device.isCpu() ? RenderDevice::Cpu : RenderDevice::Gpu);
}

// The packed scene's arrays follow one another in one staging buffer, and
// each starts aligned for its type: the glass scene's planes are an odd
// count of 4-byte words, which put the lights' doubles off their alignment
// when they came last.
TEST(GpuScene, LayoutAlignsEachArrayForItsType) {
  RenderScene compiled(glassScene());
  gpu::GpuSceneLayout layout = gpu::layoutOf(compiled);
  ASSERT_EQ(layout.planes.bytes, 4u);
  const gpu::GpuSceneLayout::Part* order[] = {&layout.objects, &layout.lights, &layout.nodes,
                                              &layout.planes};
  VkDeviceSize at = 0;
  for (const gpu::GpuSceneLayout::Part* part : order) {
    EXPECT_EQ(part->offset, at);
    at += part->bytes;
  }
  EXPECT_EQ(layout.bytes, at);
  EXPECT_EQ(layout.objects.offset % alignof(double), 0u);
  EXPECT_EQ(layout.lights.offset % alignof(double), 0u);
  EXPECT_EQ(layout.lights.bytes, 2 * 6 * sizeof(double));
  EXPECT_EQ(layout.nodes.offset % alignof(std::uint32_t), 0u);
  EXPECT_EQ(layout.planes.offset % alignof(std::uint32_t), 0u);
}

TEST(GpuRender, AdaptiveSamplingIsRefused) {
  RenderSettings settings;
  settings.width = 8;
  settings.height = 8;
  settings.samplesPerPixel = 4;
  settings.adaptiveThreshold = 0.03;
  settings.device = RenderDevice::Gpu;
  RenderScene compiled(defaultScene());
  EXPECT_THROW(renderImage(compiled, settings), DeviceUnavailable);
}

TEST(GpuRender, AutoStaysOnTheCpuForSmallImages) {
  RenderSettings settings;
  settings.width = 100;
  settings.height = 100;
  settings.device = RenderDevice::Auto;
  EXPECT_EQ(chooseDevice(settings), RenderDevice::Cpu);
  settings.device = RenderDevice::Gpu;
  EXPECT_EQ(chooseDevice(settings), RenderDevice::Gpu);
}

// The threshold counts samples for each CPU thread: 1920x1080 at 1 spp
// (2,073,600 samples) is worth a GPU against 2 threads, not against 4, and
// 2 samples a pixel make it worth one against 4 again, not against 5.
TEST(GpuRender, AutoWeighsSamplesAgainstTheCpuThreads) {
  RenderSettings settings;
  settings.width = 1920;
  settings.height = 1080;
  settings.device = RenderDevice::Auto;
  settings.threads = 2;
  EXPECT_TRUE(autoPrefersGpu(settings));
  settings.threads = 4;
  EXPECT_FALSE(autoPrefersGpu(settings));
  EXPECT_EQ(chooseDevice(settings), RenderDevice::Cpu);
  settings.samplesPerPixel = 2;
  EXPECT_TRUE(autoPrefersGpu(settings));
  settings.threads = 5;
  EXPECT_FALSE(autoPrefersGpu(settings));
  // Adaptive sampling stays on the CPU at any count.
  settings.threads = 1;
  settings.samplesPerPixel = 16;
  settings.adaptiveThreshold = 0.03;
  EXPECT_FALSE(autoPrefersGpu(settings));
  // Past the threshold the choice is the probe's: a real GPU, else the CPU
  // (lavapipe does not count).
  settings.adaptiveThreshold = 0.0;
  RenderDevice expected = probeGpu(false).available ? RenderDevice::Gpu : RenderDevice::Cpu;
  EXPECT_EQ(chooseDevice(settings), expected);
}

}  // namespace
}  // namespace render
