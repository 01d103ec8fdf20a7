// sfconvert end to end, in-process with its streams captured: each format
// written and read back, what a conversion loses, and nothing written over
// its input or from an invalid one.
#include "tools/sfconvert/sfconvert.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tools/common/exit_code.h"
#include "tools/sfcheck/sfcheck.h"
#include "tools/tool_test_support.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

TEST_F(ToolTest, SfconvertInstructionsToSceneFileReportsLosses) {
  std::string in = write("in.txt", kInstructions);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("out.sf")}), 0);
  EXPECT_NE(err_.str().find("warning: AMBIENT 0.15 of CUBE object 1 is dropped"),
            std::string::npos);
  EXPECT_EQ(read("out.sf").substr(0, 7), "CAMERA\n");
  // --no-loss: an error, and no file at all.
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "--no-loss", in, path("strict.sf")}), 1);
  EXPECT_NE(err_.str().find("error: AMBIENT 0.15"), std::string::npos);
  EXPECT_EQ(files(), (std::vector<std::string>{"in.txt", "out.sf"}));
}

TEST_F(ToolTest, SfconvertRoundTripsThroughBothFormats) {
  std::string in = write("in.sf", kValidScene);
  ASSERT_EQ(run(runSfconvert, {"sfconvert", in, path("a.txt")}), 0) << err_.str();
  EXPECT_NE(read("a.txt").find("OUTPUT_FILE a.ppm\n"), std::string::npos);
  ASSERT_EQ(run(runSfconvert, {"sfconvert", path("a.txt"), path("b.sf")}), 0) << err_.str();
  ASSERT_EQ(run(runSfconvert, {"sfconvert", in, path("n.sf")}), 0) << err_.str();
  EXPECT_EQ(read("b.sf"), read("n.sf"));
}

TEST_F(ToolTest, SfconvertNeverWritesOverItsInput) {
  std::string in = write("scene.sf", kValidScene);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, in}), toInt(ExitCode::InvalidInput));
  EXPECT_EQ(read("scene.sf"), kValidScene);
  fs::create_symlink(in, dir_ / "alias.sf");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("alias.sf")}), 1);
  EXPECT_EQ(read("scene.sf"), kValidScene);
}

TEST_F(ToolTest, SfconvertOutputFormatAndStdout) {
  std::string in = write("scene.sf", kValidScene);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("out.xyz")}), toInt(ExitCode::Usage));
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("out.xyz"), "--to", "instructions"}), 0);
  EXPECT_EQ(read("out.xyz").substr(0, 12), "OUTPUT_FILE ");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, "-", "--to", "sf"}), 0);
  EXPECT_EQ(out_.str().substr(0, 7), "CAMERA\n");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, "-"}), toInt(ExitCode::Usage));
}

TEST_F(ToolTest, SfconvertRepairsTransposedFiles) {
  std::string in = write("t.sf",
                         "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 5 1\n"
                         "CUBE\n1 1 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n2 3 4 1\n");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("bad.sf")}), 1);
  EXPECT_NE(err_.str().find("'sfconvert --transpose-matrices' repairs such files"),
            std::string::npos);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "--transpose-matrices", in, path("fixed.sf")}), 0);
  EXPECT_EQ(read("fixed.sf"),
            "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n"
            "\nCUBE\n1 1 1\n1 0 0 2\n0 1 0 3\n0 0 1 4\n0 0 0 1\n");
}

TEST_F(ToolTest, SfconvertApproximatesOnlyWhenAsked) {
  std::string in = write("shear.sf",
                         "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n"
                         "CUBE\n1 1 1\n1 0.5 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("s.txt")}), 1);
  EXPECT_NE(err_.str().find("[matrix-not-expressible]"), std::string::npos);
  EXPECT_FALSE(fs::exists(path("s.txt")));
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "--approximate", in, path("s.txt")}), 0);
  EXPECT_NE(err_.str().find("note: m01 moves from 0.5 to"), std::string::npos) << err_.str();
  EXPECT_TRUE(fs::exists(path("s.txt")));
}

TEST_F(ToolTest, SfconvertRejectsInvalidInputAndWritesNothing) {
  std::string in = write("bad.sf", "CAMERA\n0 0 0\n");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("out.sf")}), 1);
  EXPECT_NE(err_.str().find("[truncated-record]"), std::string::npos);
  EXPECT_EQ(files(), std::vector<std::string>{"bad.sf"});
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("no/such/folder/out.sf")}), 1);
  std::string good = write("good.sf", kValidScene);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", good, path("no/such/folder/out.sf")}),
            toInt(ExitCode::IoError));
}

TEST_F(ToolTest, SfconvertWritesAndReadsGltfAndGlb) {
  std::string in = write("scene.sf", kValidScene);
  ASSERT_EQ(run(runSfconvert, {"sfconvert", in, path("a.gltf")}), 0) << err_.str();
  EXPECT_EQ(read("a.gltf").substr(0, 1), "{");
  ASSERT_EQ(run(runSfconvert, {"sfconvert", in, path("b.glb"), "--fov", "45", "--width", "640",
                               "--height", "480", "--tessellation", "8"}),
            0)
      << err_.str();
  EXPECT_EQ(read("b.glb").substr(0, 4), "glTF");
  ASSERT_EQ(run(runSfconvert, {"sfconvert", in, path("normal.sf")}), 0);
  for (const char* name : {"a.gltf", "b.glb"}) {
    // -v: the camera's note, checked below.
    ASSERT_EQ(run(runSfconvert, {"sfconvert", "-v", path(name), path(std::string(name) + ".sf")}),
              0)
        << err_.str();
    EXPECT_EQ(read(std::string(name) + ".sf"), read("normal.sf")) << name;
  }
  EXPECT_NE(err_.str().find("render with sfrender --fov 45"), std::string::npos) << err_.str();
  // --to picks the format whatever the name.
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("c.bin"), "--to", "glb"}), 0);
  EXPECT_EQ(read("c.bin").substr(0, 4), "glTF");
}

TEST_F(ToolTest, SfconvertWritesAnExternalBufferBesideTheGltf) {
  std::string in = write("scene.sf", kValidScene);
  ASSERT_EQ(run(runSfconvert, {"sfconvert", in, path("ext.gltf"), "--external-buffers"}), 0)
      << err_.str();
  EXPECT_EQ(files(), (std::vector<std::string>{"ext.bin", "ext.gltf", "scene.sf"}));
  EXPECT_NE(read("ext.gltf").find("\"uri\": \"ext.bin\""), std::string::npos);
  ASSERT_EQ(run(runSfconvert, {"sfconvert", path("ext.gltf"), path("back.sf")}), 0) << err_.str();
  // Options that make no sense are usage errors.
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("x.glb"), "--external-buffers"}),
            toInt(ExitCode::Usage));
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("x.gltf"), "--fov", "180"}),
            toInt(ExitCode::Usage));
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("x.gltf"), "--tessellation", "2"}),
            toInt(ExitCode::Usage));
}

TEST_F(ToolTest, SfconvertRejectsHostileGltfAndWritesNothing) {
  std::string escape =
      write("escape.gltf",
            R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":4,"uri":"../../etc/passwd"}]})");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", escape, path("out.sf")}), 1);
  EXPECT_NE(err_.str().find("[gltf-external-file]"), std::string::npos) << err_.str();
  std::string glb = write("cut.glb", std::string("glTF\x02\0\0\0\x40\0\0\0", 12));
  EXPECT_EQ(run(runSfconvert, {"sfconvert", glb, path("out.sf")}), 1);
  EXPECT_NE(err_.str().find("[gltf-invalid-glb]"), std::string::npos) << err_.str();
  EXPECT_EQ(files(), (std::vector<std::string>{"cut.glb", "escape.gltf"}));
}

TEST_F(ToolTest, SfconvertWritesAndReadsPovRay) {
  std::string in = write("in.sf", kValidScene);
  ASSERT_EQ(run(runSfconvert, {"sfconvert", in, path("a.pov"), "--fov", "45", "--width", "320",
                               "--height", "200"}),
            0)
      << err_.str();
  std::string pov = read("a.pov");
  EXPECT_NE(pov.find("#version 3.7;"), std::string::npos);
  EXPECT_NE(pov.find("fov 45 width 320 height 200"), std::string::npos);
  // Back to a scene file: the same bytes, and the view to render it with.
  ASSERT_EQ(run(runSfconvert, {"sfconvert", path("a.pov"), path("b.sf")}), 0) << err_.str();
  ASSERT_EQ(run(runSfconvert, {"sfconvert", in, path("n.sf")}), 0) << err_.str();
  EXPECT_EQ(read("b.sf"), read("n.sf"));
  ASSERT_EQ(run(runSfconvert, {"sfconvert", "-v", path("a.pov"), path("c.sf")}), 0);
  EXPECT_NE(err_.str().find("hint: render with sfrender --fov 45 --width 320 --height 200"),
            std::string::npos)
      << err_.str();
  // --to pov and --flat.
  ASSERT_EQ(run(runSfconvert, {"sfconvert", in, "-", "--to", "pov", "--flat"}), 0);
  EXPECT_EQ(out_.str().find("light_source"), std::string::npos);
  EXPECT_NE(out_.str().find("finish { ambient 1 diffuse 0"), std::string::npos);
}

TEST_F(ToolTest, SfconvertSkipsUnsupportedPovRayOnlyWhenAsked) {
  std::string in = write("in.pov",
                         "#include \"colors.inc\"\ncamera { location <0, 1, -5> look_at 0 }\n"
                         "torus { 1, 0.2 pigment { Red } }\nsphere { 0, 1 pigment { Red } }\n");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("a.sf")}), toInt(ExitCode::InvalidInput));
  EXPECT_NE(err_.str().find(":3:1: error: 'torus' is not supported (line 3) [pov-unsupported]"),
            std::string::npos)
      << err_.str();
  EXPECT_FALSE(fs::exists(path("a.sf")));
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("a.sf"), "--skip-unsupported"}), 0)
      << err_.str();
  EXPECT_NE(read("a.sf").find("SPHERE\n1 0 0\n"), std::string::npos);
  // A file named .pov with nothing in it is an empty POV-Ray scene.
  std::string empty = write("empty.pov", "// nothing yet\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "-v", empty}), 0) << err_.str();
  EXPECT_NE(err_.str().find("POV-Ray's default camera"), std::string::npos) << err_.str();
}

}  // namespace
}  // namespace tools
