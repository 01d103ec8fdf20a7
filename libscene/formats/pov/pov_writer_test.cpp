// The POV-Ray writer: what it writes, what it reports, and that every scene
// of the corpus comes back from it bit for bit.
#include "libscene/formats/pov/pov_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "libscene/formats/pov/pov_reader.h"
#include "libscene/formats/sf/sf_writer.h"
#include "libscene/testing/test_support.h"
#include "libscene/text/number.h"
#include "scenefile/convert.h"
#include "scenefile/read.h"
#include "scenefile/transform.h"

namespace scene {
namespace {

using testing::smallScene;
using testing::withCode;

std::string povOf(const Scene& s, const PovWriteOptions& options = {}) {
  DiagnosticList out;
  std::optional<std::string> text = writePovScene(s, testing::conversionWith(options), out);
  EXPECT_TRUE(text.has_value());
  return text.value_or("");
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(PovWriter, WritesTheMatrixColumnByColumnForPovRaysRowVectors) {
  Scene s = smallScene();
  // A shear: x += 0.5 y, so column 1 is (0.5, 1, 0).
  s.objects[0].matrix[1][0] = 0.5;
  std::string text = povOf(s);
  EXPECT_TRUE(has(text, "sphere { 0, 1\n  matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0.1, -0, 1e-300>\n"))
      << text;
}

TEST(PovWriter, WritesTheSceneHeaderAndTheMaterial) {
  Scene s = smallScene();
  s.objects[0].material.ambient = 0.25;
  s.objects[0].material.reflectivity = 0.5;
  s.objects[0].material.ri = 1.5;
  std::string text = povOf(s);
  EXPECT_TRUE(has(text, "#version 3.7;\n")) << text;
  // ambient_light is the sum of the lights' colours, the bounces plus one.
  EXPECT_TRUE(has(text,
                  "global_settings { assumed_gamma srgb max_trace_level 6 adc_bailout 0 "
                  "ambient_light rgb <1, 0.5, 0.25> }"))
      << text;
  EXPECT_TRUE(has(text, "background { rgb 0 }")) << text;
  EXPECT_TRUE(has(text, "light_source { <3, 3, 3> color rgb <1, 0.5, 0.25> }")) << text;
  EXPECT_TRUE(has(text,
                  "  pigment { rgb <1, 0, 0> }\n  finish { ambient 0.25 diffuse 0.9 phong "
                  "0.9 phong_size 200 reflection 0.5 }\n  interior { ior 1.5 }\n"))
      << text;
}

TEST(PovWriter, WritesSfrendersCameraVectors) {
  Scene s = smallScene();
  PovWriteOptions options;
  options.verticalFovDegrees = 90.0;
  options.width = 200;
  options.height = 100;
  std::string text = povOf(s, options);
  // tan(45 degrees) = 1: up is 2 high, right 4 wide, right = forward x up.
  EXPECT_TRUE(has(text,
                  "  location <0, 0, 5>\n  direction <-0, -0, -1>\n"
                  "  right <3.9999999999999996, 0, 0>\n  up <0, 1.9999999999999998, 0>\n"))
      << text;
  EXPECT_TRUE(has(text,
                  "// sfconvert: camera matrix 1 0 0 0 0 1 0 0 0 0 1 5 0 0 0 1 colour 0 0 "
                  "0 fov 90 width 200 height 100\n"))
      << text;
}

TEST(PovWriter, CarriesALightsWholeMatrixInAComment) {
  Scene s = smallScene();
  s.lights[0].matrix[0][0] = 2.0;
  std::string text = povOf(s);
  EXPECT_TRUE(has(text,
                  "// sfconvert: light matrix 2 0 0 3 0 1 0 3 0 0 1 3 0 0 0 1\n"
                  "light_source { <3, 3, 3>"))
      << text;
}

TEST(PovWriter, TurnsAPlanesHalfSpaceAwayFromTheEye) {
  Scene s = smallScene();
  s.objects[0].kind = ObjectKind::Plane;
  s.objects[0].matrix = glm::dmat4(1.0);
  EXPECT_TRUE(has(povOf(s), "plane { y, 0\n"));
  s.objects[0].matrix[3][1] = 10.0;  // the plane y = 10, above the eye
  EXPECT_TRUE(has(povOf(s), "plane { -y, 0\n"));
}

TEST(PovWriter, ReportsWhatPovRayRendersDifferently) {
  Scene s = smallScene();
  s.objects[0].material.transparency = 0.5;
  s.objects[0].material.reflectivity = 0.25;
  DiagnosticList out;
  std::optional<std::string> text = writePovScene(s, {}, out);
  ASSERT_TRUE(text.has_value());
  EXPECT_TRUE(has(*text, "pigment { rgbt <1, 0, 0, 0.5> }"));
  std::vector<Diagnostic> losses = withCode(out, DiagnosticCode::LossPov);
  ASSERT_EQ(losses.size(), 2u);
  EXPECT_EQ(losses[0].severity, Severity::Warning);
  EXPECT_EQ(losses[0].message,
            "TRANSPARENCY 0.5 of SPHERE object 1 is written as POV-Ray's transmit, which "
            "renders differently");

  DiagnosticList errors;
  EXPECT_FALSE(writePovScene(s, testing::noLossConversion(), errors).has_value());
  EXPECT_EQ(errors.errorCount(), 2u);
}

TEST(PovWriter, FlatWritesUnlitIdentityColoursAndNoLights) {
  Scene s = smallScene();
  s.objects[0].material.transparency = 0.5;
  PovWriteOptions options;
  options.flat = true;
  DiagnosticList out;
  std::optional<std::string> text = writePovScene(s, testing::conversionWith(options), out);
  ASSERT_TRUE(text.has_value());
  EXPECT_TRUE(out.empty()) << "a flat picture is no conversion of the look";
  EXPECT_FALSE(has(*text, "light_source"));
  EXPECT_TRUE(has(*text, "ambient_light rgb <1, 1, 1>"));
  std::array<int, 3> rgb = povFlatColour(0, 1);
  std::ostringstream pigment;
  pigment << "pigment { rgb <" << formatNumber(rgb[0] / 255.0) << ", "
          << formatNumber(rgb[1] / 255.0) << ", " << formatNumber(rgb[2] / 255.0) << "> }";
  EXPECT_TRUE(has(*text, pigment.str())) << *text;
  EXPECT_TRUE(has(*text, "finish { ambient 1 diffuse 0 phong 0 specular 0 reflection 0 }"));
}

TEST(PovWriter, FlatColoursAreDistinctAndDecodeBack) {
  for (std::size_t count :
       {std::size_t{1}, std::size_t{12}, std::size_t{4095}, std::size_t{5000}}) {
    std::set<std::array<int, 3>> seen;
    for (std::size_t i = 0; i < count; ++i) {
      std::array<int, 3> rgb = povFlatColour(i, count);
      EXPECT_NE(rgb, (std::array<int, 3>{0, 0, 0}));
      EXPECT_TRUE(seen.insert(rgb).second) << i;
      EXPECT_EQ(povFlatObject(rgb, count), static_cast<long long>(i));
      if (count < 4096) {
        // A few levels of rounding still find the object.
        std::array<int, 3> off = {std::max(rgb[0] - 3, 0), std::min(rgb[1] + 3, 255), rgb[2]};
        EXPECT_EQ(povFlatObject(off, count), static_cast<long long>(i));
      }
    }
    EXPECT_EQ(povFlatObject({0, 0, 0}, count), -1);
  }
  EXPECT_FALSE(povFlatObject({8, 0, 0}, 10).has_value()) << "between two levels";
  // Neighbours look different.
  std::array<int, 3> a = povFlatColour(0, 10), b = povFlatColour(1, 10);
  EXPECT_GT(std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]), 100);
}

using scene::testing::readText;

// sf -> pov -> sf gives the same bytes as sf -> sf, for every valid file of
// the corpus (instruction files included), and instruction -> pov ->
// instruction gives the same bytes as instruction -> instruction.
TEST(PovRoundTrip, EveryCorpusSceneComesBackByteIdentical) {
  int files = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(SCENE_TESTDATA_DIR) / "valid")) {
    std::string ext = entry.path().extension().string();
    if (ext != ".sf" && ext != ".txt") continue;
    ReadResult read = parseScene(readText(entry.path()), entry.path().filename().string());
    if (!read.ok()) continue;
    ++files;
    SCOPED_TRACE(entry.path().filename().string());
    DiagnosticList out;
    std::optional<std::string> pov = writePovScene(read.scene, {}, out);
    ASSERT_TRUE(pov.has_value());
    PovImport back = importPov(*pov, "back.pov");
    ASSERT_TRUE(back.read.ok()) << back.read.diagnostics.items().front().message << "\n" << *pov;
    EXPECT_EQ(writeSceneFile(back.read.scene), writeSceneFile(read.scene)) << *pov;
    EXPECT_EQ(back.view.verticalFovDegrees, 60.0);
    EXPECT_FALSE(back.view.mirrored);
    if (ext == ".txt") {
      DiagnosticList a, b;
      std::optional<std::string> direct = convertScene(read.scene, Format::InstructionFile, {}, a);
      std::optional<std::string> viaPov =
          convertScene(back.read.scene, Format::InstructionFile, {}, b);
      ASSERT_TRUE(direct && viaPov);
      EXPECT_EQ(*viaPov, *direct);
    }
  }
  EXPECT_GE(files, 50);
}

}  // namespace
}  // namespace scene
