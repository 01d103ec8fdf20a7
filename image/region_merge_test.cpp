#include "image/region_merge.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "image/image_file.h"
#include "tools/common/file_io.h"

namespace image {
namespace {

namespace fs = std::filesystem;

// sfrender's default --max-pixels.
constexpr std::int64_t kLimit = std::int64_t{8192} * 8192;

// The smallest float whose level (`quantize`) is `level`.
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
    float first = firstOfLevel(level, render::eightBitLevel);
    float below = std::nextafter(first, 0.0f);
    bool together = srgbToLinear(below) == srgbToLinear(first);
    together8 += together ? 1 : 0;
    ASSERT_LT(srgbToLinear(std::nextafter(below, 0.0f)), srgbToLinear(first)) << level;
    EXPECT_EQ(render::eightBitLevel(displayFromLinear(srgbToLinear(first))),
              together ? level - 1 : level);
    EXPECT_EQ(render::eightBitLevel(displayFromLinear(srgbToLinear(std::nextafter(first, 1.0f)))),
              level);
  }
  for (int level = 1; level <= 65535; ++level) {
    float first = firstOfLevel(level, render::sixteenBitLevel);
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
    ASSERT_EQ(render::eightBitLevel(back), render::eightBitLevel(display)) << display;
    ASSERT_EQ(render::sixteenBitLevel(back), render::sixteenBitLevel(display)) << display;
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

// Why the files do not merge; empty when they do.
std::string mergeFailure(const std::vector<fs::path>& files, std::int64_t maxPixels) {
  tools::Outcome<render::Image> merged = mergeImageRegions(files, maxPixels);
  return merged ? "" : merged.failure().message;
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
    tools::MaybeFailure failure = writeImageFile(image, folder_ / name);
    EXPECT_FALSE(failure) << failure->message;
    return folder_ / name;
  }
  fs::path folder_;
};

TEST_F(MergeRegions, GivesTheWholeImageInEveryFormat) {
  render::Image whole = gradient(7, 5);
  std::vector<fs::path> parts = {write(rows(whole, 3, 5), "c.exr"),
                                 write(rows(whole, 0, 2), "a.exr"),
                                 write(rows(whole, 2, 3), "b.exr")};
  tools::Outcome<render::Image> merged = mergeImageRegions(parts, kLimit);
  ASSERT_TRUE(merged) << merged.failure().message;
  ASSERT_EQ(merged->width, 7);
  ASSERT_EQ(merged->height, 5);
  EXPECT_EQ(ppmImageBytes(*merged), ppmImageBytes(whole));
  EXPECT_EQ(ppmImageBytes(*merged, {16, false}), ppmImageBytes(whole, {16, false}));
  tools::Outcome<ImageRegionFile> once = readImageRegion(write(whole, "whole.exr"), kLimit);
  tools::Outcome<ImageRegionFile> again = readImageRegion(write(*merged, "merged.exr"), kLimit);
  ASSERT_TRUE(once && again);
  EXPECT_EQ(once->rgb, again->rgb);
  EXPECT_EQ(again->region.width, 7);
  EXPECT_EQ(again->region.fullHeight, 5);
}

TEST_F(MergeRegions, WritesTheDataAndDisplayWindows) {
  tools::Outcome<ImageRegionFile> read =
      readImageRegion(write(rows(gradient(7, 5), 2, 4), "r.exr"), kLimit);
  ASSERT_TRUE(read) << read.failure().message;
  const ImageRegionFile& file = *read;
  EXPECT_EQ(file.region.x, 0);
  EXPECT_EQ(file.region.y, 2);
  EXPECT_EQ(file.region.width, 7);
  EXPECT_EQ(file.region.height, 2);
  EXPECT_EQ(file.region.fullWidth, 7);
  EXPECT_EQ(file.region.fullHeight, 5);
}

TEST_F(MergeRegions, RefusesAGapAMismatchAndHalves) {
  render::Image whole = gradient(7, 5);
  std::string error =
      mergeFailure({write(rows(whole, 0, 2), "a.exr"), write(rows(whole, 3, 5), "c.exr")}, kLimit);
  EXPECT_EQ(error, "no region holds pixel 0,2 of the 7x5 image");
  error = mergeFailure({folder_ / "a.exr", write(rows(gradient(7, 6), 2, 6), "d.exr")}, kLimit);
  EXPECT_NE(error.find("is a region of a 7x6 at 0,0 image"), std::string::npos) << error;
  std::string halfName = "h.exr";
  ASSERT_FALSE(writeImageFile(rows(whole, 2, 5), folder_ / halfName, {16, false}));
  error = mergeFailure({folder_ / "a.exr", folder_ / halfName}, kLimit);
  EXPECT_NE(error.find("holds 16-bit floating-point values"), std::string::npos) << error;
}

// A float EXR with the windows and values given, as a hostile program
// would write it: OpenImageIO directly.
fs::path writeExr(const fs::path& path, OIIO::ImageSpec spec, const std::vector<float>& values) {
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path.string());
  EXPECT_TRUE(out && out->open(path.string(), spec));
  EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, values.data()));
  EXPECT_TRUE(out->close());
  return path;
}

OIIO::ImageSpec windows(int x, int y, int width, int height, int fullWidth, int fullHeight,
                        int channels = 3) {
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  spec.x = x;
  spec.y = y;
  spec.full_width = fullWidth;
  spec.full_height = fullHeight;
  return spec;
}

// Sets an EXR header's box2i attribute `name` (dataWindow, displayWindow):
// the windows no writer would write, as a hostile file holds them.
fs::path withBox(const fs::path& path, const std::string& name, std::int32_t xMin,
                 std::int32_t yMin, std::int32_t xMax, std::int32_t yMax) {
  std::string bytes = tools::readWholeFile(path).valueOr("");
  std::string key = name + std::string(1, '\0') + "box2i" + std::string(1, '\0');
  std::size_t at = bytes.find(key);
  EXPECT_NE(at, std::string::npos) << name;
  std::int32_t box[4] = {xMin, yMin, xMax, yMax};  // little-endian, as EXR's
  std::memcpy(&bytes[at + key.size() + 4], box, sizeof box);
  EXPECT_FALSE(tools::writeFileAtomically(path, bytes));
  return path;
}

// A tile's display window is the image the merge allocates: bounded by the
// limit of a render's pixels, checked before any allocation, and so are the
// data window and the channels.
TEST_F(MergeRegions, BoundsWhatATileAsksForBeforeAllocating) {
  std::string error;
  render::Image one = gradient(1, 1);
  fs::path huge = withBox(write(one, "huge.exr"), "displayWindow", -(1 << 29), 0, (1 << 29) - 1, 0);
  error = mergeFailure({huge}, kLimit);
  EXPECT_EQ(error, "'" + huge.string() +
                       "' is a region of a 1073741824x1 image, 1073741824 pixels, more than the "
                       "limit of 67108864; raise it with --max-pixels");
  fs::path wide =
      withBox(write(one, "wide.exr"), "displayWindow", 0, 0, (1 << 16) - 1, (1 << 14) - 1);
  error = mergeFailure({wide}, kLimit);
  EXPECT_NE(error.find("more than the limit"), std::string::npos) << error;
  // The same limit as a render's, raised by the same flag.
  render::Image whole = gradient(7, 5);
  fs::path a = write(rows(whole, 0, 5), "a.exr");
  error = mergeFailure({a}, 34);
  EXPECT_NE(error.find("7x5 image, 35 pixels, more than the limit of 34"), std::string::npos);
  EXPECT_EQ(mergeFailure({a}, 35), "");
  // Data windows past the display window (OpenEXR itself refuses windows
  // near the edges of an int).
  fs::path outside = withBox(write(one, "outside.exr"), "dataWindow", 1000, 0, 1000, 0);
  error = mergeFailure({outside}, kLimit);
  EXPECT_NE(error.find("reach outside its image"), std::string::npos) << error;
  fs::path below = withBox(write(one, "below.exr"), "dataWindow", 0, -5, 0, -5);
  error = mergeFailure({below}, kLimit);
  EXPECT_NE(error.find("reach outside its image"), std::string::npos) << error;
  // An attribute that declares more bytes than the file holds, which
  // OpenEXR would allocate before reading them.
  {
    fs::path claims = write(one, "claims.exr");
    std::string bytes = tools::readWholeFile(claims).valueOr("");
    std::string key = std::string("compression") + '\0' + "compression" + '\0';
    std::size_t at = bytes.find(key);
    ASSERT_NE(at, std::string::npos);
    std::memcpy(&bytes[at + key.size()], "\x00\x00\x00\x70", 4);  // 1,879,048,192
    ASSERT_FALSE(tools::writeFileAtomically(claims, bytes));
    error = mergeFailure({claims}, kLimit);
    EXPECT_EQ(error, "'" + claims.string() +
                         "''s OpenEXR attribute 'compression' declares 1879048192 bytes, more "
                         "than the " +
                         std::to_string(bytes.size()) + " of the file");
  }
  fs::path five =
      writeExr(folder_ / "five.exr", windows(0, 0, 2, 1, 2, 1, 5), std::vector<float>(10, 0.5f));
  error = mergeFailure({five}, kLimit);
  EXPECT_NE(error.find("holds 5 channels"), std::string::npos) << error;
}

// Only regular files: a device or a pipe is refused before it is opened,
// at once (reading /dev/zero would never end, a pipe would block).
TEST_F(MergeRegions, ReadsRegularFilesOnly) {
  std::string error = mergeFailure({"/dev/zero"}, kLimit);
  EXPECT_EQ(error, "cannot read '/dev/zero': it is a character device, not a regular file");
  fs::path pipe = folder_ / "pipe.exr";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  error = mergeFailure({pipe}, kLimit);
  EXPECT_EQ(error, "cannot read '" + pipe.string() + "': it is a pipe, not a regular file");
  error = mergeFailure({folder_}, kLimit);
  EXPECT_EQ(error, "cannot read '" + folder_.string() + "': it is a directory");
}

// A file that cannot be read is told apart from files that do not make one
// image: sfrender ends the one with an I/O error, the other as invalid input.
TEST_F(MergeRegions, TellsAnUnreadableFileFromOneThatDoesNotFit) {
  auto code = [](tools::Outcome<render::Image> merged) {
    return merged ? tools::ExitCode::Success : merged.failure().code;
  };
  EXPECT_EQ(code(mergeImageRegions({folder_ / "missing.exr"}, kLimit)), tools::ExitCode::IoError);
  EXPECT_EQ(code(mergeImageRegions({"/dev/zero"}, kLimit)), tools::ExitCode::IoError);
  render::Image whole = gradient(7, 5);
  EXPECT_EQ(code(mergeImageRegions({write(rows(whole, 0, 2), "top.exr")}, kLimit)),
            tools::ExitCode::InvalidInput);
  EXPECT_EQ(code(mergeImageRegions({write(rows(whole, 0, 5), "big.exr")}, 34)),
            tools::ExitCode::InvalidInput);
}

// Tiles are OpenEXR, and only OpenEXR's reader sees a tile's bytes:
// another format, even holding floats, is refused by its content.
TEST_F(MergeRegions, ReadsOpenExrOnly) {
  render::Image whole = gradient(7, 5);
  std::string error;
  ASSERT_FALSE(writeImageFile(rows(whole, 0, 5), folder_ / "t.png"));
  ASSERT_TRUE(!writeImageFile(rows(whole, 0, 5), folder_ / "float.tif", {32, false}) ||
              !writeImageFile(rows(whole, 0, 5), folder_ / "float.tif"));
  fs::rename(folder_ / "float.tif", folder_ / "float.exr");
  for (const char* name : {"t.png", "float.exr"}) {
    error = mergeFailure({folder_ / name}, kLimit);
    EXPECT_EQ(error,
              "'" + (folder_ / name).string() + "' is not an OpenEXR file; " + kRegionsAreFloatExr);
  }
}

// A file named twice is two regions that agree: the image, whichever
// file comes twice and wherever.
TEST_F(MergeRegions, TakesATileNamedTwice) {
  render::Image whole = gradient(7, 5);
  fs::path top = write(rows(whole, 0, 2), "top.exr");
  fs::path bottom = write(rows(whole, 2, 5), "bottom.exr");
  for (const std::vector<fs::path>& files : std::vector<std::vector<fs::path>>{
           {top, bottom, top}, {top, top, bottom}, {bottom, top, bottom, bottom}}) {
    tools::Outcome<render::Image> merged = mergeImageRegions(files, kLimit);
    ASSERT_TRUE(merged) << merged.failure().message;
    EXPECT_EQ(ppmImageBytes(*merged), ppmImageBytes(whole));
  }
}

// No render writes a value that is not finite, so no tile may hold one:
// refused, naming the file and the pixel.
TEST_F(MergeRegions, RefusesValuesThatAreNotFinite) {
  std::string error;
  render::Image whole = gradient(7, 5);
  fs::path top = write(rows(whole, 0, 2), "top.exr");
  const float kNan = std::numeric_limits<float>::quiet_NaN();
  const float kInf = std::numeric_limits<float>::infinity();
  struct Case {
    float value;
    std::string said;
  };
  for (const Case& c : {Case{kNan, "nan"}, Case{kInf, "inf"}, Case{-kInf, "-inf"}}) {
    std::vector<float> values(7 * 3 * 3, 0.25f);
    values[3 * (7 * 1 + 4) + 2] = c.value;
    fs::path bottom = writeExr(folder_ / "bottom.exr", windows(0, 2, 7, 3, 7, 5), values);
    error = mergeFailure({top, bottom}, kLimit);
    EXPECT_EQ(error, "'" + bottom.string() + "' holds " + c.said +
                         " at pixel 4,3 (its B channel); a render writes finite values only");
  }
}

}  // namespace
}  // namespace image
