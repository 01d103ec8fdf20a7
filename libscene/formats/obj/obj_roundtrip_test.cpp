// Round trips through OBJ: what the writer writes, the reader gives back bit
// for bit from its comments, for the corpus and for seeded random scenes,
// with the MTL beside it or without one.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "libscene/formats/obj/obj_reader.h"
#include "libscene/formats/obj/obj_writer.h"
#include "libscene/formats/sf/sf_writer.h"
#include "libscene/testing/random_cases.h"
#include "libscene/testing/random_scenes.h"
#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

namespace fs = std::filesystem;

std::string allOf(const DiagnosticList& list) {
  std::string text;
  for (const Diagnostic& d : list.items()) {
    text += std::string(codeName(d.code)) + ": " + d.message + "\n";
  }
  return text;
}

// The scene through an OBJ and its MTL, written to `folder` when given.
ReadResult throughObj(const Scene& scene, const std::optional<fs::path>& folder,
                      DiagnosticList& written) {
  ConversionOptions options;
  if (folder) options.obj.materialLibrary = "scene.mtl";
  std::optional<ConvertedFiles> files = writeObj(scene, options, written);
  if (!files) return ReadResult{Scene{}, DiagnosticList{}};
  if (folder) {
    fs::create_directories(*folder);
    std::ofstream(*folder / "scene.mtl", std::ios::binary) << files->sidecar;
  }
  return parseObj(files->main, "scene.obj", folder);
}

TEST(ObjRoundTrip, EveryValidCorpusFileComesBackExactly) {
  fs::path folder = fs::temp_directory_path() / "obj-roundtrip-corpus";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SCENE_TESTDATA_DIR) / "valid")) {
    std::string ext = entry.path().extension().string();
    if (ext != ".sf" && ext != ".txt") continue;
    ReadResult original = parseScene(testing::readText(entry.path()), entry.path().string());
    ASSERT_TRUE(original.ok()) << entry.path();
    for (bool withMtl : {true, false}) {
      DiagnosticList written;
      ReadResult back =
          throughObj(original.scene, withMtl ? std::optional(folder) : std::nullopt, written);
      ASSERT_TRUE(back.ok()) << entry.path() << "\n" << allOf(written) << allOf(back.diagnostics);
      EXPECT_EQ(back.scene, original.scene) << entry.path() << allOf(back.diagnostics);
      EXPECT_EQ(writeSceneFile(back.scene), writeSceneFile(original.scene)) << entry.path();
      EXPECT_TRUE(testing::withCode(back.diagnostics, DiagnosticCode::ObjCommentStale).empty())
          << entry.path() << allOf(back.diagnostics);
    }
    ++files;
  }
  fs::remove_all(folder);
  EXPECT_GE(files, 50);
}

TEST(ObjRoundTrip, RandomScenesComeBackBitForBit) {
  fs::path folder = fs::temp_directory_path() / "obj-roundtrip-random";
  testing::RandomSceneGenerator random(20261206);
  int checked = 0;
  for (int i = 0; checked < testing::randomCases(300); ++i) {
    ASSERT_LT(i, testing::randomCases(1000)) << "too many random scenes were invalid";
    Scene scene = random.scene(i % 2 == 0);
    if (!parseScene(writeSceneFile(scene), "random.sf").ok()) continue;
    DiagnosticList written;
    ReadResult back = throughObj(scene, i % 3 ? std::optional(folder) : std::nullopt, written);
    if (written.hasErrors()) {
      // Only a mesh whose vertices overflow in world space is refused.
      ASSERT_FALSE(testing::withCode(written, DiagnosticCode::ValueNotFinite).empty())
          << allOf(written);
      continue;
    }
    ASSERT_TRUE(back.ok()) << "scene " << i << "\n" << allOf(back.diagnostics);
    ASSERT_EQ(testing::numberBits(back.scene), testing::numberBits(scene))
        << "scene " << i << "\n"
        << allOf(back.diagnostics) << writeSceneFile(scene);
    ASSERT_EQ(back.scene, scene) << "scene " << i;
    ++checked;
  }
  fs::remove_all(folder);
}

}  // namespace
}  // namespace scene
