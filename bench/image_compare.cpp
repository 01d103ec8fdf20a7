// image_compare: how closely two renders of the same scene agree, for the
// render benchmark (bench/render_bench.sh), which compares sfrender's image
// with POV-Ray's.
//
//   image_compare A.ppm B.ppm [--side-by-side OUT.png] [--crop X,Y,W,H]
//
// Both images must have the same size. Output is one "key: value" line per
// figure, for people and for the script:
//   nonblack_a, nonblack_b   fraction of pixels with any channel above 0
//   mean_a, mean_b           mean channel value, 0 to 255
//   close_8                  fraction of pixels whose channels all differ by
//                            at most 8 of 255
//   far_64                   fraction of pixels where some channel differs by
//                            more than 64 of 255 (a different object, or
//                            shadow, is seen there)
//   far_64_mirrored          the same against B mirrored left to right: far
//                            above far_64 unless the scene is symmetric, so
//                            a mirrored B shows as far_64 > far_64_mirrored
// --side-by-side writes A (left) and B (right), each the crop (or the whole
// image) at half size unless a crop is given, as one image (PNG by the name).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <OpenImageIO/imageio.h>

namespace {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // 3 channels, row by row from the top
  std::uint8_t at(int x, int y, int c) const {
    return rgb[3 * (static_cast<std::size_t>(y) * width + x) + c];
  }
};

bool readImage(const std::string& path, Image& image) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    std::cerr << "image_compare: cannot read " << path << ": " << OIIO::geterror() << '\n';
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  image.width = spec.width;
  image.height = spec.height;
  std::vector<std::uint8_t> all(static_cast<std::size_t>(spec.width) * spec.height *
                                spec.nchannels);
  if (spec.nchannels < 3 || !in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8,
                                            all.data())) {
    std::cerr << "image_compare: cannot read " << path << " as RGB: " << in->geterror() << '\n';
    return false;
  }
  image.rgb.resize(static_cast<std::size_t>(spec.width) * spec.height * 3);
  for (std::size_t p = 0; p < static_cast<std::size_t>(spec.width) * spec.height; ++p) {
    for (int c = 0; c < 3; ++c) image.rgb[3 * p + c] = all[p * spec.nchannels + c];
  }
  return true;
}

int maxChannelDifference(const Image& a, int ax, const Image& b, int bx, int y) {
  int d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.at(ax, y, c)) - int(b.at(bx, y, c))));
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Compares two renders of the same scene, pixel by pixel."};
  std::string pathA;
  std::string pathB;
  std::string sideBySide;
  std::vector<int> crop;
  app.add_option("a", pathA, "the first image")->required();
  app.add_option("b", pathB, "the second image, of the same size")->required();
  app.add_option("--side-by-side", sideBySide, "write both images side by side to this file");
  app.add_option("--crop", crop, "X,Y,W,H: the part of each image to put side by side")
      ->delimiter(',')
      ->expected(4);
  CLI11_PARSE(app, argc, argv);

  Image a;
  Image b;
  if (!readImage(pathA, a) || !readImage(pathB, b)) return 1;
  if (a.width != b.width || a.height != b.height) {
    std::cerr << "image_compare: the images differ in size: " << a.width << "x" << a.height
              << " and " << b.width << "x" << b.height << '\n';
    return 1;
  }

  const double pixels = static_cast<double>(a.width) * a.height;
  std::uint64_t nonblackA = 0, nonblackB = 0, close = 0, far = 0, farMirrored = 0;
  double sumA = 0, sumB = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      int maxA = 0, maxB = 0;
      for (int c = 0; c < 3; ++c) {
        maxA = std::max<int>(maxA, a.at(x, y, c));
        maxB = std::max<int>(maxB, b.at(x, y, c));
        sumA += a.at(x, y, c);
        sumB += b.at(x, y, c);
      }
      nonblackA += maxA > 0;
      nonblackB += maxB > 0;
      int d = maxChannelDifference(a, x, b, x, y);
      close += d <= 8;
      far += d > 64;
      farMirrored += maxChannelDifference(a, x, b, a.width - 1 - x, y) > 64;
    }
  }
  std::printf("width: %d\nheight: %d\n", a.width, a.height);
  std::printf("nonblack_a: %.4f\nnonblack_b: %.4f\n", nonblackA / pixels, nonblackB / pixels);
  std::printf("mean_a: %.2f\nmean_b: %.2f\n", sumA / (3 * pixels), sumB / (3 * pixels));
  std::printf("close_8: %.4f\nfar_64: %.4f\nfar_64_mirrored: %.4f\n", close / pixels,
              far / pixels, farMirrored / pixels);

  if (!sideBySide.empty()) {
    int x0 = 0, y0 = 0, w = a.width, h = a.height, step = 2;
    if (crop.size() == 4) {
      x0 = std::clamp(crop[0], 0, a.width - 1);
      y0 = std::clamp(crop[1], 0, a.height - 1);
      w = std::clamp(crop[2], 1, a.width - x0);
      h = std::clamp(crop[3], 1, a.height - y0);
      step = 1;
    }
    int ow = w / step, oh = h / step, gap = 8;
    int outWidth = 2 * ow + gap;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(outWidth) * oh * 3, 255);
    for (int y = 0; y < oh; ++y) {
      for (int x = 0; x < ow; ++x) {
        for (int c = 0; c < 3; ++c) {
          out[3 * (static_cast<std::size_t>(y) * outWidth + x) + c] =
              a.at(x0 + x * step, y0 + y * step, c);
          out[3 * (static_cast<std::size_t>(y) * outWidth + ow + gap + x) + c] =
              b.at(x0 + x * step, y0 + y * step, c);
        }
      }
    }
    auto file = OIIO::ImageOutput::create(sideBySide);
    OIIO::ImageSpec spec(outWidth, oh, 3, OIIO::TypeDesc::UINT8);
    if (!file || !file->open(sideBySide, spec) ||
        !file->write_image(OIIO::TypeDesc::UINT8, out.data()) || !file->close()) {
      std::cerr << "image_compare: cannot write " << sideBySide << '\n';
      return 1;
    }
  }
  return 0;
}
