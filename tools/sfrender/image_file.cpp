#include "tools/sfrender/image_file.h"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "tools/common/file_io.h"
#include "tools/common/output_file_format.h"

namespace tools {

namespace {

// The functions of the OpenImageIO module (oiio_module.cpp).
struct OiioModule {
  int (*format)(const char* path) = nullptr;
  int (*write)(const char* path, int width, int height, int floating, const void* pixels,
               char* error, std::size_t errorSize) = nullptr;
};

#ifndef SFRENDER_MODULE_DIR
#define SFRENDER_MODULE_DIR "../lib/scenefile"
#endif

// The module's file: in SFRENDER_MODULE_DIR (tools/CMakeLists.txt: the
// prefix's lib/scenefile/ seen from its bin/), relative to the folder of the
// running program as /proc/self/exe names it, so that an installed prefix
// works wherever it is moved; the build folder has the same layout. Empty
// when the program's own path cannot be read.
std::filesystem::path oiioModulePath() {
  std::error_code failed;
  std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", failed);
  if (failed || program.empty()) return {};
  return (program.parent_path() / SFRENDER_MODULE_DIR / "sfrender_oiio.so").lexically_normal();
}

// Why the module did not load, for a message that says where it was looked for.
std::string moduleFailure(const std::filesystem::path& file, const std::string& why) {
  if (file.empty()) {
    return "OpenImageIO's module (sfrender_oiio.so), which writes every format but .ppm, could "
           "not be loaded: the program's own path (/proc/self/exe), which it is found from, "
           "cannot be read";
  }
  std::string reason = why;
  std::string prefix = file.string() + ": ";
  if (reason.compare(0, prefix.size(), prefix) == 0) reason.erase(0, prefix.size());
  return "OpenImageIO's module, which writes every format but .ppm, could not be loaded from " +
         file.string() + (reason.empty() ? "" : " (" + reason + ")");
}

// Loads the module (oiioModulePath). dlopen counts its loads, so a second
// call is cheap; the module is never unloaded, as OpenImageIO's threads may
// outlive a write.
std::optional<OiioModule> loadOiio(std::string& error) {
  std::filesystem::path file = oiioModulePath();
  if (file.empty()) {
    error = moduleFailure(file, "");
    return std::nullopt;
  }
  void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = ::dlerror();
    error = moduleFailure(file, why ? why : "");
    return std::nullopt;
  }
  OiioModule m;
  m.format = reinterpret_cast<decltype(m.format)>(::dlsym(handle, "sfrender_oiio_format"));
  m.write = reinterpret_cast<decltype(m.write)>(::dlsym(handle, "sfrender_oiio_write"));
  if (!m.format || !m.write) {
    error = moduleFailure(file, "it lacks its functions");
    return std::nullopt;
  }
  return m;
}

// Binary PPM (P6, 8-bit) is written here rather than through OpenImageIO:
// the format is a header and the bytes, and OpenImageIO's writer, which
// writes it a scanline at a time behind its plugin lookup, cost 0.15 to
// 0.2 s on a 1920x1080 image. Only the exact extension ".ppm" is taken.
bool isPpm(const std::filesystem::path& path) {
  return path.extension() == ".ppm";
}

}  // namespace

std::string ppmImageBytes(const render::Image& image) {
  std::string header =
      "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  std::string bytes(header.size() + image.rgb.size(), '\0');
  std::copy(header.begin(), header.end(), bytes.begin());
  std::transform(image.rgb.begin(), image.rgb.end(), bytes.begin() + header.size(),
                 [](float v) { return static_cast<char>(quantizeChannel(v)); });
  return bytes;
}

unsigned char quantizeChannel(float value) {
  float clamped = std::clamp(value, 0.0f, 1.0f);
  return static_cast<unsigned char>(std::lround(clamped * 255.0f));
}

std::optional<std::string> imageRefusal(const std::filesystem::path& path) {
  std::string useInstead = "use " + imageExtensionList();
  if (!hasImageExtension(path)) return useInstead;
  if (isPpm(path)) return std::nullopt;
  std::string error;
  std::optional<OiioModule> oiio = loadOiio(error);
  if (!oiio) return error + "; .ppm needs no module";
  if (oiio->format(path.c_str()) < 0) return useInstead;
  return std::nullopt;
}

bool canWriteImage(const std::filesystem::path& path) {
  return !imageRefusal(path);
}

std::uint64_t ppmFileSize(int width, int height, const std::filesystem::path& path) {
  if (!isPpm(path)) return 0;
  std::string header = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
  return header.size() +
         std::uint64_t{3} * static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
}

bool writeImageFile(const render::Image& image, const std::filesystem::path& path,
                    std::string& error, bool replace) {
  if (!hasImageExtension(path)) {
    error = "no image format for the extension '" + path.extension().string() + "'";
    return false;
  }
  bool ppm = isPpm(path);
  std::optional<OiioModule> oiio;
  int format = 0;
  if (!ppm) {
    oiio = loadOiio(error);
    if (!oiio) return false;
    format = oiio->format(path.c_str());
    if (format < 0) {
      error = "no image format for the extension '" + path.extension().string() + "'";
      return false;
    }
  }
  bool floating = format == 1;

  // The image goes to a temporary beside the target (file_io.h), which keeps
  // the target's extension so that OpenImageIO picks the same writer.
  StagedFile file;
  if (!file.open(path, true, error)) return false;
  if (ppm) {
    if (!file.write(ppmImageBytes(image), error)) return false;
  } else {
    bool ok = false;
    char message[512] = "";
    std::string temporary = file.temporaryPath().string();
    if (floating) {
      ok = oiio->write(temporary.c_str(), image.width, image.height, 1, image.rgb.data(), message,
                       sizeof message);
    } else {
      std::vector<unsigned char> bytes(image.rgb.size());
      std::transform(image.rgb.begin(), image.rgb.end(), bytes.begin(), quantizeChannel);
      ok = oiio->write(temporary.c_str(), image.width, image.height, 0, bytes.data(), message,
                       sizeof message);
    }
    if (!ok) {
      error = message;
      return false;
    }
  }
  return file.finish(error) && file.commit(error, replace);
}

}  // namespace tools
