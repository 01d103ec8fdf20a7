#include "tools/sfrender/image_target.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tools/tool_test_support.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

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
  EXPECT_EQ(targets[0], fs::path("a.png"));
  EXPECT_EQ(targets[1], root / "in/sub/pic.png");
  // Those whose render writes nothing: refused there, with the reason.
  for (std::size_t i = 2; i < targets.size(); ++i) EXPECT_FALSE(targets[i]) << i;
}

TEST(ImageTarget, TheDefaultOfOneScene) {
  EXPECT_EQ(defaultImageTarget("x/s.sf", std::nullopt).path, fs::path("s.png"));
  EXPECT_FALSE(defaultImageTarget("x/s.sf", std::nullopt).fromOutputFile);
  EXPECT_EQ(defaultImageTarget("x/i.txt", "p.png").path, fs::path("x/p.png"));
  EXPECT_TRUE(defaultImageTarget("x/i.txt", "p.png").fromOutputFile);
  EXPECT_EQ(defaultImageTarget("-", "p.png").path, fs::path("p.png"));
  EXPECT_EQ(defaultImageTarget("", "default-scene.ppm").path, fs::path("default-scene.ppm"));
}

}  // namespace
}  // namespace tools
