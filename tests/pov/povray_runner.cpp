#include "tests/pov/povray_runner.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "libscene/formats/pov/pov_writer.h"

namespace povtest {

namespace fs = std::filesystem;

std::optional<std::string> povrayProgram() {
#ifdef POVRAY_PROGRAM
  if (fs::exists(POVRAY_PROGRAM)) return std::string(POVRAY_PROGRAM);
#endif
  return std::nullopt;
}

std::optional<Image8> readImage8(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return std::nullopt;
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3) return std::nullopt;
  std::vector<std::uint8_t> all(static_cast<std::size_t>(spec.width) * spec.height *
                                spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, all.data())) {
    return std::nullopt;
  }
  Image8 image;
  image.width = spec.width;
  image.height = spec.height;
  image.rgb.resize(static_cast<std::size_t>(spec.width) * spec.height * 3);
  for (std::size_t p = 0; p < static_cast<std::size_t>(spec.width) * spec.height; ++p) {
    for (int c = 0; c < 3; ++c) image.rgb[3 * p + c] = all[p * spec.nchannels + c];
  }
  return image;
}

std::optional<Image8> renderWithPovray(const std::string& povText, int width, int height,
                                       const std::string& name, std::string& log,
                                       const std::string& options) {
  std::optional<std::string> program = povrayProgram();
  if (!program) {
    log = "no povray program";
    return std::nullopt;
  }
  fs::path dir = fs::temp_directory_path() / ("sfpov-" + std::to_string(::getpid()) + "-" + name);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.pov", std::ios::binary) << povText;
  // POV-Ray's own security settings let it write into the current folder.
  std::string command = "cd '" + dir.string() + "' && '" + *program +
                        "' +Iscene.pov +Oimage.ppm +FP -A -D -V +W" + std::to_string(width) +
                        " +H" + std::to_string(height) + " " + options + " > povray.log 2>&1";
  int status = std::system(command.c_str());
  std::ifstream logFile(dir / "povray.log");
  std::ostringstream text;
  text << logFile.rdbuf();
  log = text.str();
  std::optional<Image8> image;
  if (status == 0) image = readImage8((dir / "image.ppm").string());
  if (!image) {
    log = "povray failed (status " + std::to_string(status) + ") in " + dir.string() + ":\n" + log;
    return std::nullopt;
  }
  if (!std::getenv("SFPOV_KEEP")) fs::remove_all(dir);
  return image;
}

std::vector<std::int32_t> flatObjectIds(const Image8& image, std::size_t objectCount) {
  std::vector<std::int32_t> ids(static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t p = 0; p < ids.size(); ++p) {
    std::array<int, 3> rgb = {image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]};
    std::optional<long long> object = scene::povFlatObject(rgb, objectCount);
    ids[p] = object ? static_cast<std::int32_t>(*object) : -2;
  }
  return ids;
}

double agreement(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b) {
  if (a.size() != b.size() || a.empty()) return 0.0;
  std::size_t same = 0;
  for (std::size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
  return static_cast<double>(same) / static_cast<double>(a.size());
}

}  // namespace povtest
