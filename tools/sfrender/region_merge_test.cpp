#include "tools/sfrender/region_merge.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <random>
#include <string>

#include "tools/sfrender/image_file.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

// The smallest float whose level (quantize) is `level`.
template <typename Quantize>
float firstOfLevel(int level, Quantize quantize) {
  float low = 0.0f, high = 1.0f;
  while (std::nextafter(low, 2.0f) < high) {
    float middle = low + (high - low) / 2;
    if (static_cast<int>(quantize(middle)) >= level) {
      high = middle;
    } else {
      low = middle;
    }
  }
  return static_cast<int>(quantize(low)) >= level ? low : high;
}

// The float just below the first of a level, and that first float, decode
// to the same linear value at a few of the 8-bit boundaries: where the sRGB
// curve is linear (up to 0.04045), dividing by 12.92 brings floats closer
// than the float spacing there. Only those two floats are ambiguous: the
// level of any other linear value is known exactly, and the one found is
// the upper of the two (docs/SCALING.md, "Exactness").
TEST(DisplayFromLinear, FewLevelBoundariesDecodeTogether) {
  int together8 = 0, together16 = 0;
  for (int level = 1; level <= 255; ++level) {
    float first = firstOfLevel(level, quantizeChannel);
    float below = std::nextafter(first, 0.0f);
    bool together = srgbToLinear(below) == srgbToLinear(first);
    together8 += together ? 1 : 0;
    ASSERT_LT(srgbToLinear(std::nextafter(below, 0.0f)), srgbToLinear(first)) << level;
    EXPECT_EQ(quantizeChannel(displayFromLinear(srgbToLinear(first))),
              together ? level - 1 : level);
    EXPECT_EQ(quantizeChannel(displayFromLinear(srgbToLinear(std::nextafter(first, 1.0f)))), level);
  }
  for (int level = 1; level <= 65535; ++level) {
    float first = firstOfLevel(level, quantizeChannel16);
    if (srgbToLinear(std::nextafter(first, 0.0f)) == srgbToLinear(first)) ++together16;
  }
  std::cout << "boundaries where two floats decode together: " << together8 << " of 255 (8 bits), "
            << together16 << " of 65535 (16 bits)\n";
  EXPECT_LT(together8, 255);
}

TEST(DisplayFromLinear, GivesBackTheLinearValueAndTheLevels) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> value(-0.5f, 2.0f);
  for (int i = 0; i < 200000; ++i) {
    float display = value(random);
    float linear = srgbToLinear(display);
    float back = displayFromLinear(linear);
    ASSERT_EQ(srgbToLinear(back), linear) << display;
    ASSERT_EQ(quantizeChannel(back), quantizeChannel(display)) << display;
    ASSERT_EQ(quantizeChannel16(back), quantizeChannel16(display)) << display;
  }
  EXPECT_EQ(displayFromLinear(0.0f), 0.0f);
  EXPECT_EQ(displayFromLinear(std::numeric_limits<float>::quiet_NaN()), 0.0f);
  float largest = std::numeric_limits<float>::max();
  EXPECT_EQ(srgbToLinear(displayFromLinear(largest)), largest);
}

render::Image gradient(int width, int height) {
  render::Image image;
  image.width = width;
  image.height = height;
  for (int p = 0; p < width * height; ++p) {
    for (int c = 0; c < 3; ++c) image.rgb.push_back(0.37f * c + 0.0123f * p - 0.1f);
  }
  return image;
}

render::Image rows(const render::Image& whole, int y0, int y1) {
  render::Image region;
  region.width = whole.width;
  region.height = y1 - y0;
  region.originY = y0;
  region.fullWidth = whole.width;
  region.fullHeight = whole.height;
  region.rgb.assign(whole.rgb.begin() + 3 * whole.width * y0,
                    whole.rgb.begin() + 3 * whole.width * y1);
  return region;
}

class MergeRegions : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("region_merge_test_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path write(const render::Image& image, const std::string& name) {
    std::string error;
    EXPECT_TRUE(writeImageFile(image, folder_ / name, error)) << error;
    return folder_ / name;
  }
  fs::path folder_;
};

TEST_F(MergeRegions, GivesTheWholeImageInEveryFormat) {
  render::Image whole = gradient(7, 5);
  std::vector<fs::path> parts = {write(rows(whole, 3, 5), "c.exr"),
                                 write(rows(whole, 0, 2), "a.exr"),
                                 write(rows(whole, 2, 3), "b.exr")};
  std::string error;
  std::optional<render::Image> merged = mergeImageRegions(parts, error);
  ASSERT_TRUE(merged) << error;
  ASSERT_EQ(merged->width, 7);
  ASSERT_EQ(merged->height, 5);
  EXPECT_EQ(ppmImageBytes(*merged), ppmImageBytes(whole));
  EXPECT_EQ(ppmImageBytes(*merged, {16, false}), ppmImageBytes(whole, {16, false}));
  ImageRegionFile once, again;
  ASSERT_TRUE(readImageRegion(write(whole, "whole.exr"), once, error)) << error;
  ASSERT_TRUE(readImageRegion(write(*merged, "merged.exr"), again, error)) << error;
  EXPECT_EQ(once.rgb, again.rgb);
  EXPECT_EQ(again.region.width, 7);
  EXPECT_EQ(again.region.fullHeight, 5);
}

TEST_F(MergeRegions, WritesTheDataAndDisplayWindows) {
  ImageRegionFile file;
  std::string error;
  ASSERT_TRUE(readImageRegion(write(rows(gradient(7, 5), 2, 4), "r.exr"), file, error)) << error;
  EXPECT_EQ(file.region.x, 0);
  EXPECT_EQ(file.region.y, 2);
  EXPECT_EQ(file.region.width, 7);
  EXPECT_EQ(file.region.height, 2);
  EXPECT_EQ(file.region.fullWidth, 7);
  EXPECT_EQ(file.region.fullHeight, 5);
}

TEST_F(MergeRegions, RefusesAGapAMismatchAndHalves) {
  render::Image whole = gradient(7, 5);
  std::string error;
  EXPECT_FALSE(mergeImageRegions(
      {write(rows(whole, 0, 2), "a.exr"), write(rows(whole, 3, 5), "c.exr")}, error));
  EXPECT_EQ(error, "no region holds pixel 0,2 of the 7x5 image");
  EXPECT_FALSE(
      mergeImageRegions({folder_ / "a.exr", write(rows(gradient(7, 6), 2, 6), "d.exr")}, error));
  EXPECT_NE(error.find("is a region of a 7x6 at 0,0 image"), std::string::npos) << error;
  std::string halfName = "h.exr";
  ASSERT_TRUE(writeImageFile(rows(whole, 2, 5), folder_ / halfName, error, {16, false}));
  EXPECT_FALSE(mergeImageRegions({folder_ / "a.exr", folder_ / halfName}, error));
  EXPECT_NE(error.find("holds 16-bit floating-point values"), std::string::npos) << error;
}

}  // namespace
}  // namespace tools
