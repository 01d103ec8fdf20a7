// Every number of an accepted scene is finite: a value that stops being
// finite while it is read, evaluated or composed is an error where it was
// made (value-not-finite), and checkSceneFinite is the last line behind the
// readers. Axes and directions of any finite, non-zero length are valid.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "libscene/core/finite_check.h"
#include "libscene/formats/instruction/instruction_reader.h"
#include "scenefile/matrix.h"
#include "libscene/formats/pov/pov_reader.h"
#include "scenefile/read.h"
#include "libscene/formats/sf/sf_reader.h"
#include "libscene/testing/test_support.h"
#include "scenefile/transform.h"
#include "scenefile/validation.h"

namespace scene {
namespace {

using testing::expectOne;
using testing::withCode;

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::nan("");

const std::string kPovHead =
    "camera { location <0, 1, -5> look_at <0, 0, 0> }\n"
    "light_source { <5, 5, -5> color rgb 1 }\n";

PovImport readPov(const std::string& body) {
  return importPov(kPovHead + body, "t.pov");
}

// Every double the model holds, by a loop independent of checkSceneFinite.
bool everyNumberFinite(const Scene& s) {
  auto finite3 = [](const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  auto finite4 = [&](const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
      if (!finite3(glm::dvec3(m[c])) || !std::isfinite(m[c][3])) return false;
    }
    return true;
  };
  bool ok = finite4(s.camera.matrix) && finite3(s.camera.colour) &&
            (!s.camera.lookAt || finite3(*s.camera.lookAt));
  for (const Light& l : s.lights) ok = ok && finite4(l.matrix) && finite3(l.colour);
  for (const Object& o : s.objects) {
    ok = ok && finite4(o.matrix) && finite3(o.material.colour);
    for (MaterialProperty p : kMaterialProperties) {
      ok = ok && std::isfinite(materialValue(o.material, p));
    }
  }
  return ok;
}

// --- POV-Ray: each operation and function is checked where it stands -------

struct PovCase {
  const char* body;
  std::uint32_t line;
  std::uint32_t column;
  const char* message;
};

TEST(FiniteValues, PovExpressionsThatAreNotFiniteAreErrorsAtTheOperation) {
  const PovCase cases[] = {
      {"light_source { <0/0, 10, -10> color rgb 1 }", 3, 18,
       "0 / 0 gives nan, which is not a finite number"},
      {"sphere { 0, 1 pigment { color rgb <sqrt(-1), 0, 0> } }", 3, 36,
       "sqrt(-1) gives nan, which is not a finite number"},
      {"sphere { 0, 1 finish { reflection acos(2) } }", 3, 35,
       "acos(2) gives nan, which is not a finite number"},
      {"plane { y, 1e308 * 10 }", 3, 18, "1e+308 * 10 gives inf, which is not a finite number"},
      {"sphere { 0, 1 interior { ior exp(1000) } }", 3, 30,
       "exp(1000) gives inf, which is not a finite number"},
      {"sphere { 0, 1 translate <-1e308 - 1e308, 0, 0> }", 3, 33,
       "-1e+308 - 1e+308 gives -inf, which is not a finite number"},
      {"sphere { 0, 1 translate <1e300, 0, 0> * 1e10 }", 3, 39,
       "'*' of a vector and a float gives inf, which is not a finite number"},
      {"sphere { 0, 1 scale 1e200 scale 1e200 }", 3, 27,
       "this scale makes a matrix entry inf, which is not a finite number"},
      {"box { -1, 1 translate 1e308*x translate 1e308*x }", 3, 31,
       "this translate makes a matrix entry inf, which is not a finite number"},
      {"cylinder { <-1e308, 0, 0>, <1e308, 0, 0>, 1 }", 3, 1,
       "the cylinder's cap minus its base gives inf, which is not a finite number"},
  };
  for (const PovCase& c : cases) {
    SCOPED_TRACE(c.body);
    PovImport r = readPov(std::string(c.body) + "\n");
    EXPECT_FALSE(r.read.ok());
    Diagnostic d = expectOne(r.read.diagnostics, DiagnosticCode::ValueNotFinite, c.line, c.column);
    EXPECT_EQ(d.message, c.message);
  }
}

TEST(FiniteValues, ADeclaredNameWhoseValueFailedIsNotReportedAgainWhereItIsUsed) {
  PovImport r = readPov("#declare Bad = 0 / 0;\nsphere { <Bad, 0, 0>, 1 }\n");
  expectOne(r.read.diagnostics, DiagnosticCode::ValueNotFinite, 3, 18);
  EXPECT_TRUE(withCode(r.read.diagnostics, DiagnosticCode::PovUnknownIdentifier).empty());
  EXPECT_TRUE(r.read.scene.objects.empty());
}

TEST(FiniteValues, LargeButFinitePovValuesStayValid) {
  // 1e308 / 10 * 10 overflows at no step.
  PovImport r = readPov("sphere { <1e308 / 10 * 10, 0, 0>, 1 }\n");
  ASSERT_TRUE(r.read.ok()) << r.read.diagnostics.items().front().message;
  ASSERT_EQ(r.read.scene.objects.size(), 1u);
  EXPECT_EQ(r.read.scene.objects[0].matrix[3][0], 1e308 / 10 * 10);
  EXPECT_TRUE(everyNumberFinite(r.read.scene));
}

TEST(FiniteValues, APovPlaneNormalTooShortForPovRaySaysSoNotLengthZero) {
  PovImport r = readPov("plane { <0, 1e-300, 0>, 0 }\n");
  Diagnostic d = expectOne(r.read.diagnostics, DiagnosticCode::PovDegenerate, 3, 1);
  EXPECT_EQ(d.message,
            "the plane's normal is too short to give a direction (length 1e-300, below "
            "POV-Ray's 1e-10)");
  PovImport zero = readPov("plane { <0, 0, 0>, 0 }\n");
  EXPECT_EQ(expectOne(zero.read.diagnostics, DiagnosticCode::PovDegenerate, 3, 1).message,
            "the plane's normal has length 0");
}

// --- Instruction files: the composed chain ---------------------------------

std::string instructionWith(const std::string& transforms) {
  return "OUTPUT_FILE out.ppm\nSTART CAMERA\n  LOCATION 0 0 5\n  LOOK_AT 0 0 0\nEND CAMERA\n"
         "START OBJECT SPHERE\n  START TRANSFORMATION\n" +
         transforms + "  END TRANSFORMATION\nEND OBJECT\n";
}

TEST(FiniteValues, AnInstructionChainThatOverflowsIsAnErrorAtTheOperationThatDidIt) {
  // Lines 8 and 9 are the first two operations.
  ReadResult scale = parseInstructionFile(
      instructionWith("    SCALE 1e200 1e200 1e200\n    SCALE 1e200 1 1\n"), "t.txt");
  Diagnostic d = expectOne(scale.diagnostics, DiagnosticCode::ValueNotFinite, 9, 5);
  EXPECT_EQ(d.message,
            "SCALE makes the object's matrix overflow a double (operation 2 of the "
            "TRANSFORMATION)");
  EXPECT_TRUE(scale.scene.objects.empty());

  ReadResult translate = parseInstructionFile(
      instructionWith("    TRANSLATE 1e308 0 0\n    ROTATE_Y 0.5\n    TRANSLATE 1e308 0 0\n"),
      "t.txt");
  expectOne(translate.diagnostics, DiagnosticCode::ValueNotFinite, 10, 5);

  // Right at the edge: 2 * 8.9e307 is finite, and stays valid.
  ReadResult edge = parseInstructionFile(
      instructionWith("    TRANSLATE 8.9e307 0 0\n    TRANSLATE 8.9e307 0 0\n"), "t.txt");
  EXPECT_TRUE(edge.ok());
}

TEST(FiniteValues, CheckedComposeStopsWhereTheUncheckedOneWouldOverflow) {
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<TransformOp> ops(1 + trial % 6);
    for (TransformOp& op : ops) {
      op.kind = static_cast<TransformKind>(random() % 5);
      op.value =
          glm::dvec3(std::pow(10.0, exponent(random)), std::pow(10.0, exponent(random)), 1.0);
    }
    std::optional<std::size_t> overflow;
    glm::dmat4 checked = composeTransform(ops, overflow);
    std::size_t good = overflow ? *overflow : ops.size();
    // The matrix returned is the product of the operations before the one
    // that overflowed, bit for bit; with that one too, an entry is not finite.
    EXPECT_EQ(checked, composeTransform(std::span(ops).first(good)));
    if (overflow) {
      glm::dmat4 over = composeTransform(std::span(ops).first(good + 1));
      bool finite = true;
      for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) finite &= std::isfinite(over[c][r]);
      }
      EXPECT_FALSE(finite);
    }
  }
}

// --- Cameras of any scale --------------------------------------------------

std::string sfCamera(const char* axis) {
  std::string a(axis);
  return "CAMERA\n0 0 0\n" + a + " 0 0 0\n0 " + a + " 0 0\n0 0 " + a + " 5\n0 0 0 1\n" +
         testing::kLightRecord;
}

TEST(FiniteValues, CameraAxesOfLength1em300And1e300AreValid) {
  for (const char* axis : {"1e-300", "1e300", "1e308", "4.9e-324"}) {
    SCOPED_TRACE(axis);
    ReadResult r = parseSceneFile(sfCamera(axis), "t.sf");
    EXPECT_TRUE(r.ok()) << r.diagnostics.items().front().message;
    EXPECT_TRUE(withCode(r.diagnostics, DiagnosticCode::CameraDegenerate).empty());
  }
  // Zero and parallel axes are still refused.
  EXPECT_FALSE(parseSceneFile(sfCamera("0"), "t.sf").ok());
}

TEST(FiniteValues, LookAtAnyFiniteDistanceAwayGivesAUnitCamera) {
  for (double distance : {1e-320, 1e-300, 1.0, 1e200, 1e308}) {
    SCOPED_TRACE(distance);
    glm::dmat4 m = cameraFromLookAt({0, 0, 0}, {distance, distance / 2, 0});
    EXPECT_NEAR(glm::length(glm::dvec3(m[2])), 1.0, 1e-15);
    EXPECT_NEAR(glm::length(glm::dvec3(m[1])), 1.0, 1e-15);
    EXPECT_LT(m[2][0], 0.0);  // forward is -m[2], towards +x
  }
}

TEST(FiniteValues, ABadNumberInTheCameraIsNotAlsoAMissingCamera) {
  const std::string light = testing::kLightRecord;
  for (const char* row : {"0 0 1 5x", "0 0 1 5 7", "0 0 1"}) {
    SCOPED_TRACE(row);
    std::string text =
        "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n" + std::string(row) + "\n0 0 0 1\n" + light;
    ReadResult r = parseSceneFile(text, "t.sf");
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(withCode(r.diagnostics, DiagnosticCode::MissingCamera).empty());
  }
}

// --- scaledLength and scaledNormalize --------------------------------------

TEST(FiniteValues, ScaledLengthIsGlmLengthWhereThatNeitherUnderflowsNorOverflows) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> value(-1e3, 1e3);
  for (int i = 0; i < 10000; ++i) {
    glm::dvec3 v(value(random), value(random), value(random));
    ASSERT_EQ(scaledLength(v), glm::length(v));
    ASSERT_EQ(scaledNormalize(v), v / glm::length(v));
  }
  EXPECT_EQ(scaledLength(glm::dvec3(std::ldexp(3.0, -1000), std::ldexp(4.0, -1000), 0)),
            std::ldexp(5.0, -1000));
  EXPECT_EQ(scaledLength(glm::dvec3(std::ldexp(3.0, 1000), std::ldexp(4.0, 1000), 0)),
            std::ldexp(5.0, 1000));
  EXPECT_EQ(scaledLength(glm::dvec3(0.0)), 0.0);
  EXPECT_EQ(scaledNormalize(glm::dvec3(4.9e-324, 0, 0)), glm::dvec3(1, 0, 0));
  EXPECT_EQ(scaledNormalize(glm::dvec3(0, -1.7e308, 0)), glm::dvec3(0, -1, 0));
  EXPECT_EQ(scaledLength(glm::dvec3(1.7e308, 1.7e308, 0)), kInf);
}

// --- The last line ---------------------------------------------------------

TEST(FiniteValues, CheckSceneFiniteNamesEveryRecordThatHoldsANonFiniteNumber) {
  Scene s = testing::smallScene();
  DiagnosticList clean;
  EXPECT_TRUE(checkSceneFinite(s, clean));
  EXPECT_TRUE(clean.empty());
  s.camera.span = {1, 1, 6};
  s.lights[0].span = {7, 1, 5};
  s.objects[0].span = {13, 1, 6};
  s.lights[0].colour.g = kInf;
  s.objects[0].material.ri = kNaN;
  Object second = s.objects[0];
  second.material.ri = 1.0;
  second.span = {19, 1, 6};
  second.transforms = std::vector<TransformOp>{
      TransformOp{TransformKind::Scale, {1, kNaN, 1}, SourceSpan{22, 5, 5}}};
  s.objects.push_back(second);
  DiagnosticList out;
  EXPECT_FALSE(checkSceneFinite(s, out));
  ASSERT_EQ(out.errorCount(), 3u);
  EXPECT_EQ(out.items()[0].span.line, 7u);
  EXPECT_EQ(out.items()[0].message, "light 1 holds a value that is not finite");
  EXPECT_EQ(out.items()[1].span.line, 13u);
  EXPECT_EQ(out.items()[2].span.line, 22u);
  EXPECT_EQ(out.items()[2].message, "SCALE of SPHERE object 2 holds a value that is not finite");
}

// The readers' test of many objects on several threads finds a non-finite
// number in any part, the first object, the last and one on each side of
// where two parts meet, and passes a clean scene, for any thread count.
TEST(FiniteValues, TheObjectsTestOnSeveralThreadsFindsANonFiniteNumberInAnyPart) {
  constexpr std::size_t kCount = 200000;  // three parts of at least 1 << 16
  std::vector<Object> objects(kCount);
  for (unsigned threads : {0u, 1u, 2u, 3u, 8u}) {
    SCOPED_TRACE(threads);
    EXPECT_TRUE(objectsFinite(objects, threads));
    for (std::size_t at : {std::size_t{0}, kCount / 2 - 1, kCount / 2, kCount - 1}) {
      SCOPED_TRACE(at);
      objects[at].matrix[3][1] = kNaN;
      EXPECT_FALSE(objectsFinite(objects, threads));
      objects[at].matrix[3][1] = 0.0;
      objects[at].material.shininess = kInf;
      EXPECT_FALSE(objectsFinite(objects, threads));
      objects[at].material.shininess = 200.0;
      objects[at].transforms = std::vector<TransformOp>{
          TransformOp{TransformKind::Translate, {0, 0, -kInf}, SourceSpan{}}};
      EXPECT_FALSE(objectsFinite(objects, threads));
      objects[at].transforms.reset();
    }
  }
  // What the readers report then: the one object, by its number.
  objects[kCount / 2].material.colour.b = kNaN;
  DiagnosticList out;
  EXPECT_FALSE(checkObjectsFinite(objects, out));
  ASSERT_EQ(out.errorCount(), 1u);
  EXPECT_EQ(out.items()[0].message, "SPHERE object 100001 holds a value that is not finite");
}

TEST(FiniteValues, NoReaderAcceptsANonFiniteNumberFromTheHostileValues) {
  // The spellings that found these bugs, in every place a number stands.
  const char* values[] = {"nan", "inf", "-inf", "1e400", "0x10", "1e308*10", "0/0", "sqrt(-1)"};
  for (const char* v : values) {
    SCOPED_TRACE(v);
    std::string sf =
        testing::kCameraRecord + "LIGHT\n1 1 " + v + "\n1 0 0 3\n0 1 0 3\n0 0 1 3\n" + "0 0 0 1\n";
    ReadResult a = parseScene(sf, "t.sf");
    EXPECT_TRUE(!a.ok() || everyNumberFinite(a.scene));
    ReadResult b = parseScene(kPovHead + "sphere { <" + v + ", 0, 0>, 1 }\n", "t.pov");
    EXPECT_FALSE(b.ok());
    EXPECT_TRUE(everyNumberFinite(b.scene));
  }
}

}  // namespace
}  // namespace scene
