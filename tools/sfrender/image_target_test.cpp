#include "tools/sfrender/image_target.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tools/tool_test_support.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

// A valid instruction file whose OUTPUT_FILE is `outputFile`.
std::string instructionsWriting(const std::string& outputFile) {
  return "OUTPUT_FILE " + outputFile +
         "\n\nSTART CAMERA\n  LOCATION 4 3 6\n  LOOK_AT 0 0.5 0\nEND CAMERA\n\n"
         "START LIGHT\n  LOCATION 5 8 5\n  COLOUR 1 1 1\nEND LIGHT\n\n"
         "START OBJECT PLANE\n  START MATERIAL\n    COLOUR 0.8 0.8 0.8\n  END MATERIAL\n"
         "END OBJECT\n";
}

TEST(ImageTarget, EachSceneOwnImageReadAhead) {
  fs::path root = freshTestFolder("image-target");
  fs::create_directories(root / "in/sub");
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(root / name) << text;
    return (root / name).string();
  };
  std::string scene = write("in/a.sf", kValidScene);
  std::string instructions = write("in/i.txt", instructionsWriting("sub/pic.png"));
  std::string escapes = write("in/e.txt", instructionsWriting("../pic.png"));
  std::string noImage = write("in/n.txt", instructionsWriting("pic.sf"));
  std::string invalid = write("in/bad.txt", "this is no scene\n");
  std::string missing = (root / "in/missing.sf").string();
  std::vector<std::optional<fs::path>> targets = readAheadImageTargets(
      {scene, instructions, escapes, noImage, invalid, missing}, scene::ReadOptions{});
  ASSERT_EQ(targets.size(), 6u);
  EXPECT_EQ(targets[0], fs::path("a.ppm"));
  EXPECT_EQ(targets[1], root / "in/sub/pic.png");
  // Those whose render writes nothing: refused there, with the reason.
  for (std::size_t i = 2; i < targets.size(); ++i) EXPECT_FALSE(targets[i]) << i;
}

TEST(ImageTarget, TheDefaultOfOneScene) {
  EXPECT_EQ(defaultImageTarget("x/s.sf", std::nullopt).path, fs::path("s.ppm"));
  EXPECT_FALSE(defaultImageTarget("x/s.sf", std::nullopt).fromOutputFile);
  EXPECT_EQ(defaultImageTarget("x/i.txt", "p.png").path, fs::path("x/p.png"));
  EXPECT_TRUE(defaultImageTarget("x/i.txt", "p.png").fromOutputFile);
  EXPECT_EQ(defaultImageTarget("-", "p.png").path, fs::path("p.png"));
  EXPECT_EQ(defaultImageTarget("", "default-scene.ppm").path, fs::path("default-scene.ppm"));
}

}  // namespace
}  // namespace tools
