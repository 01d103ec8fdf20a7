// sfrender's image files end to end: --bits and --alpha each format takes,
// the formats --help lists, and the coverage an --alpha render writes.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "image/image_file.h"
#include "image/read_back_test_support.h"
#include "tools/common/exit_code.h"
#include "tools/common/file_io.h"
#include "tools/tool_test_support.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

class ImageFileTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = freshTestFolder("sfimage"); }
  void TearDown() override { fs::remove_all(dir_); }

  int sfrender(const std::vector<std::string>& args) {
    std::vector<std::string> all = {"sfrender"};
    all.insert(all.end(), args.begin(), args.end());
    return runTool(tools::sfrender, all, out_, err_);
  }

  fs::path dir_;
  std::ostringstream out_, err_;
};

TEST_F(ImageFileTest, BitsAndAlphaAFormatCannotHoldAreUsageErrors) {
  std::string scene = (dir_ / "s.sf").string();
  ASSERT_FALSE(writeFileAtomically(scene, kValidScene));
  struct Case {
    std::vector<std::string> flags;
    std::string name;
    std::string message;
    bool sfrenders = true;  // sfrender's message, not CLI11's
  };
  const Case cases[] = {
      {{"--bits", "16"},
       "x.jpg",
       "cannot write '" + (dir_ / "x.jpg").string() +
           "' with --bits 16: JPEG images take --bits 8"},
      {{"--bits", "32"}, "x.png", "with --bits 32: PNG images take --bits 8 or 16"},
      {{"--bits", "32"}, "x.tif", "with --bits 32: TIFF images take --bits 8 or 16"},
      {{"--bits", "8"}, "x.exr", "OpenEXR images take --bits 32 (float) or 16 (half)"},
      {{"--bits", "16"}, "x.hdr", "Radiance HDR images take --bits 32 (float)"},
      {{"--alpha"}, "x.ppm", "with --alpha: PPM images have no alpha channel; --alpha takes .png"},
      {{"--alpha"}, "x.jpg", "JPEG images have no alpha channel"},
      {{"--alpha"}, "x.hdr", "Radiance HDR images have no alpha channel"},
      {{"--bits", "12"}, "x.png", "--bits", false},
      {{},
       "x.jxl",
       "cannot write images named '" + (dir_ / "x.jxl").string() +
           "': use .ppm, .pgm, .pbm, .pnm, .png,"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {scene,      "-o", (dir_ / c.name).string(), "--width", "8",
                                     "--height", "6"};
    args.insert(args.end(), c.flags.begin(), c.flags.end());
    EXPECT_EQ(sfrender(args), toInt(ExitCode::Usage)) << c.name;
    EXPECT_NE(err_.str().find(c.message), std::string::npos) << err_.str();
    if (c.sfrenders) {
      EXPECT_EQ(err_.str().rfind("sfrender: error: ", 0), 0u) << err_.str();
    }
  }
  EXPECT_EQ(fileNamesIn(dir_), std::vector<std::string>{"s.sf"});
  // What they take.
  for (const auto& [name, flags] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"a.png", {"--bits", "16", "--alpha"}},
           {"a.ppm", {"--bits", "16"}},
           {"a.exr", {"--bits", "16", "--alpha"}},
           {"a.tif", {"--alpha"}}}) {
    std::vector<std::string> args = {
        scene, "-o", (dir_ / name).string(), "--width", "8", "--height", "6", "--quiet"};
    args.insert(args.end(), flags.begin(), flags.end());
    EXPECT_EQ(sfrender(args), 0) << name << ": " << err_.str();
  }
}

TEST_F(ImageFileTest, HelpListsWhatOpenImageIOWrites) {
  EXPECT_EQ(sfrender({"--help"}), 0);
  std::string help = out_.str();
  for (const image::ImageFormat& format : image::writableImageFormats()) {
    for (const std::string& extension : format.extensions) {
      EXPECT_NE(help.find(" " + extension + " "), std::string::npos) << extension << "\n" << help;
    }
  }
  EXPECT_NE(help.find("Image formats"), std::string::npos) << help;
  EXPECT_NE(help.find("--alpha"), std::string::npos) << help;
}

// Rendered with --alpha, a wall whose edge runs down the middle of the
// middle column of a 9-pixel-wide image: that column half covered, the
// background transparent, the wall opaque, in PNG and EXR alike.
TEST_F(ImageFileTest, AlphaIsTheCoverageOfEachPixel) {
  std::string scene = (dir_ / "wall.sf").string();
  ASSERT_FALSE(writeFileAtomically(scene,
                                   "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"
                                   "LIGHT\n1 1 1\n1 0 0 0\n0 1 0 30\n0 0 1 0\n0 0 0 1\n"
                                   "CUBE\n0.8 0.4 0.2\n10 0 0 10\n0 10 0 0\n0 0 1 -5\n0 0 0 1\n"));
  for (const char* name : {"wall.png", "wall.exr"}) {
    ASSERT_EQ(sfrender({scene, "-o", (dir_ / name).string(), "--width", "9", "--height", "5",
                        "--spp", "16", "--alpha", "--quiet"}),
              0)
        << err_.str();
    image::ReadBack r = image::readBack(dir_ / name);
    ASSERT_EQ(r.spec.nchannels, 4);
    for (int j = 0; j < 5; ++j) {
      for (int i = 0; i < 9; ++i) {
        float alpha = r.pixels[4 * (j * 9 + i) + 3];
        float covered = i < 4 ? 0.0f : i == 4 ? 0.5f : 1.0f;
        // 0.5 is level 127.5 of 8 bits, which rounds up.
        if (std::string(name) == "wall.png" && i == 4) covered = 128.0f / 255.0f;
        EXPECT_EQ(alpha, covered) << name << " " << i << "," << j;
        if (i < 4) {
          EXPECT_EQ(r.pixels[4 * (j * 9 + i)], 0.0f) << name;
        }
      }
    }
    // The half-covered pixel's straight colour is the wall's (in the PNG),
    // and the EXR's is premultiplied.
    // (Lit from high above, the wall's shading changes little from one
    // pixel to the next, and has no highlight.)
    float red = r.pixels[4 * (2 * 9 + 4)];
    float wallRed = std::string(name) == "wall.png" ? r.pixels[4 * (2 * 9 + 5)]
                                                    : 0.5f * r.pixels[4 * (2 * 9 + 5)];
    EXPECT_NEAR(red, wallRed, 0.03f * wallRed) << name;
  }
}

}  // namespace
}  // namespace tools
