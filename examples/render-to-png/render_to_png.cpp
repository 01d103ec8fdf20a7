// render-to-png SCENE IMAGE.png [WIDTH HEIGHT]: reads a scene in any format
// the library knows, prints its diagnostics as sfcheck does, renders it with
// a progress line and writes the 8-bit image as a PNG. Exit 1: the scene has
// errors; 2: a usage error; 3: a file that cannot be read or written.
#include <png.h>
#include <scenefile/diagnostic_format.h>
#include <scenefile/read_file.h>
#include <scenefile/render.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

// Writes the PNG into `file` with `png`: false where libpng failed (it
// jumps back here). Nothing local changes after setjmp.
bool writeRows(png_structp png, png_infop info, std::FILE* file, int width, int height,
               const std::vector<std::uint8_t>& levels) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y) {
    png_write_row(png, levels.data() + static_cast<std::size_t>(y) * width * 3);
  }
  png_write_end(png, info);
  return true;
}

// The 8-bit levels as an RGB PNG, rows from the top.
bool writePng(const std::string& path, int width, int height,
              const std::vector<std::uint8_t>& levels) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  bool written = info && writeRows(png, info, file, width, height, levels);
  png_destroy_write_struct(&png, &info);
  written = std::fclose(file) == 0 && written;
  if (!written) std::remove(path.c_str());  // no half-written image
  return written;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 5) {
    std::cerr << "usage: render-to-png SCENE IMAGE.png [WIDTH HEIGHT]\n";
    return 2;
  }
  scene::RenderSettings settings;
  if (argc == 5) {
    settings.width = std::atoi(argv[3]);
    settings.height = std::atoi(argv[4]);
    if (settings.width < 1 || settings.height < 1) {
      std::cerr << "render-to-png: the width and height are whole numbers from 1\n";
      return 2;
    }
  }

  scene::SourceExcerpts quotes;
  scene::ReadResult read = scene::readSceneFile(argv[1], {}, &quotes);
  std::cerr << scene::formatDiagnostics(read.diagnostics, {}, &quotes);
  for (const scene::Diagnostic& d : read.diagnostics.items()) {
    if (d.code == scene::DiagnosticCode::CannotReadFile) return 3;
  }
  if (!read.ok()) return 1;

  // A glTF or POV-Ray camera's field of view and aspect ratio, as sfrender
  // takes them.
  std::optional<int> width, height;
  if (argc == 5) width = settings.width, height = settings.height;
  scene::applySceneView(read.scene, width, height, false, settings);

  scene::RenderControl control;
  control.progress = [](int done, int total) {
    std::fprintf(stderr, "\rrendering: %3d%%", done * 100 / total);
    if (done == total) std::fputc('\n', stderr);
  };
  scene::RenderedImage image = scene::renderScene(read.scene, settings, control);
  if (!writePng(argv[2], image.width, image.height, scene::eightBitLevels(image))) {
    std::cerr << argv[2] << ": error: cannot write the image\n";
    return 3;
  }
  return 0;
}
