// An image file's pixels read back with OpenImageIO as the file stores
// them, for the tests of what the image writers and sfrender write.
#pragma once

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <vector>

namespace image {

struct ReadBack {
  OIIO::ImageSpec spec;
  std::vector<float> pixels;  // as stored, scaled to [0, 1] for integers
};

// The file's pixels as it stores them: alpha left straight where it is.
inline ReadBack readBack(const std::filesystem::path& file) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(file.string(), &config);
  ReadBack r;
  if (!in) {
    ADD_FAILURE() << file << ": " << OIIO::geterror();
    return r;
  }
  r.spec = in->spec();
  r.pixels.resize(r.spec.image_pixels() * r.spec.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, r.spec.nchannels, OIIO::TypeDesc::FLOAT, r.pixels.data()))
      << in->geterror();
  return r;
}

}  // namespace image
