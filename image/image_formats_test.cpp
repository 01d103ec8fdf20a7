// The formats sfrender writes, from a list as OpenImageIO's module gives it
// (no module needed), and sfcheck's fixed copy of it against the module's.
#include "image/image_formats.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "image/image_file.h"
#include "tools/common/output_file_format.h"

namespace image {
namespace {

const char* const kList =
    "openexr 1 exr sxr\n"
    "newformat 0 nf\n"
    "pnm 0 ppm pgm\n"
    "png 1 png\n"
    "broken line\n";

TEST(ImageFormats, FollowTheModulesListWithSfrendersOwnPpmFirst) {
  std::vector<ImageFormat> formats = imageFormatsFrom(kList);
  std::vector<std::string> names;
  for (const ImageFormat& f : formats) names.push_back(f.name);
  // .ppm, then in the order of sfrender's table, the unknown format last.
  EXPECT_EQ(names, (std::vector<std::string>{"ppm", "pnm", "png", "openexr", "newformat"}));
  EXPECT_EQ(formats[1].extensions, std::vector<std::string>{".pgm"});  // .ppm is sfrender's
  EXPECT_EQ(findImageFormat(formats, "a/b.PPM")->name, "ppm");
  EXPECT_EQ(findImageFormat(formats, "b.Sxr")->name, "openexr");
  EXPECT_EQ(findImageFormat(formats, "b.gif"), nullptr);
  EXPECT_EQ(findImageFormat(formats, "png"), nullptr);
  EXPECT_EQ(imageExtensionsOf(formats), ".ppm, .pgm, .png, .exr, .sxr or .nf");
}

TEST(ImageFormats, EachTakesItsBitsAndAlpha) {
  std::vector<ImageFormat> formats = imageFormatsFrom(kList);
  const ImageFormat& exr = *findImageFormat(formats, "x.exr");
  const ImageFormat& png = *findImageFormat(formats, "x.png");
  const ImageFormat& ppm = *findImageFormat(formats, "x.ppm");
  const ImageFormat& other = *findImageFormat(formats, "x.nf");
  EXPECT_TRUE(exr.linear && exr.alpha);
  EXPECT_EQ(storedBits(exr, {}), 32);
  EXPECT_EQ(storedBits(exr, {16, false}), 16);
  EXPECT_FALSE(png.linear);
  EXPECT_EQ(storedBits(png, {}), 8);
  // A format sfrender knows nothing of: 8-bit display values.
  EXPECT_FALSE(other.linear);
  EXPECT_EQ(other.bits, std::vector<int>{8});

  EXPECT_EQ(imageOptionsRefusal(formats, png, {16, true}), std::nullopt);
  EXPECT_EQ(imageOptionsRefusal(formats, exr, {16, true}), std::nullopt);
  EXPECT_EQ(imageOptionsRefusal(formats, ppm, {16, false}), std::nullopt);
  EXPECT_EQ(imageOptionsRefusal(formats, png, {32, false}), "PNG images take --bits 8 or 16");
  EXPECT_EQ(imageOptionsRefusal(formats, exr, {8, false}),
            "OpenEXR images take --bits 32 (float) or 16 (half)");
  EXPECT_EQ(imageOptionsRefusal(formats, other, {16, false}), "NEWFORMAT images take --bits 8");
  EXPECT_EQ(imageOptionsRefusal(formats, ppm, {0, true}),
            "PPM images have no alpha channel; --alpha takes .png or .exr");
}

TEST(ImageFormats, TheHelpTableNamesEveryExtension) {
  std::string table = imageFormatTable(imageFormatsFrom(kList));
  EXPECT_EQ(table.substr(0, table.find('\n')),
            "  extensions  format        --bits    alpha  values");
  EXPECT_NE(table.find("  .exr .sxr   OpenEXR       32 16     alpha  linear\n"), std::string::npos)
      << table;
  EXPECT_NE(table.find("  .ppm        PPM           8 16             sRGB\n"), std::string::npos)
      << table;
  EXPECT_NE(table.find("  .png        PNG           8 16      alpha  sRGB\n"), std::string::npos)
      << table;
}

// sfcheck cannot ask OpenImageIO (tools/common/output_file_format.h), so it
// keeps a copy of the list; this is where the copy meets OpenImageIO's.
TEST(ImageFormats, SfchecksListIsOpenImageIOs) {
  std::vector<std::string> runtime;
  for (const ImageFormat& f : writableImageFormats()) {
    runtime.insert(runtime.end(), f.extensions.begin(), f.extensions.end());
  }
  std::vector<std::string> fixed(tools::imageExtensions().begin(), tools::imageExtensions().end());
  EXPECT_EQ(fixed, runtime) << "OpenImageIO writes other formats than "
                               "tools/common/output_file_format.cpp lists: update the list";
  for (const std::string& extension : runtime) {
    EXPECT_TRUE(canWriteImage("x" + extension)) << extension;
    EXPECT_TRUE(tools::hasImageExtension("x" + extension)) << extension;
  }
  // OpenImageIO's, but no file (term, null), or unfit for a render (GIF
  // keeps 256 colours, ICO 256 pixels a side, ZFile one channel), or for
  // reading only (.pfm, .dib).
  for (const char* name :
       {"x.term", "x.null", "x.gif", "x.ico", "x.zfile", "x.pfm", "x.dib", "x"}) {
    EXPECT_FALSE(canWriteImage(name)) << name;
    EXPECT_FALSE(tools::hasImageExtension(name)) << name;
  }
  EXPECT_TRUE(tools::hasImageExtension("a/b.Tiff"));
  EXPECT_FALSE(tools::hasImageExtension("a.png/b"));
}

}  // namespace
}  // namespace image
