// What sfrender's image files hold (docs/RENDERING.md, "Image files"): the
// levels and linear values, the colour tags of each format, --bits and
// --alpha, read back with OpenImageIO and Little CMS.
#include "image/image_file.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <lcms2.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "image/read_back_test_support.h"
#include "tools/common/file_io.h"
#include "tools/tool_test_support.h"

namespace image {
namespace {

namespace fs = std::filesystem;

// A width x height image as renderImage makes it with coverage: a smooth
// gradient with values below 0 and above 1 in the first row, coverage
// stepping through 0, 1/4, ... 1, and the colour premultiplied by it (0
// where nothing covers the pixel).
render::Image testImage(int width = 24, int height = 10) {
  render::Image image;
  image.width = width;
  image.height = height;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      float a = static_cast<float>((i + j) % 5) / 4.0f;
      float u = static_cast<float>(i) / (width - 1);
      float v = static_cast<float>(j) / (height - 1);
      glm::vec3 straight =
          j == 0 ? glm::vec3(1.3f * u - 0.15f, 2.5f * u, -u) : glm::vec3(u, v, 1.0f - 0.5f * u * v);
      image.rgb.insert(image.rgb.end(), {a * straight.x, a * straight.y, a * straight.z});
      image.coverage.push_back(a);
    }
  }
  return image;
}

class ImageFileTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = tools::freshTestFolder("sfimage"); }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const ImageOptions& options,
                 const render::Image& image = testImage()) {
    fs::path file = dir_ / name;
    tools::MaybeFailure failure = writeImageFile(image, file, options);
    EXPECT_FALSE(failure) << name << ": " << failure->message;
    return file;
  }

  fs::path dir_;
};

TEST(ImageFile, SrgbDecodingIsTheStandardsExtendedPastOne) {
  // The sRGB encoding (IEC 61966-2-1), which decoding must undo.
  auto encode = [](double l) {
    return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
  };
  for (int i = 0; i <= 1000; ++i) {
    float v = static_cast<float>(i) / 1000.0f;
    EXPECT_NEAR(encode(srgbToLinear(v)), v, 2e-7) << v;
  }
  EXPECT_EQ(srgbToLinear(0.0f), 0.0f);
  EXPECT_EQ(srgbToLinear(1.0f), 1.0f);
  EXPECT_FLOAT_EQ(srgbToLinear(0.04045f), 0.04045f / 12.92f);
  // Above 1 the power segment goes on; below 0 the curve is mirrored.
  EXPECT_FLOAT_EQ(srgbToLinear(2.0f), static_cast<float>(std::pow(2.055 / 1.055, 2.4)));
  EXPECT_EQ(srgbToLinear(-0.5f), -srgbToLinear(0.5f));
  EXPECT_LT(srgbToLinear(1.0f), srgbToLinear(1.0001f));
  // Never infinite.
  constexpr float kLargest = std::numeric_limits<float>::max();
  EXPECT_EQ(srgbToLinear(kLargest), kLargest);
  EXPECT_EQ(srgbToLinear(-std::numeric_limits<float>::infinity()), -kLargest);
}

// The expected stored value of channel c of pixel p: a display level, or a
// linear value; straight colour with alpha in integer files, premultiplied
// in floating-point ones.
float expected(const render::Image& image, std::size_t p, int c, bool alpha, int bits,
               bool linear) {
  float a = alpha ? image.coverage[p] : 1.0f;
  if (c == 3) return a;
  float v = image.rgb[3 * p + c];
  float straight = a > 0.0f ? v / a : 0.0f;
  if (linear) return a * srgbToLinear(alpha ? straight : v);
  return bits == 16 ? render::sixteenBitLevel(straight) / 65535.0f
                    : render::eightBitLevel(straight) / 255.0f;
}

TEST_F(ImageFileTest, IntegerImagesHoldTheLevelsOfTheDisplayValues) {
  render::Image image = testImage();
  for (const char* extension : {".png", ".tif", ".ppm"}) {
    for (int bits : {8, 16}) {
      for (bool alpha : {false, true}) {
        // (OpenImageIO's PNM reader reads 16-bit samples one level off:
        // SixteenBitPpmIsNetpbms checks those bytes.)
        if (std::string(extension) == ".ppm" && (alpha || bits == 16)) continue;
        std::string name = "i" + std::to_string(bits) + (alpha ? "a" : "") + extension;
        ReadBack r = readBack(write(name, {bits, alpha}, image));
        ASSERT_EQ(r.spec.nchannels, alpha ? 4 : 3) << name;
        EXPECT_EQ(r.spec.format, bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8)
            << name;
        for (std::size_t p = 0; p < image.coverage.size(); ++p) {
          for (int c = 0; c < r.spec.nchannels; ++c) {
            float want = expected(image, p, c, alpha, bits, false);
            if (c == 3)
              want = (bits == 16 ? render::sixteenBitLevel(want) / 65535.0f
                                 : render::eightBitLevel(want) / 255.0f);
            // Within a small part of a 16-bit level of the level expected.
            ASSERT_NEAR(r.pixels[r.spec.nchannels * p + c], want, 1e-6)
                << name << " " << p << "." << c;
          }
        }
      }
    }
  }
}

TEST_F(ImageFileTest, ExrHoldsTheLinearValuesWithTheirChromaticities) {
  render::Image image = testImage();
  for (int bits : {32, 16}) {
    for (bool alpha : {false, true}) {
      std::string name = "e" + std::to_string(bits) + (alpha ? "a" : "") + ".exr";
      ReadBack r = readBack(write(name, {bits, alpha}, image));
      ASSERT_EQ(r.spec.nchannels, alpha ? 4 : 3) << name;
      EXPECT_EQ(r.spec.format, bits == 16 ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
      if (alpha) {
        EXPECT_EQ(r.spec.channelnames.back(), "A");
      }
      EXPECT_EQ(r.spec.get_string_attribute("oiio:ColorSpace"), "Linear");
      const OIIO::ParamValue* chromaticities = r.spec.find_attribute("chromaticities");
      ASSERT_NE(chromaticities, nullptr) << name;
      ASSERT_EQ(chromaticities->type(), OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8));
      const float* xy = static_cast<const float*>(chromaticities->data());
      // Rec. 709 (sRGB) red, green, blue and the D65 white.
      const std::array<float, 8> rec709 = {0.64f, 0.33f, 0.30f,   0.60f,
                                           0.15f, 0.06f, 0.3127f, 0.3290f};
      for (int k = 0; k < 8; ++k) EXPECT_EQ(xy[k], rec709[k]) << k;
      for (std::size_t p = 0; p < image.coverage.size(); ++p) {
        for (int c = 0; c < r.spec.nchannels; ++c) {
          float want = expected(image, p, c, alpha, bits, true);
          float got = r.pixels[r.spec.nchannels * p + c];
          // A half keeps 11 significant bits.
          float slack = bits == 16 ? std::abs(want) * 0x1p-11f + 0x1p-24f : 0.0f;
          ASSERT_NEAR(got, want, slack) << name << " " << p << "." << c;
        }
      }
    }
  }
}

// The chunk types of a PNG file, in order, with the IHDR's bit depth and
// colour type.
struct PngChunks {
  std::vector<std::string> types;
  int bitDepth = 0;
  int colourType = 0;
  std::uint32_t gamma = 0;  // gAMA's, times 100000
};

PngChunks pngChunks(const std::string& bytes) {
  PngChunks chunks;
  auto u32 = [&](std::size_t at) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at]) << 24 |
                                      static_cast<unsigned char>(bytes[at + 1]) << 16 |
                                      static_cast<unsigned char>(bytes[at + 2]) << 8 |
                                      static_cast<unsigned char>(bytes[at + 3]));
  };
  EXPECT_EQ(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n"), 0);
  for (std::size_t at = 8; at + 8 <= bytes.size();) {
    std::uint32_t length = u32(at);
    std::string type = bytes.substr(at + 4, 4);
    chunks.types.push_back(type);
    if (type == "IHDR") {
      chunks.bitDepth = static_cast<unsigned char>(bytes[at + 16]);
      chunks.colourType = static_cast<unsigned char>(bytes[at + 17]);
    }
    if (type == "gAMA") chunks.gamma = u32(at + 8);
    at += 12 + std::size_t{length};
  }
  return chunks;
}

TEST_F(ImageFileTest, PngIsTaggedSrgbByItsChunk) {
  for (int bits : {8, 16}) {
    for (bool alpha : {false, true}) {
      std::string name = "p" + std::to_string(bits) + (alpha ? "a" : "") + ".png";
      tools::Outcome<std::string> bytes = tools::readWholeFile(write(name, {bits, alpha}));
      ASSERT_TRUE(bytes) << bytes.failure().message;
      PngChunks chunks = pngChunks(*bytes);
      auto has = [&](const char* type) {
        return std::find(chunks.types.begin(), chunks.types.end(), type) != chunks.types.end();
      };
      auto before = [&](const char* a, const char* b) {
        return std::find(chunks.types.begin(), chunks.types.end(), a) <
               std::find(chunks.types.begin(), chunks.types.end(), b);
      };
      EXPECT_EQ(chunks.bitDepth, bits) << name;
      EXPECT_EQ(chunks.colourType, alpha ? 6 : 2) << name;  // RGB with alpha, RGB
      // sRGB, with gAMA (1 / 2.2) and cHRM for readers that know no sRGB;
      // never iCCP beside it (the PNG standard allows one of the two).
      EXPECT_TRUE(has("sRGB") && has("gAMA") && has("cHRM")) << name;
      EXPECT_FALSE(has("iCCP")) << name;
      EXPECT_TRUE(before("sRGB", "IDAT")) << name;
      EXPECT_EQ(chunks.gamma, 45455u) << name;
    }
  }
}

// The sRGB profile of Little CMS, against which an embedded one is judged.
std::vector<std::uint8_t> convertedBy(const std::vector<std::uint8_t>& profile,
                                      const std::vector<std::uint8_t>& rgb) {
  cmsHPROFILE embedded = cmsOpenProfileFromMem(profile.data(), profile.size());
  cmsHPROFILE srgb = cmsCreate_sRGBProfile();
  std::vector<std::uint8_t> out(rgb.size());
  if (embedded && srgb) {
    cmsHTRANSFORM transform =
        cmsCreateTransform(embedded, TYPE_RGB_8, srgb, TYPE_RGB_8, INTENT_RELATIVE_COLORIMETRIC, 0);
    if (transform) {
      cmsDoTransform(transform, rgb.data(), out.data(), rgb.size() / 3);
      cmsDeleteTransform(transform);
    }
  }
  if (embedded) cmsCloseProfile(embedded);
  if (srgb) cmsCloseProfile(srgb);
  return out;
}

TEST_F(ImageFileTest, TiffAndJpegCarryAnSrgbProfile) {
  for (const char* name : {"t.tif", "t16.tif", "j.jpg"}) {
    int bits = std::string(name) == "t16.tif" ? 16 : 8;
    ReadBack r = readBack(write(name, {bits, false}));
    EXPECT_EQ(r.spec.get_string_attribute("oiio:ColorSpace"), "sRGB") << name;
    EXPECT_EQ(r.spec.get_int_attribute("Exif:ColorSpace"), 1) << name;  // sRGB
    const OIIO::ParamValue* icc = r.spec.find_attribute("ICCProfile");
    ASSERT_NE(icc, nullptr) << name;
    const auto* begin = static_cast<const std::uint8_t*>(icc->data());
    std::vector<std::uint8_t> profile(begin, begin + icc->type().size());
    cmsHPROFILE opened = cmsOpenProfileFromMem(profile.data(), profile.size());
    ASSERT_NE(opened, nullptr) << name;
    char description[64] = "";
    cmsGetProfileInfoASCII(opened, cmsInfoDescription, "en", "US", description, sizeof description);
    EXPECT_STREQ(description, "sRGB IEC61966-2.1");
    EXPECT_EQ(cmsGetProfileVersion(opened), 2.1);
    EXPECT_EQ(cmsGetColorSpace(opened), cmsSigRgbData);
    cmsCloseProfile(opened);
    // Converted from it to sRGB, every colour stays what it was.
    std::vector<std::uint8_t> rgb;
    for (int v = 0; v < 256; v += 15)
      rgb.insert(rgb.end(), {std::uint8_t(v), 128, std::uint8_t(255 - v)});
    std::vector<std::uint8_t> converted = convertedBy(profile, rgb);
    for (std::size_t i = 0; i < rgb.size(); ++i) {
      EXPECT_NEAR(converted[i], rgb[i], 1) << name << " " << i;
    }
  }
  // Made the same way each time: the profile carries no date of its own.
  EXPECT_EQ(tools::readWholeFile(write("a.jpg", {})).valueOr("a"),
            tools::readWholeFile(write("b.jpg", {})).valueOr("b"));
}

TEST_F(ImageFileTest, TiffAlphaIsStraight) {
  ReadBack r = readBack(write("a.tif", {8, true}));
  EXPECT_EQ(r.spec.get_int_attribute("tiff:UnassociatedAlpha"), 1);
  EXPECT_EQ(r.spec.alpha_channel, 3);
}

TEST_F(ImageFileTest, SixteenBitPpmIsNetpbms) {
  // (OpenImageIO 2.4 writes no 16-bit PNM that reads back, which is why
  // .pnm takes 8 bits only; its reader reads sfrender's .ppm, above.)
  render::Image image = testImage(7, 5);
  tools::Outcome<std::string> bytes = tools::readWholeFile(write("hand.ppm", {16, false}, image));
  ASSERT_TRUE(bytes) << bytes.failure().message;
  const std::string header = "P6\n7 5\n65535\n";
  EXPECT_EQ(bytes->compare(0, header.size(), header), 0);
  EXPECT_EQ(bytes->size(), header.size() + 7 * 5 * 3 * 2);
  EXPECT_EQ(bytes->size(), ppmFileSize(7, 5, "x.ppm", {16, false}));
  // Each sample two bytes, the most significant first.
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    auto byte = [&](std::size_t k) { return static_cast<unsigned char>((*bytes)[k]); };
    std::size_t at = header.size() + 2 * i;
    ASSERT_EQ(byte(at) << 8 | byte(at + 1), render::sixteenBitLevel(image.rgb[i])) << i;
  }
}

// Every format sfrender lists writes the image at each --bits it takes, with
// and without alpha where it has alpha, and reads back as that picture (to
// within what its compression keeps).
TEST_F(ImageFileTest, EveryListedFormatWritesWhatItPromises) {
  // Smooth, for the lossy formats: gradients of straight colour and of
  // coverage (never 0, where the colour is black).
  render::Image image;
  image.width = 64;
  image.height = 48;
  for (int j = 0; j < image.height; ++j) {
    for (int i = 0; i < image.width; ++i) {
      float a = 0.25f + 0.75f * static_cast<float>(i + j) / 110.0f;
      float u = static_cast<float>(i) / 63.0f;
      float v = static_cast<float>(j) / 47.0f;
      image.rgb.insert(image.rgb.end(), {a * u, a * v, a * (1.0f - 0.5f * u)});
      image.coverage.push_back(a);
    }
  }
  std::vector<ImageFormat> formats = writableImageFormats();
  ASSERT_GT(formats.size(), 1u) << "no OpenImageIO module";
  for (const ImageFormat& format : formats) {
    for (int bits : format.bits) {
      for (bool alpha : {false, true}) {
        if (alpha && !format.alpha) continue;
        std::string name =
            format.name + std::to_string(bits) + (alpha ? "a" : "") + format.extensions.front();
        ReadBack r = readBack(write(name, {bits, alpha}, image));
        ASSERT_EQ(r.spec.width, image.width) << name;
        ASSERT_EQ(r.spec.nchannels, alpha ? 4 : 3) << name;
        double error = 0.0;
        for (std::size_t p = 0; p < image.coverage.size(); ++p) {
          for (int c = 0; c < r.spec.nchannels; ++c) {
            float want = expected(image, p, c, alpha, bits, format.linear);
            float got = r.pixels[r.spec.nchannels * p + c];
            // Linear values compared as display values, where a level means
            // the same everywhere.
            if (format.linear && c < 3) {
              error += std::abs(std::cbrt(got) - std::cbrt(want)) / 3;
            } else {
              error += std::abs(got - std::clamp(want, 0.0f, 1.0f));
            }
          }
        }
        error /= static_cast<double>(image.coverage.size() * r.spec.nchannels);
        EXPECT_LT(error, 2.0 / 255.0) << name << ": mean error " << error * 255 << " levels";
      }
    }
  }
}

// Each extension gives its own format, though the writers write into memory
// under no name: a file OpenImageIO reads as the format listed, AVIF as AV1
// (not HEVC, as .heic), .jp2 in JPEG 2000's file format and .j2k as its
// bare codestream.
TEST_F(ImageFileTest, EveryExtensionWritesItsOwnFormat) {
  render::Image image = testImage();
  image.width = image.height = 32;  // JPEG 2000's least
  image.rgb.assign(3 * 32 * 32, 0.5f);
  for (const ImageFormat& format : writableImageFormats()) {
    for (const std::string& extension : format.extensions) {
      fs::path file = write("x" + extension, {}, image);
      std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(file.string());
      ASSERT_TRUE(in) << extension;
      EXPECT_EQ(in->format_name(), format.name == "ppm" ? "pnm" : format.name) << extension;
      std::string bytes = tools::readWholeFile(file).valueOr("");
      std::string want = extension == ".avif"   ? "avif"
                         : extension == ".heic" ? "heic"
                         : extension == ".jp2"  ? "jP  "
                         : extension == ".j2k"  ? "\xff\x4f\xff\x51"
                                                : "";
      std::size_t at = extension == ".jp2" ? 4 : extension == ".j2k" ? 0 : 8;
      if (!want.empty()) {
        EXPECT_EQ(bytes.substr(at, 4), want) << extension;
      }
    }
  }
}

// sfrender writes .ppm by hand: the file must be the one OpenImageIO writes
// (.pnm goes through it) and read back through OpenImageIO identically.
TEST(ImageFile, HandWrittenPpmMatchesOpenImageIO) {
  render::Image image;
  image.width = 7;
  image.height = 5;
  for (int i = 0; i < image.width * image.height * 3; ++i) {
    image.rgb.push_back(static_cast<float>(i % 23) / 19.0f - 0.1f);
  }
  fs::path dir = fs::temp_directory_path() / ("sfppm-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  ASSERT_FALSE(writeImageFile(image, dir / "hand.ppm"));
  ASSERT_FALSE(writeImageFile(image, dir / "oiio.pnm"));
  tools::Outcome<std::string> hand = tools::readWholeFile(dir / "hand.ppm");
  tools::Outcome<std::string> oiio = tools::readWholeFile(dir / "oiio.pnm");
  ASSERT_TRUE(hand && oiio);
  EXPECT_EQ(*hand, *oiio);

  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open((dir / "hand.ppm").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, image.width);
  EXPECT_EQ(in->spec().height, image.height);
  EXPECT_EQ(in->spec().nchannels, 3);
  std::vector<unsigned char> pixels(image.rgb.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data()));
  in->close();
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    ASSERT_EQ(pixels[i], render::eightBitLevel(image.rgb[i])) << i;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace image
