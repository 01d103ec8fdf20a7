// Round trips through glTF: what the writer writes, the reader gives back
// bit for bit, for the corpus and for seeded random scenes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "libscene/formats/gltf/gltf_reader.h"
#include "libscene/formats/gltf/gltf_writer.h"
#include "libscene/formats/instruction/instruction_writer.h"
#include "libscene/formats/sf/sf_writer.h"
#include "libscene/testing/random_cases.h"
#include "libscene/testing/random_scenes.h"
#include "libscene/testing/test_support.h"
#include "scenefile/convert.h"
#include "scenefile/read.h"

namespace scene {
namespace {

namespace fs = std::filesystem;

using scene::testing::readText;

std::string firstError(const DiagnosticList& list) {
  for (const Diagnostic& d : list.items()) {
    if (d.severity == Severity::Error) return std::string(codeName(d.code)) + ": " + d.message;
  }
  return "";
}

// The scene through glTF (JSON or GLB) and back.
ReadResult throughGltf(const Scene& scene, bool binary) {
  DiagnosticList diagnostics;
  std::optional<GltfFiles> files = writeGltf(scene, {}, binary, diagnostics);
  EXPECT_TRUE(files.has_value()) << firstError(diagnostics);
  if (!files) return ReadResult{Scene{}, DiagnosticList{}};
  return parseScene(files->main, binary ? "scene.glb" : "scene.gltf");
}

std::optional<std::string> instructions(const Scene& scene) {
  DiagnosticList ignored;
  return writeInstructionFile(scene, {}, ignored);
}

TEST(GltfRoundTrip, EveryValidCorpusFileComesBackByteIdentical) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SCENE_TESTDATA_DIR) / "valid")) {
    std::string ext = entry.path().extension().string();
    if (ext != ".sf" && ext != ".txt") continue;
    ReadResult original = parseScene(readText(entry.path()), entry.path().string());
    ASSERT_TRUE(original.ok()) << entry.path();
    std::string sf = writeSceneFile(original.scene);
    std::optional<std::string> txt = instructions(original.scene);
    for (bool binary : {false, true}) {
      ReadResult back = throughGltf(original.scene, binary);
      ASSERT_TRUE(back.ok()) << entry.path() << ": " << firstError(back.diagnostics);
      EXPECT_EQ(writeSceneFile(back.scene), sf) << entry.path() << (binary ? " (glb)" : "");
      EXPECT_EQ(back.scene, original.scene) << entry.path();
      // instruction -> glTF -> instruction keeps every material value and
      // operation, so the text comes back as it was written.
      if (txt) {
        EXPECT_EQ(instructions(back.scene), txt) << entry.path();
      }
    }
    ++files;
  }
  EXPECT_GE(files, 50);
}

TEST(GltfRoundTrip, ThousandsOfRandomScenesComeBackByteIdentical) {
  testing::RandomSceneGenerator random(20261123);
  int checked = 0;
  for (int i = 0; checked < testing::randomCases(1500); ++i) {
    ASSERT_LT(i, testing::randomCases(3000)) << "too many random scenes were invalid";
    Scene scene = random.scene();
    std::string sf = writeSceneFile(scene);
    // Only scenes a scene file may hold (a product of scales can leave the
    // condition number above 1e12).
    if (!parseScene(sf, "random.sf").ok()) continue;
    for (bool binary : {false, true}) {
      ReadResult back = throughGltf(scene, binary);
      ASSERT_TRUE(back.ok()) << "scene " << i << ": " << firstError(back.diagnostics) << "\n" << sf;
      ASSERT_EQ(writeSceneFile(back.scene), sf) << "scene " << i << (binary ? " (glb)" : "");
      ASSERT_EQ(back.scene, scene) << "scene " << i;
    }
    ++checked;
  }
}

TEST(GltfRoundTrip, InstructionFileThroughGlbKeepsEveryMaterialValue) {
  std::string text = readText(fs::path(SCENE_TESTDATA_DIR) / "valid" / "all-material-values.txt");
  ReadResult original = parseScene(text, "all-material-values.txt");
  ASSERT_TRUE(original.ok());
  ReadResult back = throughGltf(original.scene, true);
  ASSERT_TRUE(back.ok()) << firstError(back.diagnostics);
  ASSERT_EQ(back.scene.objects.size(), original.scene.objects.size());
  for (std::size_t i = 0; i < original.scene.objects.size(); ++i) {
    EXPECT_EQ(back.scene.objects[i].material, original.scene.objects[i].material);
  }
  EXPECT_EQ(instructions(back.scene), instructions(original.scene));
}

// JavaScript writes -0 as 0 in JSON: a file rewritten by a JavaScript
// program (glTF-Transform, for one) keeps a zero's sign only where our
// extras spell it out.
TEST(GltfRoundTrip, NegativeZerosSurviveAJavaScriptRewrite) {
  ReadResult original = parseScene(
      readText(fs::path(SCENE_TESTDATA_DIR) / "valid" / "all-primitives.sf"), "all-primitives.sf");
  ASSERT_TRUE(original.ok());
  Scene scene = original.scene;
  scene.objects[0].matrix[0][1] = -0.0;
  scene.lights[0].colour.g = -0.0;
  scene.camera.matrix[3][0] = -0.0;
  std::string sf = writeSceneFile(scene);
  ASSERT_NE(sf.find("-0"), std::string::npos);
  DiagnosticList diagnostics;
  std::optional<GltfFiles> files = writeGltf(scene, {}, false, diagnostics);
  ASSERT_TRUE(files.has_value());
  nlohmann::json doc = nlohmann::json::parse(files->main);
  auto asJavaScript = [](auto& self, nlohmann::json& j) -> void {
    if (j.is_number_float() && j.get<double>() == 0.0) j = 0;
    if (j.is_structured()) {
      for (nlohmann::json& e : j) self(self, e);
    }
  };
  asJavaScript(asJavaScript, doc);
  ReadResult back = parseScene(doc.dump(), "rewritten.gltf");
  ASSERT_TRUE(back.ok()) << firstError(back.diagnostics);
  EXPECT_EQ(writeSceneFile(back.scene), sf);
}

}  // namespace
}  // namespace scene
