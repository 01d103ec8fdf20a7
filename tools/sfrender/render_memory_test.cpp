#include "tools/sfrender/render_memory.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace tools {
namespace {

TEST(RenderMemory, ImageGrowsWithThePixelsAndSceneAndBvhWithTheObjects) {
  RenderMemoryEstimate empty = estimateRenderMemory(0, 0, 1, 1);
  EXPECT_EQ(empty.scene, 0u);
  EXPECT_EQ(empty.bvh, 0u);
  EXPECT_GT(empty.image, 0u);

  RenderMemoryEstimate small = estimateRenderMemory(10, 1, 640, 480);
  RenderMemoryEstimate big = estimateRenderMemory(1'000'000, 1, 640, 480);
  EXPECT_EQ(small.image, big.image);
  EXPECT_EQ(estimateRenderMemory(2000, 0, 1, 1).scene,
            2 * estimateRenderMemory(1000, 0, 1, 1).scene);
  EXPECT_EQ(estimateRenderMemory(2000, 0, 1, 1).bvh, 2 * estimateRenderMemory(1000, 0, 1, 1).bvh);
  // At least the float image, and each object's matrices (two 4x4 and 3x3
  // doubles, more than 200 bytes).
  EXPECT_GE(small.image, 640u * 480 * 12);
  EXPECT_GE(big.scene, 1'000'000u * 200);
  EXPECT_GT(big.bvh, small.bvh);
  EXPECT_EQ(big.total(), big.image + big.scene + big.bvh);

  RenderMemoryEstimate wide = estimateRenderMemory(10, 1, 1280, 960);
  EXPECT_EQ(wide.image, 4 * small.image);
}

TEST(RenderMemory, HugeCountsSaturateInsteadOfWrapping) {
  RenderMemoryEstimate e = estimateRenderMemory(UINT64_MAX / 2, UINT64_MAX / 2, 32768, 32768);
  EXPECT_EQ(e.scene, UINT64_MAX);
  EXPECT_EQ(e.bvh, UINT64_MAX);
  EXPECT_EQ(e.total(), UINT64_MAX);
  EXPECT_TRUE(renderMemoryRefusal(e, std::uint64_t{1} << 40).has_value());
}

TEST(RenderMemory, ReadsMemAvailableInKibibytes) {
  const char* meminfo =
      "MemTotal:       131072000 kB\n"
      "MemFree:         1000000 kB\n"
      "MemAvailable:    2048000 kB\n"
      "Buffers:           12345 kB\n";
  EXPECT_EQ(parseMemAvailable(meminfo), std::uint64_t{2048000} * 1024);
  EXPECT_EQ(parseMemAvailable("MemTotal: 10 kB\n"), std::nullopt);
  EXPECT_EQ(parseMemAvailable("MemAvailable: lots\n"), std::nullopt);
  EXPECT_EQ(parseMemAvailable("NotMemAvailable: 5 kB\n"), std::nullopt);
}

TEST(RenderMemory, RefusesOnlyWhatDoesNotFitAndSaysBothFigures) {
  RenderMemoryEstimate e = estimateRenderMemory(1000, 2, 640, 480);
  EXPECT_EQ(renderMemoryRefusal(e, e.total()), std::nullopt);
  EXPECT_EQ(renderMemoryRefusal(e, std::nullopt), std::nullopt);  // unknown: not refused
  std::optional<std::string> refusal = renderMemoryRefusal(e, 1000);
  ASSERT_TRUE(refusal.has_value());
  EXPECT_EQ(refusal->rfind("the render needs about ", 0), 0u) << *refusal;
  EXPECT_NE(refusal->find("(image 7 MiB, scene "), std::string::npos) << *refusal;
  EXPECT_NE(refusal->find("only 1000 bytes of memory is available"), std::string::npos) << *refusal;
}

}  // namespace
}  // namespace tools
