// sfbuild_idcompare SCENE SHOT.ppm [EDGE] [MAX_FRACTION]: compares a
// screenshot of sfbuild's id view (F9) with the object each pixel's centre
// ray meets in the renderer (render::renderObjectIds) at the same size.
// Pixels within EDGE pixels (default 2) of a boundary between two ids of the
// renderer's picture are not compared: there the builder's tessellated
// meshes and the exact shapes may differ by a pixel. Of the others, at most
// MAX_FRACTION (default 0.001) may disagree. Exit 0 when they agree.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "renderer/render.h"
#include "scenefile/read.h"
#include "tools/common/file_io.h"
#include "tools/sfbuild/builder_state.h"

namespace {

// Binary PPM (P6), maxval 255.
bool readPpm(const std::string& path, int& width, int& height, std::vector<unsigned char>& rgb) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int maxval = 0;
  auto skip = [&] {
    while (in >> std::ws && in.peek() == '#') {
      std::string comment;
      std::getline(in, comment);
    }
  };
  in >> magic;
  skip();
  in >> width;
  skip();
  in >> height;
  skip();
  in >> maxval;
  in.get();
  if (!in || magic != "P6" || maxval != 255 || width <= 0 || height <= 0) return false;
  rgb.resize(static_cast<std::size_t>(width) * height * 3);
  in.read(reinterpret_cast<char*>(rgb.data()), static_cast<std::streamsize>(rgb.size()));
  return static_cast<std::size_t>(in.gcount()) == rgb.size();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: sfbuild_idcompare SCENE SHOT.ppm [EDGE] [MAX_FRACTION]\n";
    return 2;
  }
  int edge = argc > 3 ? std::stoi(argv[3]) : 2;
  double maxFraction = argc > 4 ? std::stod(argv[4]) : 0.001;
  tools::Outcome<std::string> text = tools::readWholeFile(argv[1]);
  if (!text) {
    std::cerr << text.failure().message << "\n";
    return tools::toInt(text.failure().code);
  }
  scene::ReadResult result = scene::parseScene(*text, argv[1]);
  if (!result.ok()) {
    std::cerr << argv[1] << ": not a valid scene\n";
    return 1;
  }
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  if (!readPpm(argv[2], width, height, rgb)) {
    std::cerr << argv[2] << ": not a binary PPM with maxval 255\n";
    return 3;
  }
  render::RenderScene renderScene(result.scene);
  render::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.verticalFovDegrees = sfbuild::kVerticalFovDegrees;
  std::vector<std::int32_t> ids = render::renderObjectIds(renderScene, settings);
  auto at = [&](int x, int y) { return ids[static_cast<std::size_t>(y) * width + x]; };

  long compared = 0, differing = 0, skipped = 0;
  std::vector<long> perObject(result.scene.objects.size() + 1, 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::int32_t id = at(x, y);
      bool nearEdge = false;
      for (int dy = -edge; dy <= edge && !nearEdge; ++dy) {
        for (int dx = -edge; dx <= edge && !nearEdge; ++dx) {
          int u = x + dx, v = y + dy;
          if (u < 0 || v < 0 || u >= width || v >= height) continue;
          nearEdge = at(u, v) != id;
        }
      }
      if (nearEdge) {
        ++skipped;
        continue;
      }
      ++compared;
      const unsigned char* p = &rgb[3 * (static_cast<std::size_t>(y) * width + x)];
      int shown = sfbuild::idFromColour(p[0], p[1], p[2]);
      if (shown != id) {
        ++differing;
      } else {
        ++perObject[static_cast<std::size_t>(id + 1)];
      }
    }
  }
  double fraction = compared ? static_cast<double>(differing) / compared : 1.0;
  std::cout << width << "x" << height << ": " << compared << " pixels compared, " << skipped
            << " within " << edge << " px of an edge skipped, " << differing << " differ (fraction "
            << fraction << ", allowed " << maxFraction << ")\n";
  for (std::size_t i = 0; i < perObject.size(); ++i) {
    std::cout << "  " << (i == 0 ? std::string("background") : "object " + std::to_string(i - 1))
              << ": " << perObject[i] << " pixels agree\n";
  }
  // Every object the renderer sees must be seen by the builder too.
  for (std::size_t i = 1; i < perObject.size(); ++i) {
    bool visible = false;
    for (std::int32_t id : ids) visible = visible || id == static_cast<std::int32_t>(i - 1);
    if (visible && perObject[i] == 0) {
      std::cout << "object " << i - 1 << " is in the render but nowhere in the screenshot\n";
      return 1;
    }
  }
  return fraction <= maxFraction ? 0 : 1;
}
