// Writing a rendered image in the format its file name asks for.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "renderer/render.h"

namespace tools {

// Whether files with this name's extension can be written: one of
// tools/common/output_file_format.h's, ".ppm" here and every other through
// OpenImageIO (whose module must load and take it).
bool canWriteImage(const std::filesystem::path& path);

// Why canWriteImage is false for `path`, as the end of a sentence: which
// extensions to use instead, or that OpenImageIO's module could not be
// loaded, from where and why (.ppm needs none); nothing when it is true.
std::optional<std::string> imageRefusal(const std::filesystem::path& path);

// The bytes of a width x height image written to `path` when it is a ".ppm"
// (the header and three bytes a pixel); 0 for another format, whose size
// is known only once written.
std::uint64_t ppmFileSize(int width, int height, const std::filesystem::path& path);

// Writes the image, as binary PPM (P6) by hand for ".ppm" and through
// OpenImageIO for every other extension: floating-point formats (EXR) get the
// linear values as they are; 8-bit formats (PPM, PNG, ...) get each channel
// clamped to [0, 1] and rounded to the nearest of 256 levels, with no gamma.
// The file is written beside the target under a temporary name and renamed,
// so it appears whole or not at all.
// With `replace` false (--no-clobber), an existing file is kept and the
// write fails.
bool writeImageFile(const render::Image& image, const std::filesystem::path& path,
                    std::string& error, bool replace = true);

// The bytes of the image as binary PPM (P6, 8-bit): what a ".ppm" file
// holds, and what `sfrender -o -` writes to standard output.
std::string ppmImageBytes(const render::Image& image);

// The 8-bit level of a linear channel value: round(clamp(v, 0, 1) * 255).
unsigned char quantizeChannel(float value);

}  // namespace tools
