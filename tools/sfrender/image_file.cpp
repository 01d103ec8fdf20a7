#include "tools/sfrender/image_file.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

namespace tools {

namespace {

// The functions of the OpenImageIO module (oiio_module.cpp).
struct OiioModule {
  int (*format)(const char* path) = nullptr;
  int (*write)(const char* path, int width, int height, int floating, const void* pixels,
               char* error, std::size_t errorSize) = nullptr;
};

// Loads the module from beside the running program. dlopen counts its
// loads, so a second call is cheap; the module is never unloaded, as
// OpenImageIO's threads may outlive a write.
std::optional<OiioModule> loadOiio(std::string& error) {
  std::error_code ignored;
  std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ignored);
  std::filesystem::path file = program.parent_path() / "sfrender_oiio.so";
  void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = ::dlerror();
    error = "cannot load OpenImageIO's module: " + std::string(why ? why : file.string());
    return std::nullopt;
  }
  OiioModule m;
  m.format = reinterpret_cast<decltype(m.format)>(::dlsym(handle, "sfrender_oiio_format"));
  m.write = reinterpret_cast<decltype(m.write)>(::dlsym(handle, "sfrender_oiio_write"));
  if (!m.format || !m.write) {
    error = "cannot load OpenImageIO's module: " + file.string() + " lacks its functions";
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

bool writePpm(const render::Image& image, int fd) {
  std::string header =
      "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  std::vector<unsigned char> bytes(header.size() + image.rgb.size());
  std::copy(header.begin(), header.end(), bytes.begin());
  std::transform(image.rgb.begin(), image.rgb.end(), bytes.begin() + header.size(),
                 quantizeChannel);
  const unsigned char* next = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    ssize_t n = ::write(fd, next, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    next += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

// Gives the finished temporary file the mode a new file would get (mkstemps
// made it private) and the target's name.
bool finishTemporary(const std::string& temporary, const std::filesystem::path& path,
                     std::string& error) {
  mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(temporary.c_str(), 0666 & ~mask);
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    error = std::strerror(errno);
    ::unlink(temporary.c_str());
    return false;
  }
  return true;
}

}  // namespace

unsigned char quantizeChannel(float value) {
  float clamped = std::clamp(value, 0.0f, 1.0f);
  return static_cast<unsigned char>(std::lround(clamped * 255.0f));
}

bool canWriteImage(const std::filesystem::path& path) {
  if (isPpm(path)) return true;
  std::string ignored;
  std::optional<OiioModule> oiio = loadOiio(ignored);
  return oiio && oiio->format(path.c_str()) >= 0;
}

bool writeImageFile(const render::Image& image, const std::filesystem::path& path,
                    std::string& error) {
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

  // A temporary file beside the target, keeping its extension so that the
  // same writer handles it.
  std::filesystem::path folder = path.parent_path();
  std::string extension = path.extension().string();
  std::string pattern =
      (folder / ("." + path.stem().string() + ".tmp-XXXXXX" + extension)).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  int fd = ::mkstemps(name.data(), static_cast<int>(extension.size()));
  if (fd < 0) {
    error = std::strerror(errno);
    return false;
  }
  std::string temporary(name.data());
  if (ppm) {
    errno = 0;
    bool ok = writePpm(image, fd);
    int saved = errno;
    // On disk before it takes the target's name (see below).
    ok = ok && ::fsync(fd) == 0;
    ok = ::close(fd) == 0 && ok;
    if (!ok) {
      error = std::strerror(saved != 0 ? saved : errno);
      if (error.empty()) error = "the image could not be written";
      ::unlink(temporary.c_str());
      return false;
    }
    return finishTemporary(temporary, path, error);
  }
  ::close(fd);

  bool ok = false;
  char message[512] = "";
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
    ::unlink(temporary.c_str());
    return false;
  }
  // On disk before it takes the target's name, so that a crash cannot leave
  // a renamed but empty file.
  int written = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (written >= 0) {
    ::fsync(written);
    ::close(written);
  }
  return finishTemporary(temporary, path, error);
}

}  // namespace tools
