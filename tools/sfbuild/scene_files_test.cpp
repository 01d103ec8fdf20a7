// Ctrl+S and Ctrl+O: the format by the extension, the materials of an
// instruction file kept, errors at their file:line:column, undo of an open.
#include "tools/sfbuild/scene_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "scenefile/convert.h"
#include "scenefile/read.h"

namespace sfbuild {
namespace {

struct FakeSceneFiles {
  std::map<std::string, std::string> files;
  FileSystem fs() {
    return {[this](const std::string& n) { return files.count(n) != 0; },
            [this](const std::string& n, const std::string& c) -> tools::MaybeFailure {
              files[n] = c;
              return std::nullopt;
            },
            [this](const std::string& n) -> tools::Outcome<std::string> {
              auto found = files.find(n);
              if (found == files.end()) {
                return tools::fileFailure(tools::ExitCode::IoError, n, "no such file");
              }
              return found->second;
            }};
  }
};

std::string asSceneFile(const scene::Scene& s) {
  scene::DiagnosticList losses;
  return scene::convertScene(s, scene::Format::SceneFile, {}, losses).value_or("");
}

// A sphere with a material of its own and a light.
BuilderState shinySphere() {
  BuilderState state = initialState(640, 480);
  FakeSceneFiles none;
  handleKey(state, '3', none.fs());
  handleKey(state, 'L', none.fs());
  scene::Material material = state.scene.objects[0].material;
  material.specular = 0.25;
  material.reflectivity = 0.5;
  setObjectMaterial(state, 0, material);
  return state;
}

TEST(SceneFiles, TheExtensionPicksTheFormatAndAnInstructionFileKeepsTheMaterials) {
  BuilderState state = shinySphere();
  FakeSceneFiles files;
  ASSERT_TRUE(saveSceneAs(state, "shiny.txt", files.fs())) << state.lastSave;
  EXPECT_EQ(state.lastSave, "saved shiny.txt");
  ASSERT_TRUE(saveSceneAs(state, "plain.sf", files.fs())) << state.lastSave;

  scene::ReadResult instructions = scene::parseScene(files.files["shiny.txt"], "shiny.txt");
  ASSERT_TRUE(instructions.ok());
  EXPECT_EQ(scene::detectFormat(files.files["shiny.txt"]), scene::Format::InstructionFile);
  ASSERT_EQ(instructions.scene.objects.size(), 1u);
  EXPECT_EQ(instructions.scene.objects[0].material.specular, 0.25);
  EXPECT_EQ(instructions.scene.objects[0].material.reflectivity, 0.5);
  EXPECT_EQ(instructions.scene.lights.size(), 1u);

  EXPECT_EQ(scene::detectFormat(files.files["plain.sf"]), scene::Format::SceneFile);
}

TEST(SceneFiles, RefusesANameWithoutAFormatAndAnotherFileThatExists) {
  BuilderState state = shinySphere();
  FakeSceneFiles files;
  files.files["taken.sf"] = "old";
  EXPECT_FALSE(saveSceneAs(state, "scene", files.fs()));
  EXPECT_NE(state.lastSave.find("the extension names no format (.sf, .txt"), std::string::npos)
      << state.lastSave;
  EXPECT_FALSE(saveSceneAs(state, "taken.sf", files.fs()));
  EXPECT_EQ(files.files["taken.sf"], "old");
  // The file saved with Ctrl+S may be saved again.
  ASSERT_TRUE(saveSceneAs(state, "mine.txt", files.fs()));
  EXPECT_TRUE(saveSceneAs(state, "mine.txt", files.fs())) << state.lastSave;
}

// An instruction file's OUTPUT_FILE is named after the file, in a form the
// reader takes back, as sfconvert names it.
TEST(SceneFiles, AnInstructionFileNamesItsImageAfterItselfInAFormThatReadsBack) {
  BuilderState state = shinySphere();
  FakeSceneFiles files;
  ASSERT_TRUE(saveSceneAs(state, "my scene.txt", files.fs())) << state.lastSave;
  EXPECT_EQ(files.files["my scene.txt"].substr(0, 25), "OUTPUT_FILE my_scene.ppm\n");
  EXPECT_TRUE(openSceneFile(state, "my scene.txt", files.fs())) << state.lastSave;
}

TEST(SceneFiles, OpeningIsAStepOfTheHistory) {
  BuilderState saved = shinySphere();
  FakeSceneFiles files;
  ASSERT_TRUE(saveSceneAs(saved, "shiny.txt", files.fs()));

  BuilderState state = initialState(640, 480);
  handleKey(state, '2', files.fs());
  scene::Scene before = state.scene;
  ASSERT_TRUE(openSceneFile(state, "shiny.txt", files.fs())) << state.lastSave;
  EXPECT_EQ(state.lastSave, "opened shiny.txt");
  // What was saved, and the OUTPUT_FILE every instruction file has.
  EXPECT_EQ(asSceneFile(state.scene), asSceneFile(saved.scene));
  ASSERT_EQ(state.scene.objects.size(), 1u);
  EXPECT_EQ(state.scene.objects[0].material, saved.scene.objects[0].material);
  EXPECT_FALSE(state.selection.has_value());
  scene::Scene opened = state.scene;
  undo(state);
  EXPECT_EQ(state.scene, before);
  redo(state);
  EXPECT_EQ(state.scene, opened);
}

TEST(SceneFiles, AnErrorIsToldAtItsPlaceAndTheSceneStays) {
  BuilderState state = shinySphere();
  scene::Scene before = state.scene;
  FakeSceneFiles files;
  // A good scene file, and a line that is no record after it.
  std::string text = asSceneFile(state.scene);
  std::string line = std::to_string(std::count(text.begin(), text.end(), '\n') + 1);
  files.files["broken.sf"] = text + "  BANANA\n";
  EXPECT_FALSE(openSceneFile(state, "broken.sf", files.fs()));
  EXPECT_EQ(state.lastSave.rfind("could not open broken.sf:" + line + ":3: ", 0), 0u)
      << state.lastSave;
  EXPECT_EQ(state.scene, before);
  EXPECT_FALSE(openSceneFile(state, "missing.sf", files.fs()));
  EXPECT_EQ(state.lastSave, "could not open missing.sf: no such file");
}

}  // namespace
}  // namespace sfbuild
