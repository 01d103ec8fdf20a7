#include "tools/common/output_location.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace tools {
namespace {

namespace fs = std::filesystem;

TEST(OutputLocation, FollowsLinksAsAWriteWould) {
  fs::path dir = fs::temp_directory_path() / ("sflinks-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "in");
  fs::create_symlink("../elsewhere/x.ppm", dir / "in" / "dangling.ppm");
  fs::create_symlink("dangling.ppm", dir / "in" / "chain.ppm");
  fs::create_symlink("sub/x.ppm", dir / "in" / "inside.ppm");
  fs::path base = fs::canonical(dir);
  EXPECT_EQ(scene::followLinks(dir / "in" / "chain.ppm"), base / "elsewhere" / "x.ppm");
  EXPECT_EQ(scene::followLinks(dir / "in" / "plain.ppm"), base / "in" / "plain.ppm");
  EXPECT_FALSE(scene::outputStaysInFolder(dir / "in", "chain.ppm"));
  EXPECT_FALSE(scene::outputStaysInFolder(dir / "in", "dangling.ppm"));
  EXPECT_TRUE(scene::outputStaysInFolder(dir / "in", "inside.ppm"));
  EXPECT_TRUE(scene::outputStaysInFolder(dir / "in", "plain.ppm"));
  fs::remove_all(dir);
}

// A loop of links that stays inside the folder is a loop, not a way out;
// one that leaves it on the way is a way out, wherever it loops.
TEST(OutputLocation, TellsALoopInsideFromAWayOut) {
  fs::path dir = fs::temp_directory_path() / ("sfloops-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "in");
  fs::create_directories(dir / "out");
  fs::create_symlink("b.ppm", dir / "in" / "a.ppm");
  fs::create_symlink("a.ppm", dir / "in" / "b.ppm");
  fs::create_symlink("self.ppm", dir / "in" / "self.ppm");
  fs::create_directory_symlink("d", dir / "in" / "d");  // a folder that is a loop
  fs::create_symlink("../out/c.ppm", dir / "in" / "leaves.ppm");
  fs::create_symlink("d.ppm", dir / "out" / "c.ppm");
  fs::create_symlink("c.ppm", dir / "out" / "d.ppm");
  using scene::OutputPlace;
  EXPECT_EQ(scene::outputPlace(dir / "in", "a.ppm"), OutputPlace::LinkLoop);
  EXPECT_EQ(scene::outputPlace(dir / "in", "self.ppm"), OutputPlace::LinkLoop);
  EXPECT_EQ(scene::outputPlace(dir / "in", "d/x.ppm"), OutputPlace::LinkLoop);
  EXPECT_EQ(scene::outputPlace(dir / "in", "leaves.ppm"), OutputPlace::Outside);
  EXPECT_EQ(scene::outputPlace(dir / "in", "plain.ppm"), OutputPlace::Inside);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tools
