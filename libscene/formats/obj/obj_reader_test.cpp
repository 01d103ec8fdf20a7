// The OBJ reader: other programs' statements and meshes, its diagnostics
// with their places, its limits, the MTL files it reads (beside the file
// alone), and the rule that makes an edited object's comment stale.
#include "libscene/formats/obj/obj_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "libscene/formats/obj/obj_writer.h"
#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

namespace fs = std::filesystem;
using testing::expectOne;
using testing::withCode;

// A box from -1 to 1 as quads, corners by negative and slashed indices.
constexpr std::string_view kBox =
    "o Box\n"
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
    "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "vt 0 0\nvn 0 0 1\ns off\n"
    "f -8 -5 -6 -7\n"              // z = -1, seen from -z
    "f 5/1 6/1 7/1 8/1\n"          // z = 1
    "f 1//1 2//1 6//1 5//1\n"      // y = -1
    "f 4/1/1 8/1/1 7/1/1 3/1/1\n"  // y = 1
    "f 1 5 8 4\n"                  // x = -1
    "f 2 3 7 6\n";                 // x = 1

ReadResult read(std::string_view text, const ReadOptions& options = {}) {
  return parseObj(text, "a.obj", std::nullopt, options);
}

TEST(ObjReader, OtherProgramsStatementsMakeABox) {
  ReadResult r = read(kBox);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.scene.objects.size(), 1u);
  EXPECT_EQ(r.scene.objects[0].kind, ObjectKind::Cube);
  expectOne(r.diagnostics, DiagnosticCode::ObjMeshFit, 1, 1, Severity::Note);
  expectOne(r.diagnostics, DiagnosticCode::ObjNoCamera, 0, 0, Severity::Note);
  EXPECT_TRUE(withCode(r.diagnostics, DiagnosticCode::ObjIgnored).empty())
      << "vt, vn and s are skipped in silence";
}

TEST(ObjReader, EachMistakeIsReportedAtItsLineAndColumn) {
  ReadResult r = read("v 1 2\nv 1 x 3\nv 0 0 0\nf 1 2 9\nf 1 0 2\nf 1 2\n%% 1\n");
  EXPECT_FALSE(r.ok());
  std::vector<Diagnostic> syntax = withCode(r.diagnostics, DiagnosticCode::ObjSyntax);
  ASSERT_EQ(syntax.size(), 5u);
  EXPECT_EQ(syntax[0].span.line, 1u);
  EXPECT_EQ(syntax[1].span.line, 4u);
  EXPECT_EQ(syntax[1].span.column, 7u);
  EXPECT_NE(syntax[1].message.find("vertex 9 does not exist"), std::string::npos);
  EXPECT_EQ(syntax[2].span.column, 5u);
  EXPECT_EQ(syntax[3].span.line, 6u);
  EXPECT_EQ(syntax[4].span.line, 7u);
  expectOne(r.diagnostics, DiagnosticCode::InvalidNumber, 2, 5);
}

TEST(ObjReader, NonFiniteNumbersAreRefused) {
  for (std::string_view v : {"v 1e999 0 0\n", "v nan 0 0\n", "v 0 inf 0\n", "v 0 0 1e-400\n"}) {
    EXPECT_FALSE(read(v).ok()) << v;
  }
}

TEST(ObjReader, LimitsStopTheReading) {
  ReadOptions few;
  few.obj.maxVertices = 7;
  expectOne(read(kBox, few).diagnostics, DiagnosticCode::ObjTooLarge, 9, 1);
  ReadOptions oneObject;
  oneObject.maxObjects = 1;
  std::string two = std::string(kBox) + "o Again\nf 1 2 3\n";
  expectOne(read(two, oneObject).diagnostics, DiagnosticCode::TooManyObjects, 20, 1);
}

TEST(ObjReader, WhatIsNoPrimitiveIsSkippedOrRefusedUnderNoLoss) {
  std::string_view tetrahedron =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  ReadResult r = read(tetrahedron);
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.scene.objects.empty());
  EXPECT_EQ(withCode(r.diagnostics, DiagnosticCode::ObjMeshNotPrimitive)[0].severity,
            Severity::Warning);
  ReadOptions strict;
  strict.noLoss = true;
  EXPECT_FALSE(read(tetrahedron, strict).ok());
}

TEST(ObjReader, IsRecognisedByItsStatementsAndByItsExtension) {
  EXPECT_EQ(detectFormat("# made by hand\nv 0 0 0\n", "x"), Format::Obj);
  EXPECT_EQ(detectFormat("mtllib a.mtl\n", "x"), Format::Obj);
  EXPECT_EQ(detectFormat("# only a comment\n", "a.obj"), Format::Obj);
  EXPECT_EQ(detectFormat("# only a comment\n", "a.sf"), Format::SceneFile);
  EXPECT_EQ(detectFormat("# a scene file\nCAMERA\n", "a.obj"), Format::SceneFile);
}

class ObjFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("obj-reader-" + std::to_string(::getpid()));
    fs::create_directories(folder_ / "inner");
  }
  void TearDown() override { fs::remove_all(folder_); }
  void write(const std::string& name, std::string_view text) {
    std::ofstream(folder_ / name, std::ios::binary) << text;
  }
  fs::path folder_;
};

TEST_F(ObjFolder, TheMtlIsReadFromBesideTheFileAlone) {
  write("box.mtl", "newmtl red\nKd 1 0 0\nKs 0.25 0.25 0.25\nNs 50\nd 0.75\nNi 1.5\n");
  write("inner/box.mtl", "newmtl red\nKd 0 1 0\n");
  std::string text = "mtllib box.mtl\nusemtl red\n" + std::string(kBox);
  ReadResult r = parseObj(text, (folder_ / "a.obj").string(), folder_);
  ASSERT_TRUE(r.ok());
  const Material& m = r.scene.objects[0].material;
  EXPECT_EQ(m.colour, glm::dvec3(1, 0, 0));
  EXPECT_EQ(m.diffuse, 1.0);
  EXPECT_EQ(m.specular, 0.25);
  EXPECT_EQ(m.shininess, 50.0);
  EXPECT_EQ(m.transparency, 0.25);
  EXPECT_EQ(m.ri, 1.5);
  for (std::string_view name : {"inner/box.mtl", "../box.mtl", "/etc/passwd", "missing.mtl"}) {
    ReadResult away = parseObj("mtllib " + std::string(name) + "\nusemtl red\n" + std::string(kBox),
                               "a.obj", folder_);
    EXPECT_TRUE(away.ok()) << name;
    EXPECT_EQ(away.scene.objects[0].material, Material{}) << name;
    EXPECT_EQ(withCode(away.diagnostics, DiagnosticCode::ObjMaterial).size(), 1u) << name;
  }
}

// The writer's file edited as another program would: the comment is
// believed only while the group's vertices and its MTL material are still
// what the writer wrote for it.
TEST_F(ObjFolder, AnEditedObjectsCommentIsStale) {
  ReadResult original = parseScene(
      "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 1\n0 0 1 8\n0 0 0 1\n\n"
      "SPHERE\n1 0 0\n2 0 0 0\n0 2 0 0\n0 0 2 0\n0 0 0 1\n",
      "a.sf");
  ASSERT_TRUE(original.ok());
  DiagnosticList out;
  ConversionOptions options;
  options.obj.materialLibrary = "a.mtl";
  std::optional<ConvertedFiles> files = writeObj(original.scene, options, out);
  ASSERT_TRUE(files.has_value());
  write("a.mtl", files->sidecar);
  ReadResult same = parseObj(files->main, "a.obj", folder_);
  ASSERT_TRUE(same.ok());
  EXPECT_EQ(same.scene, original.scene);
  EXPECT_TRUE(withCode(same.diagnostics, DiagnosticCode::ObjCommentStale).empty());

  // Every vertex moved by 1%: the sphere is larger, and is read as it is.
  std::string moved;
  std::istringstream lines(files->main);
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("v ")) {
      std::istringstream v(line.substr(2));
      double x, y, z;
      v >> x >> y >> z;
      line = "v " + std::to_string(x * 1.01) + " " + std::to_string(y * 1.01) + " " +
             std::to_string(z * 1.01);
    }
    moved += line + "\n";
  }
  ReadResult edited = parseObj(moved, "a.obj", folder_);
  ASSERT_TRUE(edited.ok());
  std::uint32_t groupLine =
      1 + static_cast<std::uint32_t>(
              std::count(moved.begin(), moved.begin() + moved.find("\no SPHERE_1"), '\n'));
  expectOne(edited.diagnostics, DiagnosticCode::ObjCommentStale, groupLine + 1, 1, Severity::Note);
  EXPECT_NEAR(edited.scene.objects[0].matrix[0][0], 2.02, 1e-4);
  EXPECT_EQ(edited.scene.objects[0].material, original.scene.objects[0].material);

  // The material edited in the MTL: read from the MTL.
  std::string mtl = files->sidecar;
  mtl.replace(mtl.find("Kd 0.9 0 0"), 10, "Kd 0 0 0.5");
  write("a.mtl", mtl);
  ReadResult recoloured = parseObj(files->main, "a.obj", folder_);
  ASSERT_TRUE(recoloured.ok());
  EXPECT_EQ(withCode(recoloured.diagnostics, DiagnosticCode::ObjCommentStale).size(), 1u);
  EXPECT_EQ(recoloured.scene.objects[0].material.colour, glm::dvec3(0, 0, 0.5));
  EXPECT_EQ(recoloured.scene.objects[0].matrix, original.scene.objects[0].matrix);
}

}  // namespace
}  // namespace scene
