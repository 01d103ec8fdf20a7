#include "tools/common/output_file_format.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace tools {

namespace {

// What sfrender writes with Debian 12's OpenImageIO (2.4.7): its own .ppm,
// then the extensions of OpenImageIO's writers that sfrender takes
// (image/oiio_module.cpp leaves out those that make no file or
// cannot hold a rendered image: GIF, ICO, ZFile), in the order of sfrender's
// table of formats (image/image_formats.cpp). sfrender asks
// OpenImageIO at run time; sfcheck, which must not load it, has this copy,
// and a test (ImageFormats.SfchecksListIsOpenImageIOs) fails when the two
// part.
constexpr std::array<std::string_view, 43> kImageExtensions = {
    ".ppm", ".pgm", ".pbm",  ".pnm",  ".png",  ".tif",   ".tiff", ".tx",   ".env", ".sm",   ".vsm",
    ".exr", ".sxr", ".mxr",  ".hdr",  ".rgbe", ".jpg",   ".jpe",  ".jpeg", ".jif", ".jfif", ".jfi",
    ".jp2", ".j2k", ".webp", ".heic", ".heif", ".heics", ".avif", ".bmp",  ".tga", ".tpic", ".dpx",
    ".sgi", ".rgb", ".rgba", ".bw",   ".int",  ".inta",  ".fits", ".iff",  ".z",   ".rla",
};

}  // namespace

std::span<const std::string_view> imageExtensions() {
  return kImageExtensions;
}

bool hasImageExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return std::find(kImageExtensions.begin(), kImageExtensions.end(), extension) !=
         kImageExtensions.end();
}

void checkOutputFileFormat(const scene::Scene& scene, scene::Severity severity,
                           scene::DiagnosticList& out) {
  if (!scene.outputFile || hasImageExtension(*scene.outputFile)) return;
  std::filesystem::path name(*scene.outputFile);
  std::string why = name.extension().empty()
                        ? "has no extension, so no image format"
                        : "ends in '" + name.extension().string() + "', no image format";
  out.report(severity, scene::DiagnosticCode::OutputFileFormat, scene.outputFileSpan,
             "OUTPUT_FILE '" + *scene.outputFile + "' " + why + " sfrender can write")
      .hint = "name the image with .ppm, .png, .tif or .exr (sfrender --help lists every format)";
}

}  // namespace tools
