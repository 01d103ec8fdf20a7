// The view in the model: a POV-Ray or glTF camera's field of view and
// aspect ratio are read into Scene::view, kept through conversions between
// the formats that hold one, and absent from the formats that do not.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "libscene/formats/pov/pov_reader.h"
#include "libscene/testing/test_support.h"
#include "libscene/text/number.h"
#include "scenefile/convert.h"
#include "scenefile/read.h"
#include "scenefile/validation.h"

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
  return parseSceneAs(format, text.value_or(""),
                      "back" + std::string(formatInfo(format).extensions[0]));
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

// One range for a view, wherever it comes from: validateScene refuses a
// scene holding one outside it, every writer refuses to write one (the
// scene's or its options'), and every value inside reads back.
TEST(View, OneRangeHoldsForTheValidatorAndEveryWriter) {
  ReadResult sf = parseScene(kSceneFile, "a.sf");
  ASSERT_TRUE(sf.ok());
  const double outFov[] = {-5, 0, 4.9e-324, 1e-300, 0.0009, 179.9991, 180, 1e300};
  const double outAspect[] = {-1, 0, 1e-300, 1.0 / 32769, 32769, 1e300};
  std::vector<View> outside;
  for (double fov : outFov) outside.push_back(View{fov, std::nullopt, {}});
  for (double aspect : outAspect) outside.push_back(View{60, aspect, {}});
  for (const View& view : outside) {
    SCOPED_TRACE(formatNumber(view.verticalFovDegrees) + " " +
                 formatNumber(view.aspectRatio.value_or(1)));
    Scene scene = sf.scene;
    scene.view = view;
    EXPECT_EQ(testing::withCode(validateScene(scene), DiagnosticCode::ValueOutOfRange).size(), 1u);
    for (const FormatInfo& row : formats()) {
      if (!row.write) continue;
      DiagnosticList out;
      EXPECT_FALSE(convertScene(scene, row.format, {}, out)) << row.name;
      EXPECT_EQ(testing::withCode(out, DiagnosticCode::ValueOutOfRange).size(), 1u) << row.name;
    }
  }
  for (double fov : outFov) {
    ConversionOptions options;
    options.gltf.yfovDegrees = fov;
    options.pov.verticalFovDegrees = fov;
    for (Format format : {Format::Gltf, Format::Pov}) {
      DiagnosticList out;
      EXPECT_FALSE(convertScene(sf.scene, format, options, out)) << fov;
    }
  }
  for (auto [width, height] : {std::pair{32769, 480}, {640, -1}, {1, 32769}}) {
    ConversionOptions options;
    options.gltf.width = options.pov.width = width;
    options.gltf.height = options.pov.height = height;
    for (Format format : {Format::Gltf, Format::Pov}) {
      DiagnosticList out;
      EXPECT_FALSE(convertScene(sf.scene, format, options, out)) << width << "x" << height;
    }
  }
  // The edges of the range, through every format that holds a view.
  for (View view : {View{kMinFovDegrees, kMinAspectRatio, {}}, View{kMaxFovDegrees, 1.0, {}},
                    View{kMaxFovDegrees, kMaxAspectRatio, {}}, View{kMinFovDegrees, 1.0, {}}}) {
    Scene scene = sf.scene;
    scene.view = view;
    EXPECT_TRUE(validateScene(scene).empty());
    for (const FormatInfo& row : formats()) {
      if (!row.holds.view) continue;
      SCOPED_TRACE(std::string(row.name) + " " + formatNumber(view.verticalFovDegrees) + " " +
                   formatNumber(*view.aspectRatio));
      ReadResult back = through(scene, row.format);
      ASSERT_TRUE(back.ok());
      ASSERT_TRUE(back.scene.view);
      EXPECT_NEAR(back.scene.view->verticalFovDegrees, view.verticalFovDegrees, 1e-6);
      ASSERT_TRUE(back.scene.view->aspectRatio);
      // POV-Ray's image is whole pixels, 480 rows at the ratio, as
      // The renderer's: a ratio beyond 32768:480 is that of the nearest size.
      if (row.format == Format::Pov) continue;
      EXPECT_NEAR(*back.scene.view->aspectRatio / *view.aspectRatio, 1.0, 1e-9);
    }
  }
}

// A POV-Ray camera whose view is out of range is still a camera: the view is
// dropped with a loss warning, as a glTF camera's is.
TEST(View, APovCameraOutOfRangeLosesItsView) {
  ReadResult read = parseScene(
      "camera { location <0, 1, -8> look_at <0, 0, 0> angle 0.0001 }\n"
      "light_source { <0, 10, -10> color rgb 1 }\n",
      "a.pov");
  EXPECT_TRUE(read.ok());
  EXPECT_FALSE(read.scene.view);
  EXPECT_EQ(testing::withCode(read.diagnostics, DiagnosticCode::PovLoss).size(), 1u);
}

}  // namespace
}  // namespace scene
