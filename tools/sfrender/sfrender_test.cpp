// sfrender end to end, in-process with its streams captured: the image a
// run names and writes, what it refuses, its statistics, its limits.
#include "tools/sfrender/sfrender.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "renderer/render.h"
#include "tools/common/exit_code.h"
#include "tools/sfcheck/sfcheck.h"
#include "tools/sfconvert/sfconvert.h"
#include "tools/tool_test_support.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

// The manual's three ways of running the renderer: no file, a scene file,
// an instruction file.
TEST_F(ToolTest, SfrenderRendersTheDefaultSceneWithoutInput) {
  std::string out = path("default.ppm");
  EXPECT_EQ(run(sfrender, {"sfrender", "-o", out, "--width", "32", "--height", "24"}), 0)
      << err_.str();
  EXPECT_NE(err_.str().find("sfrender: wrote " + out + " (32x24, the default scene)"),
            std::string::npos);
  std::string image = read("default.ppm");
  EXPECT_EQ(image.substr(0, 13), "P6\n32 24\n255\n");
  EXPECT_EQ(image.size(), std::string("P6\n32 24\n255\n").size() + 32 * 24 * 3);
}

TEST_F(ToolTest, SfrenderNamesASceneFilesImageAfterIt) {
  std::string in = write("ball.sf", kValidScene);
  fs::path before = fs::current_path();
  fs::current_path(dir_);
  int status = run(sfrender, {"sfrender", "ball.sf", "--width", "16", "--height", "12"});
  fs::current_path(before);
  EXPECT_EQ(status, 0) << err_.str();
  // A PNG, as POV-Ray writes, in the current folder.
  EXPECT_EQ(read("ball.png").substr(0, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_NE(err_.str().find("sfrender: wrote ball.png (16x12)"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "ball.ppm"));
}

// The OUTPUT_FILE a glTF file carries from an instruction file, for its
// round trip, does not name the image: only an instruction file does.
TEST_F(ToolTest, SfrenderNamesOnlyAnInstructionFilesImageByItsOutputFile) {
  std::string txt = write("scene.txt", instructionsWriting("chosen.ppm"));
  ASSERT_EQ(run(runSfconvert, {"sfconvert", txt, path("scene.gltf")}), 0) << err_.str();
  fs::path before = fs::current_path();
  fs::current_path(dir_);
  int fromGltf = run(sfrender, {"sfrender", "scene.gltf", "--width", "16", "--height", "12"});
  int fromTxt = run(sfrender, {"sfrender", "scene.txt", "--width", "16", "--height", "12"});
  fs::current_path(before);
  EXPECT_EQ(fromGltf, 0) << err_.str();
  EXPECT_EQ(fromTxt, 0) << err_.str();
  EXPECT_EQ(read("scene.png").substr(0, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_EQ(read("chosen.ppm").substr(0, 2), "P6");
}

// What POV-Ray has and the subset does not fails the render, unless
// --skip-unsupported leaves it out (with a warning) and renders the rest.
TEST_F(ToolTest, SfrenderSkipsUnsupportedPovRayOnlyWhenAsked) {
  std::string in = write("in.pov",
                         "camera { location <0, 1, -5> look_at 0 }\n"
                         "light_source { <4, 8, -6> color rgb 1 }\n"
                         "torus { 1, 0.2 pigment { color rgb 1 } }\n"
                         "sphere { 0, 1 pigment { color rgb <1, 0, 0> } }\n");
  std::vector<std::string> args = {"sfrender", in, "-o", path("a.png"), "--width", "16"};
  EXPECT_EQ(run(sfrender, args), toInt(ExitCode::InvalidInput));
  EXPECT_NE(err_.str().find("error: 'torus' is not supported"), std::string::npos) << err_.str();
  EXPECT_NE(err_.str().find("--skip-unsupported"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(path("a.png")));
  args.push_back("--skip-unsupported");
  EXPECT_EQ(run(sfrender, args), 0) << err_.str();
  EXPECT_NE(err_.str().find("warning: 'torus' is not supported"), std::string::npos) << err_.str();
  EXPECT_TRUE(fs::exists(path("a.png")));
}

TEST_F(ToolTest, SfrenderHonoursAndConfinesOutputFile) {
  fs::create_directory(dir_ / "scenes");
  std::string in = write("scenes/i.txt", kInstructions);
  EXPECT_EQ(run(sfrender, {"sfrender", in, "--width", "16", "--height", "12", "--quiet"}), 0)
      << err_.str();
  EXPECT_TRUE(fs::exists(dir_ / "scenes" / "pic.ppm"));  // beside the instruction file
  EXPECT_EQ(err_.str(), "");

  std::string escaping = kInstructions;
  escaping.replace(escaping.find("pic.ppm"), 7, "../escaped.ppm");
  std::string bad = write("scenes/e.txt", escaping);
  EXPECT_EQ(run(sfrender, {"sfrender", bad, "--width", "16", "--height", "12"}),
            toInt(ExitCode::InvalidInput));
  EXPECT_NE(err_.str().find("error: OUTPUT_FILE '../escaped.ppm' leaves the instruction file's "
                            "folder [output-file-escapes]"),
            std::string::npos)
      << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "escaped.ppm"));
  // -o names the output, and then the user has chosen.
  EXPECT_EQ(
      run(sfrender, {"sfrender", bad, "-o", path("chosen.png"), "--width", "16", "--height", "12"}),
      0);
  EXPECT_TRUE(fs::exists(dir_ / "chosen.png"));
}

TEST_F(ToolTest, SfrenderRefusesBadRequests) {
  std::string in = write("s.sf", kValidScene);
  EXPECT_EQ(run(sfrender, {"sfrender", in, "-o", path("x.unknownformat")}), toInt(ExitCode::Usage));
  EXPECT_EQ(run(sfrender, {"sfrender", in, "--width", "0"}), toInt(ExitCode::Usage));
  EXPECT_EQ(run(sfrender, {"sfrender", in, "--spp", "-1"}), toInt(ExitCode::Usage));
  EXPECT_EQ(run(sfrender, {"sfrender", path("missing.sf")}), toInt(ExitCode::IoError));
  std::string invalid = write("bad.sf", "CAMERA\n");
  EXPECT_EQ(run(sfrender, {"sfrender", invalid, "-o", path("bad.ppm")}),
            toInt(ExitCode::InvalidInput));
  EXPECT_FALSE(fs::exists(dir_ / "bad.ppm"));
  // A scene file may have any name, an image's among them: never written over.
  std::string odd = write("scene.ppm", kValidScene);
  EXPECT_EQ(run(sfrender, {"sfrender", odd, "-o", odd}), toInt(ExitCode::InvalidInput));
  EXPECT_EQ(read("scene.ppm"), kValidScene);
  EXPECT_EQ(run(sfrender, {"sfrender", in, "-o", path("n/o/x.ppm")}), toInt(ExitCode::IoError));
}

TEST_F(ToolTest, SfrenderStatsAndFloatImages) {
  std::string in = write("s.sf", kValidScene);
  EXPECT_EQ(run(sfrender, {"sfrender", in, "-o", path("s.exr"), "--width", "8", "--height", "6",
                           "--stats", "--spp", "4"}),
            0)
      << err_.str();
  EXPECT_NE(err_.str().find("8x6, 4 spp, depth 5:"), std::string::npos) << err_.str();
  EXPECT_NE(err_.str().find("(192 primary,"), std::string::npos) << err_.str();
  EXPECT_TRUE(fs::exists(dir_ / "s.exr"));
  EXPECT_EQ(files(), (std::vector<std::string>{"s.exr", "s.sf"}));  // no temporary left
}

// A batch on the GPU renders its scenes through one device it opens once:
// each image is the one its scene gives rendered alone.
TEST_F(ToolTest, SfrenderBatchOnTheGpuGivesEachSceneItsOwnImage) {
  render::GpuProbe probe = render::probeGpu();
  if (!probe.available) GTEST_SKIP() << "no Vulkan device: " << probe.reason;
  std::vector<std::string> scenes = {write("a.sf", kValidScene), write("b.txt", kInstructions),
                                     write("c.sf", kValidScene)};
  std::vector<std::string> size = {"--device", "gpu", "--width", "24", "--height", "18"};
  std::vector<std::string> batch = {"sfrender"};
  batch.insert(batch.end(), scenes.begin(), scenes.end());
  batch.insert(batch.end(), size.begin(), size.end());
  batch.insert(batch.end(), {"-o", path("batch-{stem}.ppm"), "--verbose"});
  ASSERT_EQ(run(sfrender, batch), 0) << err_.str();
  // The device is opened once, by the first scene.
  std::string said = err_.str();
  std::size_t opened = said.find(" for the scenes on the gpu");
  EXPECT_NE(opened, std::string::npos) << said;
  EXPECT_EQ(said.find(" for the scenes on the gpu", opened + 1), std::string::npos) << said;
  const std::vector<std::string> stems = {"a", "b", "c"};
  for (std::size_t k = 0; k < stems.size(); ++k) {
    std::vector<std::string> alone = {"sfrender", scenes[k], "-o",
                                      path("alone-" + stems[k] + ".ppm")};
    alone.insert(alone.end(), size.begin(), size.end());
    ASSERT_EQ(run(sfrender, alone), 0) << err_.str();
    std::string image = read("batch-" + stems[k] + ".ppm");
    EXPECT_EQ(image.size(), std::string("P6\n24 18\n255\n").size() + 24 * 18 * 3) << stems[k];
    EXPECT_EQ(image, read("alone-" + stems[k] + ".ppm")) << stems[k];
  }
}

TEST_F(ToolTest, SfrenderSettingsAboveTheirLimitsAreUsageErrorsNamingTheFlag) {
  std::string out = path("a.ppm");
  EXPECT_EQ(run(sfrender, {"sfrender", "-o", out, "--width", "8192", "--height", "8193"}),
            toInt(ExitCode::Usage));
  EXPECT_EQ(
      err_.str(),
      "sfrender: error: --width 8192 and --height 8193 make 67,117,056 pixels, more than the limit "
      "of 67,108,864; raise it with --max-pixels\n");
  EXPECT_EQ(run(sfrender, {"sfrender", "-o", out, "--spp", "1025"}), toInt(ExitCode::Usage));
  EXPECT_EQ(
      err_.str(),
      "sfrender: error: --spp 1025 is more than the limit of 1024 samples per pixel; raise it with "
      "--max-spp\n");
  EXPECT_EQ(run(sfrender, {"sfrender", "-o", out, "--depth", "65"}), toInt(ExitCode::Usage));
  EXPECT_EQ(err_.str(),
            "sfrender: error: --depth 65 is more than the limit of 64 bounces; raise it with "
            "--max-depth\n");
  EXPECT_FALSE(fs::exists(out));
  // Lowered limits hold too, and raised ones let the render through.
  EXPECT_EQ(
      run(sfrender, {"sfrender", "-o", out, "--width", "8", "--height", "8", "--max-pixels", "63"}),
      toInt(ExitCode::Usage));
  // A scene with nothing reflective or transparent: bounces cost nothing.
  std::string matte = write("matte.sf", kValidScene);
  EXPECT_EQ(
      run(sfrender, {"sfrender", matte, "-o", out, "--width", "2", "--height", "2", "--spp", "2000",
                     "--max-spp", "2000", "--depth", "70", "--max-depth", "70", "--quiet"}),
      0)
      << err_.str();
  EXPECT_TRUE(fs::exists(out));
}

TEST_F(ToolTest, SfrenderRefusesARenderThatDoesNotFitInMemory) {
  std::string out = path("a.ppm");
  std::vector<std::string> args = {"sfrender", "-o", out, "--width", "640", "--height", "480"};
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  auto oneMebibyte = [] { return std::optional<std::uint64_t>(std::uint64_t{1} << 20); };
  std::istringstream none;
  EXPECT_EQ(runSfrender(static_cast<int>(argv.size()), argv.data(), ToolStreams(none, out_, err_),
                        oneMebibyte),
            toInt(ExitCode::OutOfResources));
  EXPECT_NE(err_.str().find("sfrender: error: the render needs about "), std::string::npos)
      << err_.str();
  EXPECT_NE(err_.str().find("(image 11 MiB, scene "), std::string::npos) << err_.str();
  EXPECT_NE(err_.str().find("but only 1 MiB of memory is available"), std::string::npos)
      << err_.str();
  EXPECT_FALSE(fs::exists(out));
  // Enough memory, or none known: it renders.
  args = {"sfrender", "-o", out, "--width", "16", "--height", "12", "--quiet"};
  argv.clear();
  for (const std::string& a : args) argv.push_back(a.c_str());
  EXPECT_EQ(runSfrender(static_cast<int>(argv.size()), argv.data(), ToolStreams(none, out_, err_),
                        oneMebibyte),
            0)
      << err_.str();
  auto unknown = [] { return std::optional<std::uint64_t>(); };
  EXPECT_EQ(runSfrender(static_cast<int>(argv.size()), argv.data(), ToolStreams(none, out_, err_),
                        unknown),
            0);
}

// A scene file of many windows whose records cannot fit is refused once its
// first window has told how many objects it holds, not after it is read.
TEST_F(ToolTest, SfrenderRefusesAStreamedSceneThatCannotFitBeforeReadingItAll) {
  std::string text = kValidScene;
  for (int i = 0; i < 80000; ++i) {
    text += "SPHERE\n1 0 0\n1 0 0 " + std::to_string(i % 100) + "\n0 1 0 0\n0 0 1 " +
            std::to_string(i / 100) + "\n0 0 0 1\n";
  }
  std::string scene = write("many.sf", text);
  std::string out = path("many.ppm");
  std::vector<std::string> args = {"sfrender", scene, "-o", out,         "--width", "4",
                                   "--height", "4",   "-v", "--threads", "1"};
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  auto eightMebibytes = [] { return std::optional<std::uint64_t>(std::uint64_t{8} << 20); };
  std::istringstream none;
  EXPECT_EQ(runSfrender(static_cast<int>(argv.size()), argv.data(), ToolStreams(none, out_, err_),
                        eightMebibytes),
            toInt(ExitCode::OutOfResources));
  EXPECT_NE(err_.str().find("but only 8 MiB of memory is available"), std::string::npos)
      << err_.str();
  // The read stopped at its first window: it never said what it read.
  EXPECT_EQ(err_.str().find("sfrender: read "), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(ToolTest, AnOutputFileWithNoImageExtensionIsReportedWhereItStands) {
  for (std::string name : {"picture", "picture.xyz", "picture.txt"}) {
    std::string file = write("n.txt", "OUTPUT_FILE " + name + kInstructions.substr(19));
    std::string where = file + ":1:13: ";
    EXPECT_EQ(run(runSfcheck, {"sfcheck", file}), 0) << name;
    EXPECT_NE(err_.str().find(where + "warning: OUTPUT_FILE '" + name + "' "), std::string::npos)
        << err_.str();
    EXPECT_NE(err_.str().find("sfrender can write [output-file-format]"), std::string::npos)
        << err_.str();
    EXPECT_EQ(run(sfrender, {"sfrender", file, "--width", "8", "--height", "6"}),
              toInt(ExitCode::InvalidInput))
        << name;
    EXPECT_NE(err_.str().find(where + "error: OUTPUT_FILE '" + name + "' "), std::string::npos)
        << err_.str();
    EXPECT_NE(err_.str().find("  hint: name the image with .ppm, .png, .tif or .exr"),
              std::string::npos)
        << err_.str();
  }
  std::string upper = write("u.txt", "OUTPUT_FILE pic.PNG" + kInstructions.substr(19));
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--werror", upper}), 0) << err_.str();
  // Named with -o, the name is a usage error, as before.
  EXPECT_EQ(run(sfrender, {"sfrender", "-o", path("picture")}), toInt(ExitCode::Usage));
  EXPECT_EQ(files(), (std::vector<std::string>{"n.txt", "u.txt"}));
}

}  // namespace
}  // namespace tools
