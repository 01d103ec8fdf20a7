// Scenes written by hand in the style of POV-Ray's tutorial convert to scene
// files that sfrender, at the field of view the reader reports, draws with
// the same objects in the same pixels as POV-Ray draws the original.
//
// POV-Ray renders the original text with one change: at the end of each
// object the reader converted, a texture layer of the object's own flat
// colour (an opaque top layer hides the object's own texture), and at the
// end of the file a black background. So the picture is POV-Ray's reading
// of the user's geometry, camera and transforms, not ours.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "libscene/formats/pov/pov_reader.h"
#include "libscene/formats/pov/pov_writer.h"
#include "libscene/testing/test_support.h"
#include "libscene/text/number.h"
#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "tests/pov/povray_runner.h"

namespace {

namespace fs = std::filesystem;

constexpr double kTutorialAgreement = 0.98;
constexpr int kTutorialWidth = 200;

using scene::testing::readText;

// The original text with each converted object's flat colour layered on top.
std::string flatVersion(const std::string& text, const std::vector<std::size_t>& ends) {
  std::vector<std::pair<std::size_t, std::size_t>> order;  // offset, object
  for (std::size_t i = 0; i < ends.size(); ++i) order.emplace_back(ends[i], i);
  std::sort(order.rbegin(), order.rend());
  std::string out = text;
  for (const auto& [offset, object] : order) {
    std::array<int, 3> rgb = scene::povFlatColour(object, ends.size());
    std::string layer = " texture { pigment { rgb <" + scene::formatNumber(rgb[0] / 255.0) + ", " +
                        scene::formatNumber(rgb[1] / 255.0) + ", " +
                        scene::formatNumber(rgb[2] / 255.0) +
                        "> } finish { emission 1 ambient 0 diffuse 0 specular 0 phong 0 "
                        "reflection 0 } } ";
    out.insert(offset, layer);
  }
  out += "\nglobal_settings { assumed_gamma 1.0 }\nbackground { rgb 0 }\n";
  return out;
}

std::vector<fs::path> tutorialScenes() {
  std::vector<fs::path> files;
  for (const auto& entry :
       fs::directory_iterator(fs::path(SCENE_TESTDATA_DIR) / "pov" / "tutorial")) {
    if (entry.path().extension() == ".pov") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class PovTutorial : public ::testing::TestWithParam<fs::path> {};

TEST_P(PovTutorial, SfrenderDrawsTheObjectsWherePovRayDoes) {
  if (!povtest::povrayProgram()) GTEST_SKIP() << "povray is not installed";
  std::string text = readText(GetParam());
  std::string name = GetParam().stem().string();
  scene::ReadOptions options;
  options.pov.imageWidth = kTutorialWidth;
  options.pov.imageHeight = kTutorialWidth * 3 / 4;
  scene::PovImport imported = scene::importPov(text, name + ".pov", options);
  ASSERT_TRUE(imported.read.ok()) << imported.read.diagnostics.items().front().message;
  const scene::Scene& scene = imported.read.scene;
  ASSERT_FALSE(scene.objects.empty());

  // The image that POV-Ray's camera is for, as the reader reports it.
  int width = kTutorialWidth;
  int height = static_cast<int>(std::lround(kTutorialWidth / imported.view.aspectRatio));
  std::string log;
  // A hand-written scene's own assumed_gamma decides POV-Ray's output: the
  // flat colours are decoded from linear levels.
  std::optional<povtest::Image8> image = povtest::renderWithPovray(
      flatVersion(text, imported.objectEnds), width, height, name, log, "File_Gamma=1.0");
  ASSERT_TRUE(image.has_value()) << log;
  std::vector<std::int32_t> povIds = povtest::flatObjectIds(*image, scene.objects.size());

  render::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.verticalFovDegrees = imported.view.verticalFovDegrees;
  std::vector<std::int32_t> ours = render::renderObjectIds(render::RenderScene(scene), settings);
  double same = povtest::agreement(ours, povIds);
  std::cout << "[ pov ] " << name << " (--fov " << scene::formatNumber(settings.verticalFovDegrees)
            << (imported.view.mirrored ? ", mirrored" : "") << "): " << 100.0 * same
            << "% of pixels show the same object\n";
  EXPECT_GE(same, kTutorialAgreement);
  // Every object shows: the test is about all of them.
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    EXPECT_NE(std::find(povIds.begin(), povIds.end(), static_cast<std::int32_t>(i)), povIds.end())
        << "object " << i << " is not in POV-Ray's picture";
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PovTutorial, ::testing::ValuesIn(tutorialScenes()),
                         [](const ::testing::TestParamInfo<fs::path>& info) {
                           std::string n = info.param.stem().string();
                           for (char& c : n) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return n;
                         });

}  // namespace
