// Property tests over seeded random scenes: what the writers write, the
// readers read back exactly.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "libscene/formats/instruction/instruction_writer.h"
#include "libscene/formats/pov/pov_reader.h"
#include "libscene/formats/pov/pov_writer.h"
#include "libscene/formats/sf/sf_writer.h"
#include "libscene/testing/random_cases.h"
#include "scenefile/convert.h"
#include "scenefile/read.h"
#include "scenefile/transform.h"

namespace scene {
namespace {

constexpr double kPi = std::numbers::pi;

class RandomScenes {
 public:
  explicit RandomScenes(std::uint64_t seed) : rng_(seed) {}

  // Any double a valid file may hold in a place with no constraint: plain
  // decimals, full-precision values, huge and subnormal magnitudes, -0.
  double anyValue() {
    switch (rng_() % 6) {
      case 0:
        return static_cast<double>(static_cast<int>(rng_() % 2001) - 1000) / 8.0;
      case 1:
        return uniform(-1e3, 1e3);
      case 2:
        return std::ldexp(uniform(-1, 1), static_cast<int>(rng_() % 2000) - 1000);
      case 3:
        return 4.9406564584124654e-324 * static_cast<double>(rng_() % 1000);
      case 4:
        return -0.0;
      default:
        return std::ldexp(uniform(-1, 1), 1000);
    }
  }

  double nonNegative() { return std::abs(anyValue()) * (rng_() % 2 ? 1.0 : 0.0) + unit(); }
  double unit() { return uniform(0.0, 1.0); }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  double angle() {
    switch (rng_() % 5) {
      case 0:
        return kPi / 2;
      case 1:
        return -kPi / 2;
      case 2:
        return (rng_() % 2 ? 1.0 : -1.0) * (kPi / 2 + std::ldexp(uniform(-1, 1), -30));
      default:
        return uniform(-2 * kPi, 2 * kPi);
    }
  }
  // A scale factor from 1e-4 to 1e4, either sign.
  double scaleFactor() {
    double s = std::pow(10.0, uniform(-4, 4));
    return rng_() % 4 == 0 ? -s : s;
  }
  double mildFactor() { return (rng_() % 4 == 0 ? -1.0 : 1.0) * uniform(0.5, 5.0); }
  std::uint64_t next() { return rng_(); }

  // A list of operations that an instruction file can hold without shear:
  // a non-uniform scale first (ratios up to 1e8, so that the condition
  // number stays below 1e12), then rotations, uniform scales and
  // translations in any order (mild non-uniform scales after quarter turns).
  std::vector<TransformOp> transformList() {
    std::vector<TransformOp> ops;
    auto add = [&ops](TransformKind kind, glm::dvec3 v) { ops.push_back({kind, v, {}}); };
    if (rng_() % 2) add(TransformKind::Scale, {scaleFactor(), scaleFactor(), scaleFactor()});
    int count = static_cast<int>(rng_() % 6);
    bool onlyQuarterTurns = true;
    for (int i = 0; i < count; ++i) {
      switch (rng_() % 5) {
        case 0: {
          double s = scaleFactor();
          add(TransformKind::Scale, {s, s, s});
          break;
        }
        case 1:
          add(TransformKind::Translate, {anyFinite(), anyFinite(), anyFinite()});
          break;
        case 2:
          // After a quarter turn (cos(pi/2) is 6e-17, not 0), a scale ratio
          // r turns that rounding into a shear of 6e-17 r: keep r small.
          if (onlyQuarterTurns) {
            add(TransformKind::Scale, {mildFactor(), mildFactor(), mildFactor()});
            break;
          }
          [[fallthrough]];
        default: {
          double a = angle();
          onlyQuarterTurns &= std::abs(std::remainder(a, kPi / 2)) == 0.0;
          TransformKind kind = std::array{TransformKind::RotateX, TransformKind::RotateY,
                                          TransformKind::RotateZ}[rng_() % 3];
          add(kind, {a, 0.0, 0.0});
        }
      }
    }
    return ops;
  }

  double anyFinite() { return uniform(-1e6, 1e6); }

  // A scene as an instruction file holds it: OUTPUT_FILE, a LOOK_AT camera,
  // objects with operation lists, and random material values when asked.
  Scene instructionScene(bool randomMaterials) {
    Scene scene = sceneFileScene();
    scene.outputFile = "out.ppm";
    scene.camera.lookAt = glm::dvec3(scene.camera.matrix[3]) - glm::dvec3(scene.camera.matrix[2]);
    for (Object& object : scene.objects) {
      object.transforms = transformList();
      object.matrix = composeTransform(*object.transforms);
      if (!randomMaterials) continue;
      for (MaterialProperty p : kMaterialProperties) {
        double v = unit();
        if (p == MaterialProperty::Shininess) v = 1.0 + 500.0 * v;
        if (p == MaterialProperty::Ri) v = 1.0 + v;
        materialValue(object.material, p) = v;
      }
    }
    return scene;
  }

  Scene sceneFileScene() {
    Scene s;
    s.camera.colour = {nonNegative(), anyValue(), unit()};
    s.camera.matrix = cameraFromLookAt({anyFinite(), anyFinite(), anyFinite()},
                                       {anyFinite(), anyFinite(), anyFinite()});
    int lights = static_cast<int>(next() % 4);
    for (int i = 0; i < lights; ++i) {
      Light light;
      light.colour = {nonNegative(), nonNegative(), nonNegative()};
      for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 3; ++r) light.matrix[c][r] = anyValue();
      }
      s.lights.push_back(light);
    }
    int objects = static_cast<int>(next() % 8);
    for (int i = 0; i < objects; ++i) {
      Object object;
      object.kind = static_cast<ObjectKind>(next() % 4);
      object.material.colour = {unit(), unit(), rng_() % 8 ? unit() : 0.0};
      object.matrix = composeTransform(transformList());
      s.objects.push_back(object);
    }
    return s;
  }

 private:
  std::mt19937_64 rng_;
};

// |a - b| per column of the 3x3 block, against that column's norm.
double columnError(const glm::dmat4& a, const glm::dmat4& b) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    double norm = glm::length(glm::dvec3(a[c]));
    for (int r = 0; r < 3; ++r) worst = std::max(worst, std::abs(a[c][r] - b[c][r]) / norm);
  }
  return worst;
}

TEST(RoundTripProperty, SceneFileWriteReadWriteIsByteIdentical) {
  RandomScenes random(20261122);
  for (int i = 0; i < 10000; ++i) {
    Scene scene = random.sceneFileScene();
    std::string first = writeSceneFile(scene);
    ReadResult read = parseScene(first, "random.sf");
    ASSERT_TRUE(read.ok()) << "scene " << i << ": " << read.diagnostics.items().front().message
                           << "\n"
                           << first;
    ASSERT_EQ(read.scene, scene) << "scene " << i;
    ASSERT_EQ(writeSceneFile(read.scene), first) << "scene " << i;
  }
}

// sf -> pov -> sf is byte-identical: matrices and colours in POV-Ray's own
// syntax, the camera and any light matrix beyond a translation in the
// writer's exact comments.
TEST(RoundTripProperty, SceneFilePovSceneFileIsByteIdentical) {
  RandomScenes random(3141);
  for (int i = 0; i < 1000; ++i) {
    Scene scene = random.sceneFileScene();
    std::string sf = writeSceneFile(scene);
    DiagnosticList diagnostics;
    std::optional<std::string> pov = writePovScene(scene, {}, diagnostics);
    ASSERT_TRUE(pov.has_value());
    PovImport back = importPov(*pov, "random.pov");
    ASSERT_TRUE(back.read.ok()) << "scene " << i << ": "
                                << back.read.diagnostics.items().front().message << "\n"
                                << *pov;
    ASSERT_EQ(writeSceneFile(back.read.scene), sf) << "scene " << i << "\n" << *pov;
  }
}

// instruction -> pov -> instruction is byte-identical too: every material
// value in POV-Ray's finish, pigment and interior, the operations, LOOK_AT
// and OUTPUT_FILE in the exact comments.
TEST(RoundTripProperty, InstructionPovInstructionIsByteIdentical) {
  RandomScenes random(2718);
  for (int i = 0; i < 1000; ++i) {
    Scene scene = random.instructionScene(true);
    DiagnosticList diagnostics;
    std::optional<std::string> direct = writeInstructionFile(scene, {}, diagnostics);
    std::optional<std::string> pov = writePovScene(scene, {}, diagnostics);
    ASSERT_TRUE(direct && pov);
    PovImport back = importPov(*pov, "random.pov");
    ASSERT_TRUE(back.read.ok()) << "scene " << i << ": "
                                << back.read.diagnostics.items().front().message;
    std::optional<std::string> viaPov = writeInstructionFile(back.read.scene, {}, diagnostics);
    ASSERT_TRUE(viaPov.has_value());
    ASSERT_EQ(*viaPov, *direct) << "scene " << i << "\n" << *pov;
  }
}

TEST(RoundTripProperty, TransformListsSurviveInstructionSceneInstructionScene) {
  RandomScenes random(7);
  double worst = 0.0;
  for (int i = 0; i < testing::randomCases(10000); ++i) {
    Scene scene = random.instructionScene(false);
    // instruction -> .sf
    DiagnosticList diagnostics;
    std::optional<std::string> instructions = writeInstructionFile(scene, {}, diagnostics);
    ASSERT_TRUE(instructions.has_value());
    ReadResult fromInstructions = parseScene(*instructions, "a.txt");
    ASSERT_TRUE(fromInstructions.ok()) << *instructions;
    std::optional<std::string> sf1 =
        convertScene(fromInstructions.scene, Format::SceneFile, {}, diagnostics);
    ReadResult scene1 = parseScene(*sf1, "b.sf");
    ASSERT_TRUE(scene1.ok());
    // .sf -> instruction -> .sf, through decomposition.
    std::optional<std::string> instructions2 =
        convertScene(scene1.scene, Format::InstructionFile, {}, diagnostics);
    ASSERT_TRUE(instructions2.has_value())
        << "scene " << i << ": " << diagnostics.items().back().message;
    ReadResult fromInstructions2 = parseScene(*instructions2, "c.txt");
    ASSERT_TRUE(fromInstructions2.ok()) << *instructions2;
    std::optional<std::string> sf2 =
        convertScene(fromInstructions2.scene, Format::SceneFile, {}, diagnostics);
    ReadResult scene2 = parseScene(*sf2, "d.sf");
    ASSERT_TRUE(scene2.ok());

    ASSERT_EQ(scene2.scene.objects.size(), scene1.scene.objects.size());
    for (std::size_t k = 0; k < scene1.scene.objects.size(); ++k) {
      const glm::dmat4& m1 = scene1.scene.objects[k].matrix;
      const glm::dmat4& m2 = scene2.scene.objects[k].matrix;
      double error = columnError(m1, m2);
      worst = std::max(worst, error);
      ASSERT_LE(error, 1e-12) << "scene " << i << " object " << k << "\n" << *instructions2;
      ASSERT_EQ(m1[3], m2[3]) << "translations are written exactly";
    }
    ASSERT_LE(columnError(scene1.scene.camera.matrix, scene2.scene.camera.matrix), 1e-12);
    ASSERT_EQ(scene1.scene.camera.matrix[3], scene2.scene.camera.matrix[3]);
  }
  std::cout << "worst relative column error: " << worst << "\n";
}

}  // namespace
}  // namespace scene
