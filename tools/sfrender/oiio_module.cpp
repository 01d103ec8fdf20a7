// The part of sfrender that needs OpenImageIO, built as a module that
// image_file.cpp loads with dlopen only when an image is written in a format
// other than PPM: linking OpenImageIO into the program made every run, even
// `sfrender --version`, relocate its ~260 shared libraries (0.26 s of CPU).
// A plain C interface, so that nothing of OpenImageIO crosses it.
#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <cstring>
#include <memory>
#include <string>

namespace {

void copyError(const std::string& message, char* error, std::size_t errorSize) {
  if (errorSize == 0) return;
  std::size_t n = std::min(message.size(), errorSize - 1);
  std::memcpy(error, message.data(), n);
  error[n] = '\0';
}

}  // namespace

extern "C" {

// 1 for a floating-point format (EXR, HDR), 0 for an 8-bit one, -1 when no
// writer takes the name's extension.
__attribute__((visibility("default"))) int sfrender_oiio_format(const char* path) {
  std::unique_ptr<OIIO::ImageOutput> probe = OIIO::ImageOutput::create(path);
  if (!probe) return -1;
  std::string name = probe->format_name();
  return name == "openexr" || name == "hdr" ? 1 : 0;
}

// Writes width x height RGB pixels, floats or bytes as `floating` says, to
// `path`; returns 1 on success, or 0 with a message in `error`. `path` is
// always image_file.cpp's temporary, which keeps the target's extension for
// OpenImageIO to choose its writer by, and is renamed over the target only
// once this returns: OpenImageIO writes the file in place, a part at a time.
__attribute__((visibility("default"))) int sfrender_oiio_write(const char* path, int width,
                                                               int height, int floating,
                                                               const void* pixels, char* error,
                                                               std::size_t errorSize) {
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  OIIO::TypeDesc type = floating ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(width, height, 3, type);
  spec.attribute("pnm:binary", 1);
  bool ok = out && out->open(path, spec);
  if (ok) ok = out->write_image(type, pixels);
  if (out) ok = out->close() && ok;
  if (!ok) {
    std::string message = out ? out->geterror() : OIIO::geterror();
    copyError(message.empty() ? "the image could not be written" : message, error, errorSize);
    return 0;
  }
  return 1;
}

}  // extern "C"
