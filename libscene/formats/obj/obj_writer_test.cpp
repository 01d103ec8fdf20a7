// The OBJ writer: the camera and the lights are losses, the materials'
// MTL terms, the vertices in world space, and the triangles' turn.
#include "libscene/formats/obj/obj_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>

#include "libscene/formats/obj/obj_mtl.h"
#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

using testing::withCode;

constexpr std::string_view kObjScene =
    "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 1\n0 0 1 8\n0 0 0 1\n\n"
    "LIGHT\n1 1 1\n1 0 0 5\n0 1 0 5\n0 0 1 5\n0 0 0 1\n\n"
    "CUBE\n1 0 0\n1 0 0 10\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";

Scene readObj(std::string_view text) {
  ReadResult r = parseScene(text, "a.sf");
  EXPECT_TRUE(r.ok());
  return r.scene;
}

TEST(ObjWriter, TheCameraAndTheLightsAreLossesErrorsUnderNoLoss) {
  Scene scene = readObj(kObjScene);
  DiagnosticList out;
  ConversionOptions options;
  ASSERT_TRUE(writeObj(scene, options, out).has_value());
  std::vector<Diagnostic> losses = withCode(out, DiagnosticCode::ObjWriteLoss);
  ASSERT_EQ(losses.size(), 2u);
  EXPECT_EQ(losses[0].severity, Severity::Warning);
  EXPECT_NE(losses[0].message.find("CAMERA"), std::string::npos);
  EXPECT_NE(losses[1].message.find("LIGHT 1"), std::string::npos);
  EXPECT_EQ(losses[1].span.line, 8u);
  options.noLoss = true;
  DiagnosticList strict;
  EXPECT_FALSE(writeObj(scene, options, strict).has_value());
  EXPECT_EQ(strict.errorCount(), 2u);
}

TEST(ObjWriter, VerticesAreInWorldSpaceAndTheMtlIsTheSidecar) {
  Scene scene = readObj(kObjScene);
  DiagnosticList out;
  ConversionOptions options;
  options.obj.materialLibrary = "scene.mtl";
  std::optional<ConvertedFiles> files = writeObj(scene, options, out);
  ASSERT_TRUE(files.has_value());
  EXPECT_NE(files->main.find("mtllib scene.mtl\n"), std::string::npos);
  EXPECT_NE(files->main.find("o CUBE_1\nusemtl CUBE_1\n"), std::string::npos);
  // The unit cube moved by 10 along x: every x is 9 or 11.
  EXPECT_NE(files->main.find("\nv 11 "), std::string::npos) << files->main;
  EXPECT_NE(files->main.find("\nv 9 "), std::string::npos);
  EXPECT_EQ(files->main.find("\nvn "), std::string::npos) << "a box is flat: no normals";
  EXPECT_NE(files->sidecar.find("newmtl CUBE_1\nKa 0.1 0 0\nKd 0.9 0 0\nKs 0.9 0.9 0.9\n"
                                "Ns 200\nNi 1\nd 1\nillum 2\n"),
            std::string::npos)
      << files->sidecar;
  options.obj.materialLibrary.clear();
  files = writeObj(scene, options, out);
  ASSERT_TRUE(files.has_value());
  EXPECT_EQ(files->main.find("mtllib"), std::string::npos);
  EXPECT_EQ(files->main.find("usemtl"), std::string::npos);
  EXPECT_TRUE(files->sidecar.empty());
}

// OBJ numbers the vertices and the normals each on their own: a box writes
// no normals, so the sphere after it counts its normals from 1.
TEST(ObjWriter, FacesNameNormalsByTheirOwnNumbers) {
  std::string text(kObjScene);
  text += "\nSPHERE\n1 1 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  DiagnosticList out;
  std::string obj = writeObj(readObj(text), {}, out)->main;
  std::size_t normals = 0, vertices = 0, largest = 0, smallest = SIZE_MAX;
  std::istringstream lines(obj);
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("vn ")) ++normals;
    if (line.starts_with("v ")) ++vertices;
    for (std::size_t at = line.find("//"); line.starts_with("f ") && at != std::string::npos;
         at = line.find("//", at + 2)) {
      std::size_t n = std::stoul(line.substr(at + 2));
      largest = std::max(largest, n);
      smallest = std::min(smallest, n);
    }
  }
  EXPECT_GT(normals, 0u);
  EXPECT_EQ(smallest, 1u);
  EXPECT_EQ(largest, normals);
  EXPECT_GT(vertices, normals);
}

TEST(ObjWriter, IllumSaysPlainReflectiveOrGlass) {
  Material m;
  EXPECT_EQ(mtlOf(m).illum, 2);
  m.reflectivity = 0.5;
  EXPECT_EQ(mtlOf(m).illum, 3);
  m.transparency = 0.5;
  EXPECT_EQ(mtlOf(m).illum, 6);
  EXPECT_EQ(mtlOf(m).d, 0.5);
  m.shininess = 5000;
  EXPECT_EQ(mtlOf(m).ns, 1000.0) << "MTL's Ns stops at 1000";
}

// A mirroring matrix turns the triangles: each face is written the other
// way round, so that it still turns counter-clockwise seen from outside.
TEST(ObjWriter, AMirroredObjectKeepsItsFacesOutward) {
  Scene scene = readObj(kObjScene);
  Scene mirrored = scene;
  mirrored.objects[0].matrix[0][0] = -1.0;
  DiagnosticList out;
  std::string plain = writeObj(scene, {}, out)->main;
  std::string flipped = writeObj(mirrored, {}, out)->main;
  std::size_t a = plain.find("\nf "), b = flipped.find("\nf ");
  std::string first = plain.substr(a + 3, plain.find('\n', a + 1) - a - 3);
  std::string second = flipped.substr(b + 3, flipped.find('\n', b + 1) - b - 3);
  EXPECT_NE(first, second);
  // The same three corners, in the other order.
  EXPECT_EQ(first.substr(0, first.find(' ')), second.substr(second.rfind(' ') + 1));
}

TEST(ObjWriter, AMeshBeyondTheDoublesIsRefused) {
  Scene scene = readObj(kObjScene);
  scene.objects[0].matrix[0][0] = 1.7e308;
  scene.objects[0].matrix[3][0] = 1.7e308;
  DiagnosticList out;
  EXPECT_FALSE(writeObj(scene, {}, out).has_value());
  EXPECT_EQ(withCode(out, DiagnosticCode::ValueNotFinite).size(), 1u);
}

}  // namespace
}  // namespace scene
