#include "tools/sfrender/image_file.h"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

namespace tools {

namespace {

bool isFloatFormat(const std::string& formatName) {
  return formatName == "openexr" || formatName == "hdr";
}

}  // namespace

unsigned char quantizeChannel(float value) {
  float clamped = std::clamp(value, 0.0f, 1.0f);
  return static_cast<unsigned char>(std::lround(clamped * 255.0f));
}

bool canWriteImage(const std::filesystem::path& path) {
  return OIIO::ImageOutput::create(path.string()) != nullptr;
}

bool writeImageFile(const render::Image& image, const std::filesystem::path& path,
                    std::string& error) {
  std::unique_ptr<OIIO::ImageOutput> probe = OIIO::ImageOutput::create(path.string());
  if (!probe) {
    error = "no image format for the extension '" + path.extension().string() + "'";
    return false;
  }
  bool floating = isFloatFormat(probe->format_name());

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
  ::close(fd);
  std::string temporary(name.data());

  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(temporary);
  OIIO::ImageSpec spec(image.width, image.height, 3,
                       floating ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  spec.attribute("pnm:binary", 1);
  bool ok = out && out->open(temporary, spec);
  if (ok && floating) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data());
  } else if (ok) {
    std::vector<unsigned char> bytes(image.rgb.size());
    std::transform(image.rgb.begin(), image.rgb.end(), bytes.begin(), quantizeChannel);
    ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  }
  if (out) ok = out->close() && ok;
  if (!ok) {
    error = out ? out->geterror() : OIIO::geterror();
    if (error.empty()) error = "the image could not be written";
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
  // mkstemps made the file private; give it the mode a new file would get.
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

}  // namespace tools
