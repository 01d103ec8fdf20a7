// The POV-Ray reader: the language as POV-Ray users write it, POV-Ray's
// geometry conventions, what it refuses, and where it says so.
#include "libscene/formats/pov/pov_reader.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

#include "libscene/testing/test_support.h"
#include "libscene/text/number.h"
#include "scenefile/read.h"
#include "scenefile/transform.h"

namespace scene {
namespace {

using testing::expectOne;
using testing::withCode;

constexpr double kPi = std::numbers::pi;

// A right-handed camera (right = direction x up in a right-handed world)
// that sees the scene unmirrored, as most tests want.
const std::string kCamera =
    "camera { location <0, 0, 10> direction -z up y right x*4/3 }\n"
    "light_source { <0, 10, 10> color rgb 1 }\n";

PovImport read(const std::string& text, ReadOptions options = {}) {
  return importPov(text, "t.pov", options);
}

std::string all(const DiagnosticList& list) {
  std::string s;
  for (const Diagnostic& d : list.items()) {
    s += std::to_string(d.span.line) + ":" + std::to_string(d.span.column) + " " +
         std::string(severityName(d.severity)) + " [" + std::string(codeName(d.code)) + "] " +
         d.message + "\n";
  }
  return s;
}

// The first object of a scene that must read cleanly.
Object onlyObject(const std::string& text) {
  PovImport r = read(kCamera + text);
  EXPECT_TRUE(r.read.ok()) << all(r.read.diagnostics);
  EXPECT_EQ(r.read.scene.objects.size(), 1u) << all(r.read.diagnostics);
  return r.read.scene.objects.empty() ? Object{} : r.read.scene.objects[0];
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) {
  return glm::dvec3(m * glm::dvec4(p, 1.0));
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(PovReader, ReadsCommentsOfBothKindsAndNestedBlockComments) {
  Object o = onlyObject(
      "// a line comment\n"
      "/* a block /* nested */ still a comment sphere { 0, 5 } */\n"
      "sphere { <1, 2, 3>, 0.5 } // after\n");
  expectNear(apply(o.matrix, {0, 0, 0}), {1, 2, 3});
  expectNear(apply(o.matrix, {1, 0, 0}), {1.5, 2, 3});
}

TEST(PovReader, AnUnclosedCommentIsReportedWhereItOpens) {
  PovImport r = read(kCamera + "sphere { 0, 1 }\n  /* open /* */\n");
  expectOne(r.read.diagnostics, DiagnosticCode::PovSyntax, 4, 3);
}

TEST(PovReader, DeclaresNumbersVectorsAndColoursWithExpressions) {
  Object o = onlyObject(
      "#version 3.7;\n"
      "#declare R = 2 * (1 + 0.5);\n"
      "#local P = <1, 2, 3> + x * R;\n"
      "#declare C = rgb <0.25, 0.5, 1> * 0.5;\n"
      "#declare S = sqrt(16) + vlength(<3, 4, 0>) - P.y;\n"
      "sphere { P, R pigment { color C } translate S * y }\n");
  expectNear(apply(o.matrix, {0, 0, 0}), {4, 2 + 7, 3});
  EXPECT_EQ(o.matrix[0][0], 3.0);
  EXPECT_EQ(o.material.colour, glm::dvec3(0.125, 0.25, 0.5));
}

TEST(PovReader, KnowsTheColoursOfColorsIncOnlyWhenIncluded) {
  Object o = onlyObject("#include \"colors.inc\"\nsphere { 0, 1 pigment { Orange } }\n");
  EXPECT_EQ(o.material.colour, glm::dvec3(1, 0.5, 0));
  Object named = onlyObject("#include \"colors.inc\"\nsphere { 0, 1 pigment { color DimGray } }\n");
  EXPECT_EQ(named.material.colour, glm::dvec3(0.329412));

  PovImport r = read(kCamera + "sphere { 0, 1 pigment { Red } }\n");
  Diagnostic d = expectOne(r.read.diagnostics, DiagnosticCode::PovUnknownIdentifier, 3, 25);
  EXPECT_EQ(d.hint, "add #include \"colors.inc\" before it");
}

TEST(PovReader, ReadsEveryColourForm) {
  auto colourOf = [](const std::string& pigment) {
    return onlyObject("#include \"colors.inc\"\nsphere { 0, 1 pigment { " + pigment + " } }\n")
        .material;
  };
  EXPECT_EQ(colourOf("rgb 0.5").colour, glm::dvec3(0.5));
  EXPECT_EQ(colourOf("color rgb <1, 0, 0>").colour, glm::dvec3(1, 0, 0));
  EXPECT_EQ(colourOf("colour red 1 green 0.5").colour, glm::dvec3(1, 0.5, 0));
  EXPECT_EQ(colourOf("color <0, 1, 0>").colour, glm::dvec3(0, 1, 0));
  EXPECT_EQ(colourOf("White * 0.5").colour, glm::dvec3(0.5));
  EXPECT_EQ(colourOf("rgbt <1, 1, 1, 0.25>").transparency, 0.25);
  EXPECT_EQ(colourOf("Red transmit 0.5").transparency, 0.5);
}

TEST(PovReader, FilterBecomesTransparencyWithALoss) {
  PovImport r = read(kCamera + "sphere { 0, 1 pigment { rgbf <1, 0, 0, 0.5> } }\n");
  ASSERT_EQ(r.read.scene.objects.size(), 1u);
  EXPECT_EQ(r.read.scene.objects[0].material.transparency, 0.5);
  expectOne(r.read.diagnostics, DiagnosticCode::PovLoss, 3, 1, Severity::Warning);
}

TEST(PovReader, MapsFinishAndInteriorWithPovRaysDefaults) {
  Object plain = onlyObject("sphere { 0, 1 }\n");
  EXPECT_EQ(plain.material.colour, glm::dvec3(0.0)) << "POV-Ray's default pigment is black";
  EXPECT_EQ(plain.material.ambient, 0.1);
  EXPECT_EQ(plain.material.diffuse, 0.6);
  EXPECT_EQ(plain.material.specular, 0.0);
  EXPECT_EQ(plain.material.shininess, 40.0);

  Object o = onlyObject(
      "#default { finish { ambient 0.2 } }\n"
      "sphere { 0, 1 texture { pigment { rgbt <1, 1, 1, 0.9> } finish { diffuse 0.7 "
      "phong 0.8 phong_size 100 reflection { 0.3 } } } interior { ior 1.33 } }\n");
  EXPECT_EQ(o.material.ambient, 0.2);
  EXPECT_EQ(o.material.diffuse, 0.7);
  EXPECT_EQ(o.material.specular, 0.8);
  EXPECT_EQ(o.material.shininess, 100.0);
  EXPECT_EQ(o.material.reflectivity, 0.3);
  EXPECT_EQ(o.material.transparency, 0.9);
  EXPECT_EQ(o.material.ri, 1.33);
}

TEST(PovReader, DeclaredMaterialsAndObjectsAreReused) {
  PovImport r = read(kCamera +
                     "#declare Shiny = finish { phong 1 phong_size 80 }\n"
                     "#declare Tex = texture { pigment { rgb <0, 0, 1> } finish { Shiny } }\n"
                     "#declare Ball = sphere { 0, 1 texture { Tex } }\n"
                     "object { Ball translate x * 2 }\n"
                     "object { Ball pigment { rgb 1 } }\n");
  ASSERT_TRUE(r.read.ok()) << all(r.read.diagnostics);
  ASSERT_EQ(r.read.scene.objects.size(), 2u);
  expectNear(apply(r.read.scene.objects[0].matrix, {0, 0, 0}), {2, 0, 0});
  EXPECT_EQ(r.read.scene.objects[0].material.colour, glm::dvec3(0, 0, 1));
  EXPECT_EQ(r.read.scene.objects[0].material.shininess, 80.0);
  EXPECT_EQ(r.read.scene.objects[1].material.colour, glm::dvec3(1));
  EXPECT_EQ(r.read.scene.objects[1].material.specular, 1.0);
}

// POV-Ray's rotate <a, b, c> turns about x, then y, then z, in degrees, with
// the same matrices as FORMATS.md's ROTATE_X/Y/Z.
TEST(PovReader, RotatesInDegreesXThenYThenZ) {
  Object o = onlyObject("box { -1, 1 rotate <30, 45, 60> }\n");
  std::vector<TransformOp> ops = {{TransformKind::RotateX, {30 * kPi / 180, 0, 0}, {}},
                                  {TransformKind::RotateY, {45 * kPi / 180, 0, 0}, {}},
                                  {TransformKind::RotateZ, {60 * kPi / 180, 0, 0}, {}}};
  glm::dmat4 expected = composeTransform(ops);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(o.matrix[c][r], expected[c][r], 1e-15);
  }
  // The sense, in numbers: a quarter turn about z takes x to y.
  Object z = onlyObject("box { -1, 1 rotate 90 * z }\n");
  expectNear(apply(z.matrix, {1, 0, 0}), {0, 1, 0}, 1e-15);
}

TEST(PovReader, ComposesTransformsInOrderAndReadsTheMatrixAsRowVectors) {
  Object o = onlyObject("box { -1, 1 scale <2, 1, 1> translate <0, 0, 5> }\n");
  expectNear(apply(o.matrix, {1, 1, 1}), {2, 1, 6});
  // x' = x + 0.5 y: POV-Ray's matrix rows are our columns.
  Object shear = onlyObject("box { -1, 1 matrix <1, 0, 0,  0.5, 1, 0,  0, 0, 1,  1, 2, 3> }\n");
  expectNear(apply(shear.matrix, {0, 1, 0}), {1.5, 3, 3});
  Object t = onlyObject(
      "#declare T = transform { rotate 90 * y translate x }\n"
      "box { -1, 1 transform { T inverse } }\n");
  expectNear(apply(t.matrix, {1, 0, 0}), {0, 0, 0}, 1e-15);
}

TEST(PovReader, BuildsEachPrimitiveOnItsUnitShape) {
  Object sphere = onlyObject("sphere { <1, 2, 3>, 2 }\n");
  EXPECT_EQ(sphere.kind, ObjectKind::Sphere);
  expectNear(apply(sphere.matrix, {0, 1, 0}), {1, 4, 3});

  Object box = onlyObject("box { <2, 3, 4>, <0, -1, 0> }\n");
  EXPECT_EQ(box.kind, ObjectKind::Cube);
  expectNear(apply(box.matrix, {-1, -1, -1}), {0, -1, 0});
  expectNear(apply(box.matrix, {1, 1, 1}), {2, 3, 4});

  // Both ends anywhere: the unit cylinder's ends land on them.
  struct Ends {
    glm::dvec3 base, cap;
  };
  for (Ends e : {Ends{{1, 2, 3}, {4, -2, 8}}, Ends{{0, 1, 0}, {0, -3, 0}},
                 Ends{{0, 0, 0}, {0, 0, 1}}, Ends{{0, 0, 0}, {0, 1e-3, 0}}}) {
    auto v = [](const glm::dvec3& p) {
      return "<" + formatNumber(p.x) + ", " + formatNumber(p.y) + ", " + formatNumber(p.z) + ">";
    };
    Object c = onlyObject("cylinder { " + v(e.base) + ", " + v(e.cap) + ", 0.5 }\n");
    EXPECT_EQ(c.kind, ObjectKind::Cylinder);
    expectNear(apply(c.matrix, {0, -1, 0}), e.base);
    expectNear(apply(c.matrix, {0, 1, 0}), e.cap);
    // The radius: a unit step across the axis is 0.5 long.
    EXPECT_NEAR(glm::length(glm::dvec3(c.matrix[0])), 0.5, 1e-15);
    EXPECT_NEAR(glm::length(glm::dvec3(c.matrix[2])), 0.5, 1e-15);
    EXPECT_GT(glm::determinant(glm::dmat3(c.matrix)), 0.0);
  }

  // POV-Ray's plane is n . p = d for the unit normal, whatever n's length.
  Object plane = onlyObject("plane { <0, 0, 2>, 3 }\n");
  EXPECT_EQ(plane.kind, ObjectKind::Plane);
  for (glm::dvec3 local : {glm::dvec3(0, 0, 0), glm::dvec3(5, 0, -2)}) {
    EXPECT_NEAR(apply(plane.matrix, local).z, 3.0, 1e-15);
  }
  EXPECT_EQ(onlyObject("plane { -y, 0 }\n").matrix, glm::dmat4(1.0));
}

TEST(PovReader, ReportsDegenerateShapes) {
  PovImport r = read(kCamera +
                     "sphere { 0, 0 }\nbox { 0, <1, 0, 1> }\n"
                     "cylinder { x, x, 1 }\nplane { 0, 1 }\n");
  EXPECT_EQ(withCode(r.read.diagnostics, DiagnosticCode::PovDegenerate).size(), 4u)
      << all(r.read.diagnostics);
  EXPECT_TRUE(r.read.scene.objects.empty());
}

TEST(PovReader, AnOpenCylinderIsReadClosedWithALoss) {
  PovImport r = read(kCamera + "cylinder { 0, y, 1 open }\n");
  EXPECT_EQ(r.read.scene.objects.size(), 1u);
  expectOne(r.read.diagnostics, DiagnosticCode::PovLoss, 3, 20, Severity::Warning);
}

// POV-Ray's default camera: at the origin looking along +z, up +y, right
// 1.33 x: a left-handed view, which the reader mirrors (z -> -z) so that a
// right-handed camera sees the same picture.
TEST(PovReader, TheDefaultCameraIsLeftHandedAndMirrorsTheScene) {
  PovImport r = read("light_source { <0, 0, 0> rgb 1 }\nsphere { <1, 2, 5>, 1 }\n");
  ASSERT_TRUE(r.read.ok()) << all(r.read.diagnostics);
  EXPECT_TRUE(r.view.mirrored);
  EXPECT_NEAR(r.view.verticalFovDegrees, 2 * std::atan(0.5) * 180 / kPi, 1e-12);
  EXPECT_NEAR(r.view.aspectRatio, 1.33, 1e-15);
  const glm::dmat4& camera = r.read.scene.camera.matrix;
  expectNear(glm::dvec3(-camera[2]), {0, 0, -1});  // forward
  expectNear(glm::dvec3(camera[1]), {0, 1, 0});
  expectNear(glm::dvec3(camera[0]), {1, 0, 0});  // right stays +x: the picture is POV-Ray's
  expectNear(apply(r.read.scene.objects[0].matrix, {0, 0, 0}), {1, 2, -5});
  Diagnostic fov = expectOne(r.read.diagnostics, DiagnosticCode::CameraFov, 1, 1, Severity::Note);
  EXPECT_EQ(fov.hint, "render with {0} {1} {2}");
  EXPECT_EQ(fov.remedies, (std::vector<Remedy>{{Setting::FieldOfView, "53.13010235415598"},
                                               {Setting::Width, "640"},
                                               {Setting::Height, "481"}}));
}

TEST(PovReader, ALookAtCameraKeepsPovRaysHandedness) {
  PovImport left = read("camera { location <0, 2, -5> look_at <0, 1, 0> }\n");
  EXPECT_TRUE(left.view.mirrored);
  // Mirrored, the eye is at z = +5 looking toward -z.
  expectNear(glm::dvec3(left.read.scene.camera.matrix[3]), {0, 2, 5});
  EXPECT_LT(-left.read.scene.camera.matrix[2][2], 0.0);

  PovImport right =
      read("camera { location <0, 2, -5> look_at <0, 1, 0> right -x*image_width/image_height }\n");
  EXPECT_FALSE(right.view.mirrored);
  expectNear(glm::dvec3(right.read.scene.camera.matrix[3]), {0, 2, -5});
  EXPECT_NEAR(right.view.aspectRatio, 4.0 / 3.0, 1e-15);
  // Right-handed: right = forward x up, which here is -x.
  expectNear(glm::dvec3(right.read.scene.camera.matrix[0]), {-1, 0, 0});
}

TEST(PovReader, AngleIsHorizontalAndAppliedBeforeLookAt) {
  // look_at written first still comes after angle, as in POV-Ray 3.5+.
  PovImport r = read("camera { look_at <0, 0, 1> angle 90 right x up y location 0 }\n");
  // |direction| = |right| / (2 tan 45) = 0.5, so tan(vfov / 2) = 0.5 / 0.5.
  EXPECT_NEAR(r.view.verticalFovDegrees, 90.0, 1e-12);
  EXPECT_NEAR(r.view.aspectRatio, 1.0, 1e-15);
  PovImport sky = read("camera { location 0 look_at <1, 0, 0> sky z right -x up y }\n");
  // With sky +z the picture's up is +z.
  expectNear(glm::dvec3(sky.read.scene.camera.matrix[1]), {0, 0, 1});
}

TEST(PovReader, CameraTransformsApplyLast) {
  PovImport r =
      read("camera { location <0, 0, -5> look_at 0 right -x*4/3 rotate <0, 90, 0> translate y }\n");
  expectNear(glm::dvec3(r.read.scene.camera.matrix[3]), {-5, 1, 0});
  expectNear(glm::dvec3(-r.read.scene.camera.matrix[2]), {1, 0, 0});
}

TEST(PovReader, NamesUnsupportedConstructsWithTheirLines) {
  std::string text = kCamera +
                     "union { sphere { 0, 1 } box { 0, 1 } }\n"
                     "#while (1) sphere { 0, 1 } #end\n"
                     "MyMacro(1, 2)\n"
                     "sphere { 0, 1 normal { bumps 0.5 } }\n"
                     "box { -1, 1 }\n";
  PovImport strict = read(text);
  EXPECT_FALSE(strict.read.ok());
  std::vector<Diagnostic> found = withCode(strict.read.diagnostics, DiagnosticCode::PovUnsupported);
  ASSERT_EQ(found.size(), 4u) << all(strict.read.diagnostics);
  EXPECT_EQ(found[0].message, "'union' is not supported (line 3)");
  EXPECT_EQ(found[1].message, "'#while' is not supported (line 4)");
  EXPECT_EQ(found[2].message, "the macro call 'MyMacro(...)' is not supported (line 5)");
  EXPECT_EQ(found[3].message, "a normal pattern is not supported (line 6)");
  EXPECT_EQ(found[0].severity, Severity::Error);

  ReadOptions skip;
  skip.pov.skipUnsupported = true;
  PovImport skipped = read(text, skip);
  EXPECT_TRUE(skipped.read.ok()) << all(skipped.read.diagnostics);
  EXPECT_EQ(skipped.read.scene.objects.size(), 2u) << "the sphere and the box after it";
  EXPECT_EQ(withCode(skipped.read.diagnostics, DiagnosticCode::PovUnsupported)[0].severity,
            Severity::Warning);
}

TEST(PovReader, NamesFromIncludeFilesItDoesNotReadAreUnsupported) {
  std::string text = kCamera +
                     "#include \"colors.inc\"\n#include \"stones.inc\"\n"
                     "sphere { 0, 1 texture { T_Stone1 } pigment { Red } }\n";
  PovImport strict = read(text);
  Diagnostic d = expectOne(strict.read.diagnostics, DiagnosticCode::PovUnsupported, 5, 25);
  EXPECT_EQ(d.message,
            "the texture 'T_Stone1' (declared in no file this reader reads) is not supported "
            "(line 5)");
  ReadOptions skip;
  skip.pov.skipUnsupported = true;
  PovImport skipped = read(text, skip);
  ASSERT_TRUE(skipped.read.ok()) << all(skipped.read.diagnostics);
  EXPECT_EQ(skipped.read.scene.objects[0].material.colour, glm::dvec3(1, 0, 0));
}

TEST(PovReader, RefusesWhatWouldReadOtherFiles) {
  ReadOptions skip;
  skip.pov.skipUnsupported = true;
  for (const char* text :
       {"#include \"my_scene.inc\"\n", "#include \"/etc/passwd\"\n", "#fopen F \"data.txt\" read\n",
        "sphere { 0, 1 pigment { image_map { png \"a.png\" } } }\n",
        "height_field { png \"hf.png\" }\n", "#if (0) #include \"other.inc\" #end\n"}) {
    PovImport r = read(kCamera + text, skip);
    EXPECT_FALSE(r.read.ok()) << text;
    EXPECT_EQ(withCode(r.read.diagnostics, DiagnosticCode::PovRefused).size(), 1u)
        << text << all(r.read.diagnostics);
  }
  EXPECT_TRUE(read(kCamera + "#include \"textures.inc\"\n#include \"colors.inc\"\n").read.ok());
}

TEST(PovReader, RefusesFilesBeyondItsLimits) {
  std::string deep =
      kCamera + "#declare X = " + std::string(200, '(') + "1" + std::string(200, ')') + ";\n";
  expectOne(read(deep).read.diagnostics, DiagnosticCode::PovLimit, 3, 14 + kMaxPovNesting);

  std::string nested;
  for (int i = 0; i < 300; ++i) nested += "union {\n";
  ReadOptions skip;
  skip.pov.skipUnsupported = true;
  PovImport r = read(kCamera + nested, skip);
  EXPECT_EQ(withCode(r.read.diagnostics, DiagnosticCode::PovLimit).size(), 1u);

  std::string huge(kMaxPovBytes + 1, ' ');
  expectOne(read(huge).read.diagnostics, DiagnosticCode::PovLimit, 1, 1);
}

TEST(PovReader, RecoversAfterAnErrorAtTheNextStatement) {
  PovImport r = read(kCamera +
                     "sphere { 0, 1 pigment { rgb <1, 0> } }\n"
                     "box { -1, 1 transalte x }\n"
                     "sphere { 0, 2 }\n");
  EXPECT_EQ(r.read.scene.objects.size(), 1u);
  std::vector<Diagnostic> errors = withCode(r.read.diagnostics, DiagnosticCode::PovSyntax);
  ASSERT_EQ(errors.size(), 2u) << all(r.read.diagnostics);
  EXPECT_EQ(errors[0].span.line, 3u);
  EXPECT_EQ(errors[1].span.line, 4u);
  EXPECT_EQ(errors[1].message, "'transalte' is no modifier of box");
  EXPECT_EQ(errors[1].hint, "did you mean 'translate'?");
}

TEST(PovReader, ReportsWhatTheSceneModelCannotHold) {
  PovImport r = read(kCamera +
                     "global_settings { ambient_light 2 }\n"
                     "background { color rgb <0, 0, 1> }\n"
                     "light_source { <0, 5, 0> rgb 1 spotlight point_at 0 radius 10 }\n"
                     "sphere { 0, 1 no_shadow finish { ambient 1.5 } }\n");
  EXPECT_TRUE(r.read.ok()) << all(r.read.diagnostics);
  expectOne(r.read.diagnostics, DiagnosticCode::PovIgnored, 3, 1, Severity::Note);
  EXPECT_EQ(withCode(r.read.diagnostics, DiagnosticCode::PovLoss).size(), 4u)
      << all(r.read.diagnostics);
  EXPECT_EQ(r.read.scene.objects[0].material.ambient, 1.0);
  ReadOptions strict;
  strict.noLoss = true;
  EXPECT_FALSE(read(kCamera + "background { rgb 1 }\n", strict).read.ok());
  EXPECT_TRUE(read(kCamera + "background { rgb 0 }\n", strict).read.ok());
}

// The mean colour a pattern is read as, and the loss naming the object.
glm::dvec3 patternMean(const std::string& pigment, std::string* loss = nullptr) {
  PovImport r = read(kCamera + "box { -1, 1 }\nsphere { 0, 1 pigment { " + pigment + " } }\n");
  EXPECT_TRUE(r.read.ok()) << pigment << "\n" << all(r.read.diagnostics);
  std::vector<Diagnostic> losses = withCode(r.read.diagnostics, DiagnosticCode::PovLoss);
  EXPECT_EQ(losses.size(), 1u) << pigment << "\n" << all(r.read.diagnostics);
  if (loss && !losses.empty()) *loss = losses[0].message;
  return r.read.scene.objects.size() == 2 ? r.read.scene.objects[1].material.colour
                                          : glm::dvec3(-1.0);
}

TEST(PovReader, PatternsBecomeTheirMeanColourWithALossNamingTheObject) {
  std::string loss;
  expectNear(patternMean("checker rgb <1, 0, 0>, rgb 1", &loss), {1, 0.5, 0.5});
  EXPECT_EQ(loss,
            "the checker pigment of SPHERE object 2 is approximated by its mean colour 1 0.5 0.5");
  // POV-Ray's own colours: checker blue and green, hexagon blue, green and
  // red, brick grey mortar (0.5) and red brick (0.6, 0.15, 0.15).
  expectNear(patternMean("checker scale 0.5"), {0, 0.5, 0.5});
  expectNear(patternMean("hexagon"), glm::dvec3(1.0 / 3.0));
  // Brick on a wall facing z: 7.5 / 8 by 2.5 / 3 of each cell is brick.
  expectNear(patternMean("brick"),
             glm::dvec3(0.5) * 0.21875 + glm::dvec3(0.6, 0.15, 0.15) * 0.78125);
  expectNear(patternMean("brick rgb 0, rgb 1 brick_size <2, 2, 2> mortar 1"), glm::dvec3(0.25));
  // colour_map patterns: the map over [0, 1], linear between entries, the
  // end colours held beyond them, in any order of entries.
  expectNear(patternMean("gradient y colour_map { [0 rgb 0] [1 rgb 1] } turbulence 0.5"),
             glm::dvec3(0.5));
  expectNear(patternMean("marble color_map { [0.5 rgb 1] [0 rgb 0] [1 rgb 1] }"), glm::dvec3(0.75));
  expectNear(patternMean("bozo colour_map { [0.25, 0.75 rgb 0 rgb 1] }"), glm::dvec3(0.5));
  expectNear(patternMean("wood colour_map { [0.3 rgb <0.2, 0.4, 0.6>] }"), {0.2, 0.4, 0.6});
  std::string entries;
  for (int i = 0; i < 256; ++i) entries += "[" + std::to_string(i / 255.0) + " rgb 1]";
  expectNear(patternMean("spotted colour_map { " + entries + " }"), glm::dvec3(1.0));
  // A later plain colour replaces the pattern, and the loss with it.
  PovImport plain = read(kCamera + "sphere { 0, 1 pigment { checker } pigment { rgb 1 } }\n");
  EXPECT_TRUE(withCode(plain.read.diagnostics, DiagnosticCode::PovLoss).empty())
      << all(plain.read.diagnostics);
}

TEST(PovReader, PatternsWithoutAMeanColourStayUnsupported) {
  std::string text = kCamera +
                     "sphere { 0, 1 pigment { bozo } }\n"
                     "sphere { 0, 1 pigment { checker pigment { rgb 1 } pigment { rgb 0 } } }\n"
                     "sphere { 0, 1 pigment { gradient x pigment_map { [0 rgb 1] } } }\n";
  std::string tooMany = kCamera + "sphere { 0, 1 pigment { gradient x colour_map {";
  for (int i = 0; i < 257; ++i) tooMany += " [0 rgb 1]";
  tooMany += " } } }\n";
  PovImport r = read(text);
  std::vector<Diagnostic> found = withCode(r.read.diagnostics, DiagnosticCode::PovUnsupported);
  ASSERT_EQ(found.size(), 3u) << all(r.read.diagnostics);
  EXPECT_EQ(found[0].message,
            "the pigment pattern 'bozo' without a colour_map is not supported (line 3)");
  EXPECT_EQ(found[1].message,
            "the pigment pattern 'checker' of pigments is not supported (line 4)");
  EXPECT_EQ(found[2].message, "the pigment pattern 'pigment_map' is not supported (line 5)");
  PovImport limit = read(tooMany);
  EXPECT_FALSE(limit.read.ok());
  EXPECT_EQ(withCode(limit.read.diagnostics, DiagnosticCode::PovSyntax).at(0).message,
            "a colour_map holds at most 256 entries, as in POV-Ray");
}

TEST(PovReader, APatternsMeanIsALossUnderEitherOptionAndAnErrorUnderNoLoss) {
  std::string text = kCamera +
                     "#declare P = pigment { checker rgb 0, rgb 1 }\n"
                     "sphere { 0, 1 pigment { P } }\nbox { -1, 1 pigment { P } }\n";
  ReadOptions skip;
  skip.pov.skipUnsupported = true;
  for (const ReadOptions& options : {ReadOptions{}, skip}) {
    PovImport r = read(text, options);
    EXPECT_TRUE(r.read.ok()) << all(r.read.diagnostics);
    std::vector<Diagnostic> losses = withCode(r.read.diagnostics, DiagnosticCode::PovLoss);
    ASSERT_EQ(losses.size(), 2u) << all(r.read.diagnostics);
    EXPECT_EQ(losses[0].severity, Severity::Warning);
    EXPECT_NE(losses[0].message.find("of SPHERE object 1 "), std::string::npos);
    EXPECT_NE(losses[1].message.find("of CUBE object 2 "), std::string::npos);
    EXPECT_EQ(losses[0].span.line, 3) << "at the pattern";
  }
  ReadOptions strict;
  strict.noLoss = true;
  PovImport r = read(text, strict);
  EXPECT_FALSE(r.read.ok());
  EXPECT_EQ(withCode(r.read.diagnostics, DiagnosticCode::PovLoss).at(0).severity, Severity::Error);
}

TEST(PovReader, LightsTakeTheirTransforms) {
  PovImport r = read(
      "camera { right -x*4/3 }\n"
      "light_source { 0 color rgb <2, 1, 0.5> translate <1, 2, 3> }\n");
  ASSERT_EQ(r.read.scene.lights.size(), 1u);
  EXPECT_EQ(r.read.scene.lights[0].position(), glm::dvec3(1, 2, 3));
  EXPECT_EQ(r.read.scene.lights[0].colour, glm::dvec3(2, 1, 0.5));
}

TEST(PovReader, AStaleExactCommentIsIgnored) {
  std::string text =
      "// sfconvert: camera matrix 1 0 0 0 0 1 0 0 0 0 1 9 0 0 0 1 colour 0 0 0\n"
      "camera { location <0, 0, 5> direction -z up y right x }\n";
  PovImport r = read(text);
  EXPECT_EQ(r.read.scene.camera.matrix[3][2], 5.0) << "the statement wins";
  expectOne(r.read.diagnostics, DiagnosticCode::PovIgnored, 2, 1, Severity::Note);
}

// Hostile input costs bounded time and memory, and is answered with
// diagnostics like any other.
TEST(PovHostileInput, GarbageBinaryAndTokens) {
  std::mt19937_64 rng(7);
  static constexpr std::string_view kTokens[] = {
      "sphere", "{",     "}",        "<",  ">",      "(",   ")",    ",",       "1.5",
      "-",      "*",     "#declare", "X",  "=",      "box", "rgb",  "pigment", "#while",
      "#end",   "\"s\"", "/*",       "*/", "camera", ";",   "union"};
  for (int round = 0; round < 6; ++round) {
    std::string text = "#version 3.7;\n";
    if (round % 2 == 0) {
      for (int i = 0; i < (1 << 20); ++i) text += static_cast<char>(rng());
    } else {
      while (text.size() < (1u << 20)) {
        text += kTokens[rng() % std::size(kTokens)];
        text += rng() % 8 ? ' ' : '\n';
      }
    }
    auto start = std::chrono::steady_clock::now();
    PovImport r = read(text);
    EXPECT_LT(testing::secondsSince(start), 5.0);
    EXPECT_TRUE(r.read.diagnostics.hasErrors());
    EXPECT_LE(r.read.diagnostics.items().size(), 2 * DiagnosticList::kDefaultErrorLimit + 2);
  }
}

TEST(PovHostileInput, EveryLimitRefusesQuickly) {
  auto start = std::chrono::steady_clock::now();
  std::string braces(2'000'000, '{');
  EXPECT_EQ(withCode(read("union " + braces).read.diagnostics, DiagnosticCode::PovLimit).size(),
            1u);

  std::string many;
  for (std::size_t i = 0; i <= 1000; ++i) many += "sphere{0,1}";
  ReadOptions fewObjects;
  fewObjects.maxObjects = 1000;
  EXPECT_EQ(
      withCode(read(many, fewObjects).read.diagnostics, DiagnosticCode::TooManyObjects).size(), 1u);

  std::string names;
  for (std::size_t i = 0; i <= kMaxPovDeclarations; ++i)
    names += "#declare N" + std::to_string(i) + "=1;";
  EXPECT_EQ(withCode(read(names).read.diagnostics, DiagnosticCode::PovLimit).size(), 1u);

  std::string digits = "#declare D = " + std::string(10'000'000, '9') + ";";
  EXPECT_EQ(withCode(read(digits).read.diagnostics, DiagnosticCode::NumberOutOfRange).size(), 1u);
  EXPECT_LT(testing::secondsSince(start), 20.0);
}

TEST(PovReader, StopsAtTheFirstObjectOrLightPastMaxObjects) {
  // kCamera holds one light: with this, two lights and three objects.
  std::string text = kCamera + "light_source { <0, 5, 0> rgb 1 }\nsphere { 0, 1 }\n" +
                     "box { -1, 1 }\nsphere { 0, 2 }\n";
  ReadOptions options;
  options.maxObjects = 3;
  PovImport r = read(text, options);
  Diagnostic d = expectOne(r.read.diagnostics, DiagnosticCode::TooManyObjects, 5, 1);
  EXPECT_EQ(d.message, "the file has more than 3 objects and lights: reading stops here");
  EXPECT_EQ(r.read.diagnostics.errorCount(), 1u);

  options.maxObjects = 5;
  EXPECT_TRUE(read(text, options).read.ok());
}

TEST(PovDetection, RecognisesPovRayBySyntaxAndTheOthersByTheirs) {
  EXPECT_TRUE(looksLikePov("#version 3.7;\n"));
  EXPECT_TRUE(looksLikePov("// a scene\n#include \"colors.inc\"\n"));
  EXPECT_TRUE(looksLikePov("/* header */ camera {}"));
  EXPECT_TRUE(looksLikePov("sphere\n// the ball\n{ 0, 1 }"));
  EXPECT_FALSE(looksLikePov("// leading\nCAMERA\n0 0 0\n"));
  EXPECT_FALSE(looksLikePov("# leading\nOUTPUT_FILE a.ppm\n"));
  EXPECT_FALSE(looksLikePov("camera\n0 0 0\n"));  // a scene file in lower case
  EXPECT_EQ(detectFormat("sphere { 0, 1 }"), Format::Pov);
  EXPECT_EQ(detectFormat("", "empty.pov"), Format::Pov);
  EXPECT_EQ(detectFormat("// only a comment\n", "a.pov"), Format::Pov);
  EXPECT_EQ(detectFormat("// only a comment\n", "a.sf"), Format::SceneFile);
  EXPECT_EQ(detectFormat("CAMERA\n", "a.pov"), Format::SceneFile);
}

}  // namespace
}  // namespace scene
