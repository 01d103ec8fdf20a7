#include <gtest/gtest.h>

#include <string>

#include "libscene/formats/instruction/instruction_reader.h"
#include "libscene/formats/instruction/instruction_writer.h"
#include "libscene/formats/sf/sf_reader.h"
#include "libscene/formats/sf/sf_writer.h"
#include "libscene/testing/test_support.h"
#include "scenefile/convert.h"
#include "scenefile/transform.h"

namespace scene {
namespace {

using testing::expectOne;
using testing::smallScene;
using testing::withCode;

TEST(SceneFileWriter, WritesRecordsRowByRow) {
  EXPECT_EQ(writeSceneFile(smallScene()),
            "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n"
            "\nLIGHT\n1 0.5 0.25\n1 0 0 3\n0 1 0 3\n0 0 1 3\n0 0 0 1\n"
            "\nSPHERE\n1 0 0\n1 0 0 0.1\n0 1 0 -0\n0 0 1 1e-300\n0 0 0 1\n");
}

TEST(SceneFileWriter, ReadsBackEqual) {
  Scene s = smallScene();
  ReadResult r = parseSceneFile(writeSceneFile(s), "x.sf");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.scene, s);
}

TEST(InstructionWriter, WritesEveryMaterialValueAndTheOperations) {
  Scene s = smallScene();
  s.outputFile = "pic.ppm";
  s.camera.lookAt = glm::dvec3(0, 0, 0);
  s.objects[0].material.ambient = 0.25;
  s.objects[0].transforms =
      std::vector<TransformOp>{{TransformKind::Translate, glm::dvec3(1, 2, 3), {}},
                               {TransformKind::RotateY, glm::dvec3(0.5, 0, 0), {}}};
  s.objects[0].matrix = composeTransform(*s.objects[0].transforms);
  DiagnosticList out;
  std::optional<std::string> text = writeInstructionFile(s, {}, out);
  ASSERT_TRUE(text.has_value());
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(*text,
            "OUTPUT_FILE pic.ppm\n\n"
            "START CAMERA\n  LOCATION 0 0 5\n  LOOK_AT 0 0 0\nEND CAMERA\n\n"
            "START LIGHT\n  LOCATION 3 3 3\n  COLOUR 1 0.5 0.25\nEND LIGHT\n\n"
            "START OBJECT SPHERE\n  START MATERIAL\n    COLOUR 1 0 0\n    AMBIENT 0.25\n"
            "    DIFFUSE 0.9\n    SPECULAR 0.9\n    SHININESS 200\n    REFLECTIVITY 0\n"
            "    TRANSPARENCY 0\n    RI 1\n  END MATERIAL\n"
            "  START TRANSFORMATION\n    TRANSLATE 1 2 3\n    ROTATE_Y 0.5\n"
            "  END TRANSFORMATION\nEND OBJECT\n");
  ReadResult back = parseInstructionFile(*text, "x.txt");
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back.scene, s);
}

TEST(InstructionWriter, DecomposesSceneFileMatrices) {
  Scene s = smallScene();
  DiagnosticList out;
  std::optional<std::string> text = writeInstructionFile(s, {}, out);
  ASSERT_TRUE(text.has_value());
  EXPECT_NE(text->find("OUTPUT_FILE output.ppm\n"), std::string::npos);
  EXPECT_NE(text->find("    TRANSLATE 0.1 -0 1e-300\n"), std::string::npos);
}

TEST(Conversion, ReportsEveryDroppedMaterialValue) {
  ReadResult r = parseInstructionFile(
      "OUTPUT_FILE a.ppm\nSTART CAMERA\nLOCATION 0 0 5\nLOOK_AT 0 0 0\nEND CAMERA\n"
      "START OBJECT CUBE\nSTART MATERIAL\nAMBIENT 0.2\nRI 1.5\nDIFFUSE 0.9\nEND MATERIAL\n"
      "END OBJECT\n",
      "a.txt");
  ASSERT_TRUE(r.ok());
  DiagnosticList out("a.txt");
  std::optional<std::string> text = convertScene(r.scene, Format::SceneFile, {}, out);
  ASSERT_TRUE(text.has_value());
  std::vector<Diagnostic> lost = withCode(out, DiagnosticCode::LossMaterial);
  ASSERT_EQ(lost.size(), 2u);  // DIFFUSE 0.9 is the default: nothing lost
  EXPECT_EQ(lost[0].message,
            "AMBIENT 0.2 of CUBE object 1 is dropped: a scene file keeps only the colour");
  EXPECT_EQ(lost[0].span.line, 6u);
  EXPECT_EQ(lost[0].severity, Severity::Warning);
  EXPECT_EQ(lost[1].message,
            "RI 1.5 of CUBE object 1 is dropped: a scene file keeps only the colour");
  expectOne(out, DiagnosticCode::DroppedOutputFile, 1, 13, Severity::Note);

  DiagnosticList strict("a.txt");
  ConversionOptions noLoss;
  noLoss.noLoss = true;
  EXPECT_FALSE(convertScene(r.scene, Format::SceneFile, noLoss, strict).has_value());
  EXPECT_EQ(strict.errorCount(), 2u);
}

TEST(Conversion, ShearNeedsApproximate) {
  ReadResult r = parseSceneFile(
      std::string(testing::kCameraRecord) + "CUBE\n1 1 1\n1 0.5 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n",
      "s.sf");
  ASSERT_TRUE(r.ok());
  DiagnosticList out("s.sf");
  EXPECT_FALSE(convertScene(r.scene, Format::InstructionFile, {}, out).has_value());
  Diagnostic d = expectOne(out, DiagnosticCode::MatrixNotExpressible, 7, 1);
  EXPECT_EQ(d.hint, "'{0}' writes the nearest rotation and scale");
  EXPECT_EQ(d.remedies, (std::vector<Remedy>{{Setting::Approximate, "true"}}));

  ConversionOptions approximate;
  approximate.instructions.approximate = true;
  DiagnosticList moved("s.sf");
  std::optional<std::string> text =
      convertScene(r.scene, Format::InstructionFile, approximate, moved);
  ASSERT_TRUE(text.has_value());
  Diagnostic w = expectOne(moved, DiagnosticCode::MatrixApproximated, 7, 1, Severity::Warning);
  ASSERT_EQ(w.notes.size(), 4u);  // m00, m01, m10 and m11 move; the rest stay
  EXPECT_NE(w.notes[1].message.find("m01 moves from 0.5 to 0.256"), std::string::npos)
      << w.notes[1].message;
  ReadResult back = parseInstructionFile(*text, "s.txt");
  EXPECT_TRUE(back.ok());

  approximate.noLoss = true;
  DiagnosticList strict("s.sf");
  EXPECT_FALSE(convertScene(r.scene, Format::InstructionFile, approximate, strict));
}

TEST(Conversion, RolledCameraNeedsApproximate) {
  // Up is -X: the camera is rolled by 90 degrees.
  ReadResult r = parseSceneFile(
      "CAMERA\n0 0 0\n0 -1 0 0\n1 0 0 0\n0 0 1 5\n0 0 0 1\n" + std::string(testing::kLightRecord),
      "c.sf");
  ASSERT_TRUE(r.ok());
  DiagnosticList out("c.sf");
  EXPECT_FALSE(convertScene(r.scene, Format::InstructionFile, {}, out).has_value());
  Diagnostic d = expectOne(out, DiagnosticCode::LossCameraRoll, 1, 1);
  EXPECT_NE(d.message.find("rolled by -90 degrees"), std::string::npos) << d.message;
  ConversionOptions approximate;
  approximate.instructions.approximate = true;
  DiagnosticList moved("c.sf");
  EXPECT_TRUE(convertScene(r.scene, Format::InstructionFile, approximate, moved));
  expectOne(moved, DiagnosticCode::CameraRollApproximated, 1, 1, Severity::Warning);
}

TEST(Conversion, LightMatricesKeepOnlyTheirPosition) {
  ReadResult r = parseSceneFile(
      std::string(testing::kCameraRecord) + "LIGHT\n1 1 1\n2 0 0 1\n0 2 0 1\n0 0 2 1\n0 0 0 1\n",
      "l.sf");
  ASSERT_TRUE(r.ok());
  DiagnosticList out("l.sf");
  std::optional<std::string> text = convertScene(r.scene, Format::InstructionFile, {}, out);
  ASSERT_TRUE(text.has_value());
  expectOne(out, DiagnosticCode::IgnoredLightMatrix, 7, 1, Severity::Note);
  EXPECT_NE(text->find("  LOCATION 1 1 1\n"), std::string::npos);
}

}  // namespace
}  // namespace scene
