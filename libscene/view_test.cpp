// The view in the model: a POV-Ray or glTF camera's field of view and
// aspect ratio are read into Scene::view, kept through conversions between
// the formats that hold one, and absent from the formats that do not.
#include <gtest/gtest.h>

#include <string>

#include "libscene/formats/pov/pov_reader.h"
#include "libscene/testing/test_support.h"
#include "scenefile/convert.h"
#include "scenefile/read.h"

namespace scene {
namespace {

const std::string kPov =
    "camera { location <0, 1, -8> look_at <0, 0, 0> angle 50 right x*16/9 }\n"
    "light_source { <0, 10, -10> color rgb 1 }\n"
    "sphere { <0, 0, 0>, 1 pigment { color rgb <1, 0, 0> } }\n";

const std::string kSceneFile = testing::kCameraRecord +
                               "LIGHT\n1 1 1\n1 0 0 0\n0 1 0 5\n0 0 1 0\n0 0 0 1\n"
                               "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 -3\n0 0 0 1\n";

ReadResult through(const Scene& scene, Format format, const ConversionOptions& options = {}) {
  DiagnosticList out;
  std::optional<std::string> text = convertScene(scene, format, options, out);
  EXPECT_TRUE(text.has_value()) << formatInfo(format).name;
  return parseSceneAs(format, text.value_or(""), "back" + std::string(formatInfo(format).extensions[0]));
}

TEST(View, APovCameraGivesTheViewItsReaderReports) {
  PovImport imported = importPov(kPov, "a.pov");
  ASSERT_TRUE(imported.read.ok());
  ASSERT_TRUE(imported.read.scene.view);
  const View& view = *imported.read.scene.view;
  EXPECT_EQ(view.verticalFovDegrees, imported.view.verticalFovDegrees);
  ASSERT_TRUE(view.aspectRatio);
  EXPECT_DOUBLE_EQ(*view.aspectRatio, 16.0 / 9.0);
  EXPECT_TRUE(view.span.known());
  // parseScene gives the same scene.
  ReadResult read = parseScene(kPov, "a.pov");
  ASSERT_TRUE(read.ok());
  EXPECT_EQ(read.scene.view, imported.read.scene.view);
}

TEST(View, ScenesAndInstructionFilesHoldNone) {
  ReadResult read = parseScene(kSceneFile, "a.sf");
  ASSERT_TRUE(read.ok());
  EXPECT_FALSE(read.scene.view);
  EXPECT_FALSE(formatInfo(Format::SceneFile).holds.view);
  EXPECT_FALSE(formatInfo(Format::InstructionFile).holds.view);
  EXPECT_FALSE(through(read.scene, Format::InstructionFile).scene.view);
}

// Each format that holds a view gives it back, and glTF also keeps that a
// scene had none (its extras say "view": false).
TEST(View, IsKeptByEveryFormatThatHoldsOne) {
  ReadResult pov = parseScene(kPov, "a.pov");
  ASSERT_TRUE(pov.ok() && pov.scene.view);
  ReadResult sf = parseScene(kSceneFile, "a.sf");
  ASSERT_TRUE(sf.ok());
  for (const FormatInfo& row : formats()) {
    if (!row.holds.view) continue;
    ReadResult back = through(pov.scene, row.format);
    ASSERT_TRUE(back.ok()) << row.name;
    ASSERT_TRUE(back.scene.view) << row.name;
    EXPECT_NEAR(back.scene.view->verticalFovDegrees, pov.scene.view->verticalFovDegrees, 1e-6)
        << row.name;
    ASSERT_TRUE(back.scene.view->aspectRatio) << row.name;
    EXPECT_NEAR(*back.scene.view->aspectRatio, *pov.scene.view->aspectRatio, 1e-2) << row.name;
    if (row.format == Format::Gltf || row.format == Format::Glb) {
      EXPECT_FALSE(through(sf.scene, row.format).scene.view) << row.name;
    }
  }
}

// An option given for the output wins over the scene's view.
TEST(View, TheOptionsFieldOfViewWinsOverTheScenes) {
  ReadResult pov = parseScene(kPov, "a.pov");
  ASSERT_TRUE(pov.ok());
  ConversionOptions options;
  options.gltf.yfovDegrees = 35.0;
  options.pov.verticalFovDegrees = 35.0;
  for (Format format : {Format::Gltf, Format::Pov}) {
    ReadResult back = through(pov.scene, format, options);
    ASSERT_TRUE(back.scene.view);
    EXPECT_NEAR(back.scene.view->verticalFovDegrees, 35.0, 1e-6) << formatInfo(format).name;
  }
  // A scene file written with a field of view into glTF has that view.
  ReadResult sf = parseScene(kSceneFile, "a.sf");
  ReadResult back = through(sf.scene, Format::Gltf, options);
  ASSERT_TRUE(back.scene.view);
  EXPECT_NEAR(back.scene.view->verticalFovDegrees, 35.0, 1e-6);
}

TEST(View, ANonFiniteViewIsRefusedBeforeAnyWriter) {
  ReadResult sf = parseScene(kSceneFile, "a.sf");
  Scene scene = sf.scene;
  scene.view = View{std::numeric_limits<double>::quiet_NaN(), std::nullopt, {}};
  DiagnosticList out;
  EXPECT_FALSE(convertScene(scene, Format::Gltf, {}, out));
  EXPECT_EQ(testing::withCode(out, DiagnosticCode::ValueNotFinite).size(), 1u);
}

}  // namespace
}  // namespace scene
