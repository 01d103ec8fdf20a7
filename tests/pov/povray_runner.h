// Running POV-Ray 3.7 headless from a test, and what the tests compare: an
// object per pixel from a flat render, 8-bit images.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenefile/scene.h"

namespace povtest {

// Linear 8-bit RGB, row by row from the top.
struct Image8 {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
};

// The povray program the build found, or nothing when there is none.
std::optional<std::string> povrayProgram();

// Renders POV-Ray scene text headless at width x height, one sample per
// pixel at the pixel centre (-A), at POV-Ray's default gamma settings, as
// `povray +I... +O... +FP -A -D -V`: the scene text itself must keep the
// output linear, as the writer's does. `name` names the files in a folder of
// its own (kept on failure). Nothing, with the reason in `log`, on failure.
// `options` are added to the command line.
std::optional<Image8> renderWithPovray(const std::string& povText, int width, int height,
                                       const std::string& name, std::string& log,
                                       const std::string& options = {});

// The object each pixel of a flat render shows (pov_writer.h's colours), -1
// for none, -2 for a colour that is no object's.
std::vector<std::int32_t> flatObjectIds(const Image8& image, std::size_t objectCount);

// The fraction of pixels on which two object-id pictures agree.
double agreement(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b);

// An image file read as 8-bit RGB (PPM, PNG, ...), for a test's own files.
std::optional<Image8> readImage8(const std::string& path);

}  // namespace povtest
