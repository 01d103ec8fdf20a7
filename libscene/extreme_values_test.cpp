// Numbers at the edges of the doubles through every writer: values within a
// factor of 2 of the largest double, subnormals and -0 in every place a valid
// scene may hold them. Each writer either writes a file that reads back, with
// every number finite and as exact as its format promises (docs/FORMATS.md,
// GLTF.md, POVRAY.md), or refuses with an error; it never writes nan, inf or
// null.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "libscene/formats/instruction/instruction_writer.h"
#include "libscene/formats/pov/pov_writer.h"
#include "libscene/formats/sf/sf_writer.h"
#include "libscene/testing/random_cases.h"
#include "libscene/testing/random_scenes.h"
#include "scenefile/convert.h"
#include "scenefile/matrix.h"
#include "scenefile/read.h"
#include "scenefile/transform.h"

namespace scene {
namespace {

constexpr double kLargest = std::numeric_limits<double>::max();
constexpr double kSmallest = std::numeric_limits<double>::denorm_min();

// A file name in the format's first extension: "limits.gltf".
std::string nameFor(Format format) {
  return "limits" + std::string(formatInfo(format).extensions[0]);
}

std::string firstError(const DiagnosticList& list) {
  for (const Diagnostic& d : list.items()) {
    if (d.severity == Severity::Error) return std::string(codeName(d.code)) + ": " + d.message;
  }
  return "";
}

bool hasError(const DiagnosticList& list, DiagnosticCode code) {
  for (const Diagnostic& d : list.items()) {
    if (d.severity == Severity::Error && d.code == code) return true;
  }
  return false;
}

// The text of a GLB's JSON chunk (its binary chunk holds floats, whose bytes
// may spell anything); any other output as it is.
std::string_view jsonPart(std::string_view bytes, Format format) {
  if (format != Format::Glb || bytes.size() < 20) return bytes;
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, sizeof length);
  return bytes.substr(20, std::min<std::size_t>(length, bytes.size() - 20));
}

// A token of the text that spells a non-finite number (nan, inf, null), or
// empty: what no writer may ever write.
std::string nonFiniteToken(std::string_view text) {
  static constexpr std::string_view kSeparators = " \t\r\n,<>[]{}():\"";
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t end = text.find_first_of(kSeparators, i);
    if (end == std::string_view::npos) end = text.size();
    std::string token(text.substr(i, end - i));
    for (char& c : token) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!token.empty() && (token[0] == '-' || token[0] == '+')) token.erase(0, 1);
    if (token == "nan" || token == "inf" || token == "infinity" || token == "null") return token;
    i = end + 1;
  }
  return "";
}

// One conversion and its reading back. `written` is false when the writer
// refused; it must then have said why with an error.
struct Through {
  bool written = false;
  std::string text;
  DiagnosticList diagnostics;
  std::optional<ReadResult> back;
};

Through through(const Scene& scene, Format format, const ConversionOptions& options = {}) {
  Through t;
  std::optional<std::string> text = convertScene(scene, format, options, t.diagnostics);
  if (!text) {
    EXPECT_GT(t.diagnostics.errorCount(), 0u) << nameFor(format) << ": refused in silence";
    return t;
  }
  t.written = true;
  t.text = std::move(*text);
  std::string bad = nonFiniteToken(jsonPart(t.text, format));
  EXPECT_EQ(bad, "") << nameFor(format) << " holds '" << bad << "'\n"
                     << (format == Format::Glb ? "" : t.text);
  t.back = parseScene(t.text, nameFor(format));
  EXPECT_TRUE(t.back->ok()) << nameFor(format) << ": " << firstError(t.back->diagnostics) << "\n"
                            << (format == Format::Glb ? "" : t.text);
  if (t.back->ok()) {
    EXPECT_EQ(testing::firstNonFinite(t.back->scene), "") << nameFor(format);
  }
  return t;
}

ConversionOptions approximate() {
  ConversionOptions options;
  options.instructions.approximate = true;
  return options;
}

std::string instructionText(const Scene& scene) {
  DiagnosticList ignored;
  ConversionOptions options;
  options.instructions.approximate = true;
  return writeInstructionFile(scene, options, ignored).value_or("(refused)");
}

// |a - b| per column of the 3x3 block, against that column's length.
double scaledColumnError(const glm::dmat4& a, const glm::dmat4& b) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    double norm = scaledLength(glm::dvec3(a[c]));
    worst = std::max(worst, scaledLength(glm::dvec3(a[c]) - glm::dvec3(b[c])) / norm);
  }
  return worst;
}

struct Tally {
  int written = 0;
  int refused = 0;
  int exact = 0;
};

// The scene as a scene file holds it (default materials, no operations),
// through every format: .sf, glTF, GLB and POV-Ray give back every bit; an
// instruction file (written with the approximate option, since a random camera rolls
// and a random matrix shears) reads back with the eye and every translation
// exact, the rest within 1e-12 per column, and writes itself again.
void checkSceneFileScene(const Scene& scene, int index, std::map<Format, Tally>& tally) {
  const std::string sf = writeSceneFile(scene);
  for (const FormatInfo& row : formats()) {
    Format format = row.format;
    Through t = through(scene, format, approximate());
    Tally& counts = tally[format];
    if (!t.written) {
      ++counts.refused;
      // The refusals a finite scene may get: a camera that no finite
      // LOOK_AT describes; an OBJ mesh whose vertices overflow in world
      // space (OBJ has no transforms).
      EXPECT_TRUE((format == Format::InstructionFile || format == Format::Obj) &&
                  hasError(t.diagnostics, DiagnosticCode::ValueNotFinite))
          << "scene " << index << " " << nameFor(format) << ": " << firstError(t.diagnostics)
          << "\n"
          << sf;
      continue;
    }
    ++counts.written;
    if (!t.back || !t.back->ok()) continue;
    const Scene& back = t.back->scene;
    if (format != Format::InstructionFile) {
      ASSERT_EQ(writeSceneFile(back), sf) << "scene " << index << " " << nameFor(format);
      ASSERT_EQ(testing::numberBits(back), testing::numberBits(scene))
          << "scene " << index << " " << nameFor(format);
      ++counts.exact;
      continue;
    }
    ASSERT_EQ(back.objects.size(), scene.objects.size());
    ASSERT_EQ(back.camera.matrix[3], scene.camera.matrix[3]) << "scene " << index;
    ASSERT_LE(scaledLength(glm::dvec3(back.camera.matrix[2]) -
                           unitDirection(glm::dvec3(scene.camera.matrix[2]))),
              1e-12)
        << "scene " << index << "\n"
        << t.text;
    for (std::size_t k = 0; k < back.objects.size(); ++k) {
      ASSERT_EQ(back.objects[k].matrix[3], scene.objects[k].matrix[3]) << "scene " << index;
      ASSERT_LE(scaledColumnError(scene.objects[k].matrix, back.objects[k].matrix),
                std::max(1e-12,
                         scaledColumnError(scene.objects[k].matrix,
                                           decomposeTransform(scene.objects[k].matrix).recomposed)))
          << "scene " << index << " object " << k;
    }
    ASSERT_EQ(instructionText(back), t.text) << "scene " << index;
  }
}

// A scene as an instruction file holds it (materials at their edges,
// operations, LOOK_AT, OUTPUT_FILE) comes back through glTF, GLB and
// POV-Ray with every bit, and through an instruction file as the same text.
void checkInstructionScene(const Scene& scene, int index, std::map<Format, Tally>& tally) {
  const std::string text = instructionText(scene);
  for (Format format : {Format::InstructionFile, Format::Gltf, Format::Glb, Format::Pov}) {
    Through t = through(scene, format, approximate());
    Tally& counts = tally[format];
    ASSERT_TRUE(t.written) << "scene " << index << " " << nameFor(format) << ": "
                           << firstError(t.diagnostics) << "\n"
                           << text;
    ++counts.written;
    ASSERT_TRUE(t.back && t.back->ok());
    ASSERT_EQ(instructionText(t.back->scene), text) << "scene " << index << " " << nameFor(format);
    ASSERT_EQ(testing::numberBits(t.back->scene), testing::numberBits(scene))
        << "scene " << index << " " << nameFor(format);
    ++counts.exact;
  }
}

TEST(ExtremeValues, RandomScenesAtTheLimitsOfTheDoublesSurviveEveryWriter) {
  testing::RandomSceneGenerator random(20261201);
  std::map<Format, Tally> fromSceneFiles;
  std::map<Format, Tally> fromInstructions;
  int checked = 0;
  int instructionScenes = 0;
  int invalid = 0;
  std::map<std::string, int> limitNumbers;
  for (int i = 0; checked < testing::randomCases(1000); ++i) {
    ASSERT_LT(i, testing::randomCases(10000)) << "too many random scenes were invalid";
    Scene generated = random.limitScene();
    // Only what a scene file may hold (sums of translations can overflow,
    // products of scales leave the condition number above 1e12).
    ReadResult valid = parseScene(writeSceneFile(generated), "limits.sf");
    if (!valid.ok()) {
      ++invalid;
      continue;
    }
    testing::forEachNumber(generated, [&limitNumbers](double v) {
      if (std::abs(v) >= kLargest / 2) ++limitNumbers["near the largest double"];
      if (v != 0.0 && std::abs(v) < std::numeric_limits<double>::min()) ++limitNumbers["subnormal"];
      if (v == 0.0 && std::signbit(v)) ++limitNumbers["-0"];
    });
    checkSceneFileScene(valid.scene, i, fromSceneFiles);
    if (::testing::Test::HasFatalFailure()) return;
    // The generated scene with its materials and operations, where an
    // instruction file may hold it.
    DiagnosticList diagnostics;
    std::optional<std::string> txt =
        convertScene(generated, Format::InstructionFile, approximate(), diagnostics);
    if (txt) {
      ReadResult instruction = parseScene(*txt, "limits.txt");
      ASSERT_TRUE(instruction.ok())
          << "scene " << i << ": " << firstError(instruction.diagnostics) << "\n"
          << *txt;
      checkInstructionScene(instruction.scene, i, fromInstructions);
      if (::testing::Test::HasFatalFailure()) return;
      ++instructionScenes;
    }
    ++checked;
  }
  // The figures that docs/FORMATS.md quotes.
  std::cout << checked << " valid scenes (" << invalid << " invalid ones skipped), "
            << instructionScenes << " of them also as instruction scenes\n";
  for (const auto& [what, count] : limitNumbers)
    std::cout << "  " << count << " numbers " << what << "\n";
  for (const FormatInfo& row : formats()) {
    Format format = row.format;
    const Tally& s = fromSceneFiles[format];
    const Tally& t = fromInstructions[format];
    std::cout << "  " << nameFor(format) << ": from .sf " << s.written << " written (" << s.exact
              << " bit for bit), " << s.refused << " refused; from instructions " << t.written
              << " written (" << t.exact << " bit for bit)\n";
  }
  EXPECT_GE(limitNumbers["near the largest double"], 500);
  EXPECT_GE(limitNumbers["subnormal"], 500);
  EXPECT_GE(limitNumbers["-0"], 500);
}

// A camera whose eye is near the largest double. The LOOK_AT
// distance used to be 2^1024, an infinity in the file.
TEST(ExtremeValues, AnEyeNearTheLargestDoubleGetsAFiniteLookAt) {
  for (double eye : {kLargest, -kLargest, kLargest / 1.5, std::ldexp(1.0, 1023)}) {
    Scene scene = testing::RandomSceneGenerator(1).scene(false);
    scene.camera.matrix = cameraFromLookAt(glm::dvec3(eye, eye / 2, -eye), glm::dvec3(0.0));
    scene.camera.lookAt.reset();
    Through t = through(scene, Format::InstructionFile, approximate());
    ASSERT_TRUE(t.written) << firstError(t.diagnostics);
    ASSERT_TRUE(t.back && t.back->ok());
    const Camera& back = t.back->scene.camera;
    ASSERT_TRUE(back.lookAt.has_value());
    EXPECT_EQ(back.matrix[3], scene.camera.matrix[3]);
    EXPECT_LE(scaledLength(glm::dvec3(back.matrix[2] - scene.camera.matrix[2])), 1e-12) << t.text;
  }
}

// Looking further out from the largest double, every point ahead
// overflows: the writer refuses, at the camera, rather than write inf.
TEST(ExtremeValues, AnEyeAtTheLargestDoubleLookingOutIsRefused) {
  Scene scene;
  scene.camera.matrix = cameraFromLookAt(glm::dvec3(kLargest, 0.0, 0.0), glm::dvec3(0.0));
  // Turn it about: forward +x, away from the origin.
  scene.camera.matrix[0] = -scene.camera.matrix[0];
  scene.camera.matrix[2] = -scene.camera.matrix[2];
  scene.camera.span = {1, 1, 6};
  DiagnosticList diagnostics;
  std::optional<std::string> text =
      convertScene(scene, Format::InstructionFile, approximate(), diagnostics);
  EXPECT_FALSE(text.has_value()) << *text;
  ASSERT_TRUE(hasError(diagnostics, DiagnosticCode::ValueNotFinite)) << firstError(diagnostics);
  EXPECT_EQ(diagnostics.items().back().span.line, 1u);
  // Slightly inside the largest double there is room ahead: written.
  scene.camera.matrix[3].x = kLargest / 1.01;
  Through t = through(scene, Format::InstructionFile, approximate());
  EXPECT_TRUE(t.written) << firstError(t.diagnostics);
}

// Camera axes of length 2^-1000 and 2^1000 are valid; every writer gives
// finite vectors for them (the plain normalisation gives inf or 0).
TEST(ExtremeValues, CameraAxesOfAnyLengthGiveFiniteVectors) {
  for (int exponent : {-1000, -600, 600, 1000}) {
    Scene scene = testing::RandomSceneGenerator(2).scene(false);
    glm::dmat4 camera = cameraFromLookAt(glm::dvec3(1, 2, 3), glm::dvec3(0.0));
    for (int c = 0; c < 3; ++c) camera[c] *= std::ldexp(1.0, exponent);
    scene.camera.matrix = camera;
    scene.camera.lookAt.reset();
    const std::string sf = writeSceneFile(scene);
    ASSERT_TRUE(parseScene(sf, "axes.sf").ok()) << sf;
    for (const FormatInfo& row : formats()) {
      Format format = row.format;
      Through t = through(scene, format, approximate());
      ASSERT_TRUE(t.written) << exponent << " " << nameFor(format) << ": "
                             << firstError(t.diagnostics);
      if (format == Format::InstructionFile) continue;
      ASSERT_TRUE(t.back && t.back->ok());
      EXPECT_EQ(writeSceneFile(t.back->scene), sf) << exponent << " " << nameFor(format);
    }
  }
}

// TRANSPARENCY -0 (and every other material value at -0) comes back through
// POV-Ray bit for bit: written as rgbt's -0, which renders as rgb.
TEST(ExtremeValues, NegativeZeroMaterialValuesComeBackThroughEveryFormat) {
  const std::string text =
      "OUTPUT_FILE out.ppm\n"
      "START CAMERA\n  LOCATION 0 0 5\n  LOOK_AT 0 0 0\nEND CAMERA\n"
      "START LIGHT\n  LOCATION -0 4 4\n  COLOUR 1 -0 1\nEND LIGHT\n"
      "START OBJECT SPHERE\n  START MATERIAL\n    COLOUR -0 0.5 -0\n    AMBIENT -0\n"
      "    DIFFUSE -0\n    SPECULAR -0\n    SHININESS 5e-324\n    REFLECTIVITY -0\n"
      "    TRANSPARENCY -0\n    RI 1.7976931348623157e308\n  END MATERIAL\n"
      "  START TRANSFORMATION\n    TRANSLATE -0 -0 -0\n  END TRANSFORMATION\nEND OBJECT\n";
  ReadResult read = parseScene(text, "negative-zero.txt");
  ASSERT_TRUE(read.ok()) << firstError(read.diagnostics);
  ASSERT_TRUE(std::signbit(read.scene.objects[0].material.transparency));
  for (Format format : {Format::InstructionFile, Format::Gltf, Format::Glb, Format::Pov}) {
    Through t = through(read.scene, format);
    ASSERT_TRUE(t.written) << nameFor(format) << ": " << firstError(t.diagnostics);
    ASSERT_TRUE(t.back && t.back->ok());
    EXPECT_TRUE(std::signbit(t.back->scene.objects[0].material.transparency)) << nameFor(format);
    EXPECT_EQ(testing::numberBits(t.back->scene), testing::numberBits(read.scene))
        << nameFor(format);
    EXPECT_EQ(instructionText(t.back->scene), instructionText(read.scene)) << nameFor(format);
  }
}

// Lights whose colours sum beyond the largest double: POV-Ray's
// ambient_light (their sum) is clamped, with a loss; noLoss refuses.
TEST(ExtremeValues, LightsSummingBeyondTheLargestDoubleClampAmbientLight) {
  Scene scene = testing::RandomSceneGenerator(3).scene(false);
  scene.lights.resize(2);
  for (Light& light : scene.lights) light.colour = glm::dvec3(kLargest, kSmallest, -0.0);
  scene.lights[1].span = {7, 1, 5};
  Through t = through(scene, Format::Pov);
  ASSERT_TRUE(t.written);
  EXPECT_NE(t.text.find("ambient_light rgb <1.7976931348623157e+308"), std::string::npos) << t.text;
  bool warned = false;
  for (const Diagnostic& d : t.diagnostics.items()) {
    warned |=
        d.code == DiagnosticCode::LossPov && d.span.line == 7 && d.severity == Severity::Warning;
  }
  EXPECT_TRUE(warned);
  ConversionOptions noLoss;
  noLoss.noLoss = true;
  DiagnosticList diagnostics;
  EXPECT_FALSE(convertScene(scene, Format::Pov, noLoss, diagnostics).has_value());
  EXPECT_TRUE(hasError(diagnostics, DiagnosticCode::LossPov));
}

// A field of view with no finite image plane is refused, not written as
// inf: the writers are given settings, not only scenes, and hold them to a
// view's range (checkView).
TEST(ExtremeValues, AFieldOfViewWithNoFiniteImagePlaneIsRefused) {
  Scene scene = testing::RandomSceneGenerator(4).scene(false);
  ConversionOptions options;
  options.pov.verticalFovDegrees = 360.0;
  DiagnosticList diagnostics;
  EXPECT_FALSE(convertScene(scene, Format::Pov, options, diagnostics).has_value());
  EXPECT_TRUE(hasError(diagnostics, DiagnosticCode::ValueOutOfRange));
}

// A turned PLANE whose origin and the eye lie near opposite largest
// doubles: the side of the eye is still found (unhalved, the offset is
// (-inf, inf, 0), and the plane's local y became inf - inf, NaN).
TEST(ExtremeValues, ThePlaneFacesAnEyeBeyondTheRangeOfItsOffset) {
  Scene scene;
  scene.camera.matrix = cameraFromLookAt(glm::dvec3(-kLargest, kLargest, 0.0), glm::dvec3(0.0));
  Object plane;
  plane.kind = ObjectKind::Plane;
  plane.matrix[0] = glm::dvec4(0.6, -0.8, 0.0, 0.0);
  plane.matrix[1] = glm::dvec4(0.8, 0.6, 0.0, 0.0);
  plane.matrix[3] = glm::dvec4(kLargest, -kLargest, 0.0, 1.0);
  scene.objects.push_back(plane);
  Through t = through(scene, Format::Pov);
  ASSERT_TRUE(t.written);
  EXPECT_NE(t.text.find("plane { -y, 0"), std::string::npos) << t.text;
}

// An object scaled by 1e50: its node matrix is clamped to floats (with a
// warning), and the chain that stands for it must hold no number beyond the
// largest float either (a column of 3.4e38 entries is 4.8e38 long), yet
// read back bit for bit from extras.
TEST(ExtremeValues, NoGltfNodeHoldsANumberBeyondTheLargestFloat) {
  Scene scene = testing::RandomSceneGenerator(5).scene(false);
  Object big;
  big.matrix = glm::dmat4(glm::dmat3(0.6, 0.8, 0.0, -0.8, 0.6, 0.0, 0.0, 0.0, 1.0) * 1e50);
  scene.objects = {big};
  const std::string sf = writeSceneFile(scene);
  Through t = through(scene, Format::Gltf);
  ASSERT_TRUE(t.written && t.back && t.back->ok());
  EXPECT_EQ(writeSceneFile(t.back->scene), sf);
  nlohmann::json doc = nlohmann::json::parse(t.text);
  double largest = 0.0;
  for (const nlohmann::json& node : doc["nodes"]) {
    for (const nlohmann::json& v : node["matrix"])
      largest = std::max(largest, std::abs(v.get<double>()));
  }
  EXPECT_LE(largest, std::numeric_limits<float>::max());
}

}  // namespace
}  // namespace scene
