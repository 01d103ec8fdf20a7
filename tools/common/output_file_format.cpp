#include "tools/common/output_file_format.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace tools {

namespace {

// RGB formats that OpenImageIO 2.4 (Debian 12) writes, 8-bit but for the
// last two (floating point); a test checks that its module takes each.
// Formats it also writes but that would lose or mangle an RGB image (.pgm,
// .gif) or are no file at all (.term, .null) are left out.
constexpr std::array<std::string_view, 12> kImageExtensions = {
    ".ppm", ".pnm", ".png",  ".jpg",  ".jpeg", ".bmp",
    ".tga", ".tif", ".tiff", ".webp", ".exr",  ".hdr",
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

std::string imageExtensionList() {
  std::string list;
  for (std::size_t i = 0; i < kImageExtensions.size(); ++i) {
    if (i > 0) list += i + 1 == kImageExtensions.size() ? " or " : ", ";
    list += kImageExtensions[i];
  }
  return list;
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
      .hint = "name the image with " + imageExtensionList();
}

}  // namespace tools
