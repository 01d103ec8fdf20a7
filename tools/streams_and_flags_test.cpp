// The tools as command-line users expect them (docs/TOOLS.md): standard
// input and output as files, --no-clobber, -q and -v, what each says it
// wrote, the JSON report's shape, the exit codes and the limit flags.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tools/common/exit_code.h"
#include "tools/common/file_io.h"
#include "tools/common/input_limits.h"
#include "tools/sfcheck/sfcheck.h"
#include "tools/sfconvert/sfconvert.h"
#include "tools/tool_test_support.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

class StreamsAndFlags : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = freshTestFolder("sfflags"); }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& content) const {
    EXPECT_FALSE(writeFileAtomically(path(name), content));
    return path(name);
  }
  std::string read(const std::string& name) const {
    return readWholeFile(path(name)).valueOr("<missing>");
  }
  // A tool on `args` with `input` as its standard input; `streams` may make
  // standard output a terminal.
  template <typename Tool>
  int run(Tool tool, const std::vector<std::string>& args, const std::string& input = "",
          bool outIsTerminal = false) {
    out_.str("");
    err_.str("");
    std::istringstream in(input);
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    ToolStreams streams(in, out_, err_);
    streams.outIsTerminal = outIsTerminal;
    return tool(static_cast<int>(argv.size()), argv.data(), streams);
  }

  fs::path dir_;
  std::ostringstream out_;
  std::ostringstream err_;
};

const std::string kUnlit = "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n";

TEST_F(StreamsAndFlags, DashReadsStandardInputInEveryTool) {
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "-"}, kValidScene), 0) << err_.str();
  EXPECT_EQ(err_.str(), "sfcheck: 1 file checked, 0 errors, 0 warnings\n");
  // Diagnostics name it <stdin>.
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--format", "short", "-"}, kUnlit), 0);
  EXPECT_EQ(err_.str().substr(0, 46), "<stdin>:1:1: warning: scene has no LIGHT [no-l");
  // The format comes from the content.
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "-", "-", "--to", "pov"}, kValidScene), 0);
  EXPECT_NE(out_.str().find("sphere {"), std::string::npos);
  EXPECT_EQ(run(sfrender, {"sfrender", "-", "-o", path("in.ppm"), "--width", "8", "--height", "6"},
                kValidScene),
            0)
      << err_.str();
  EXPECT_TRUE(fs::exists(path("in.ppm")));
  // A scene from standard input has no name to give its image.
  EXPECT_EQ(run(sfrender, {"sfrender", "-"}, kValidScene), toInt(ExitCode::Usage));
  EXPECT_NE(err_.str().find("name it with -o FILE"), std::string::npos) << err_.str();
}

TEST_F(StreamsAndFlags, BinaryOutputToATerminalIsRefused) {
  std::string scene = write("a.sf", kValidScene);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", scene, "-", "--to", "glb"}, "", true),
            toInt(ExitCode::Usage));
  EXPECT_EQ(out_.str(), "");
  EXPECT_NE(err_.str().find("sfconvert: error: standard output is a terminal"), std::string::npos);
  // Text to a terminal is fine, and binary to a pipe.
  EXPECT_EQ(run(runSfconvert, {"sfconvert", scene, "-", "--to", "gltf"}, "", true), 0);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", scene, "-", "--to", "glb"}), 0);
  EXPECT_EQ(out_.str().substr(0, 4), "glTF");
  std::vector<std::string> toStdout = {"sfrender", scene, "-o",       "-",
                                       "--width",  "4",   "--height", "2"};
  EXPECT_EQ(run(sfrender, toStdout, "", true), toInt(ExitCode::Usage));
  EXPECT_EQ(out_.str(), "");
  EXPECT_EQ(run(sfrender, toStdout), 0) << err_.str();
  EXPECT_EQ(out_.str().substr(0, 11), "P6\n4 2\n255\n");
  EXPECT_EQ(out_.str().size(), 11u + 4 * 2 * 3);
}

TEST_F(StreamsAndFlags, NoClobberKeepsAnExistingOutput) {
  std::string scene = write("a.sf", kValidScene);
  write("out.sf", "old");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "--no-clobber", scene, path("out.sf")}),
            toInt(ExitCode::IoError));
  EXPECT_EQ(err_.str(), path("out.sf") + ": error: the file exists, and --no-clobber keeps it\n");
  EXPECT_EQ(read("out.sf"), "old");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "--no-clobber", scene, path("new.sf")}), 0);
  EXPECT_EQ(read("new.sf").substr(0, 7), "CAMERA\n");
  // A .gltf's buffer counts: nothing is written if either exists.
  write("model.bin", "old");
  EXPECT_EQ(run(runSfconvert,
                {"sfconvert", "--no-clobber", "--external-buffers", scene, path("model.gltf")}),
            toInt(ExitCode::IoError));
  EXPECT_FALSE(fs::exists(path("model.gltf")));
  // sfrender refuses before it renders.
  write("image.ppm", "old");
  EXPECT_EQ(run(sfrender, {"sfrender", "--no-clobber", scene, "-o", path("image.ppm")}),
            toInt(ExitCode::IoError));
  EXPECT_EQ(read("image.ppm"), "old");
  // Without the flag, outputs are replaced as ever.
  EXPECT_EQ(run(runSfconvert, {"sfconvert", scene, path("out.sf")}), 0);
  EXPECT_EQ(read("out.sf").substr(0, 7), "CAMERA\n");
}

TEST_F(StreamsAndFlags, NoClobberHoldsAtTheRenameItself) {
  // A file made after the check but before the rename is kept too.
  write("late.sf", "late");
  std::vector<FileToWrite> files = {{path("late.sf"), "new"}};
  EXPECT_TRUE(writeFilesAtomically(files, false));
  StagedFile staged;
  ASSERT_FALSE(staged.open(path("later.sf"), false));
  ASSERT_FALSE(staged.write("new"));
  write("later.sf", "made meanwhile");
  EXPECT_EQ(staged.commit(false).value_or(ToolFailure{}).message,
            "the file exists, and --no-clobber keeps it");
  EXPECT_EQ(read("later.sf"), "made meanwhile");
}

TEST_F(StreamsAndFlags, EveryToolSaysWhatItWroteUnlessQuiet) {
  std::string scene = write("a.sf", kValidScene);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", scene, path("b.pov")}), 0);
  EXPECT_EQ(err_.str(),
            "sfconvert: wrote " + path("b.pov") + " (a POV-Ray scene, 1 object, 1 light)\n");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "-q", scene, path("b.gltf")}), 0);
  EXPECT_EQ(err_.str(), "");
  EXPECT_EQ(
      run(sfrender, {"sfrender", scene, "-o", path("a.ppm"), "--width", "4", "--height", "3"}), 0);
  EXPECT_EQ(err_.str(), "sfrender: wrote " + path("a.ppm") + " (4x3)\n");
  EXPECT_EQ(run(sfrender, {"sfrender", "--quiet", scene, "-o", path("a.ppm")}), 0);
  EXPECT_EQ(err_.str(), "");
  // --stats is asked for: it prints even when quiet.
  EXPECT_EQ(run(sfrender, {"sfrender", "-q", "--stats", scene, "-o", path("a.ppm"), "--width", "4",
                           "--height", "3"}),
            0);
  EXPECT_NE(err_.str().find("million rays/s"), std::string::npos) << err_.str();
}

TEST_F(StreamsAndFlags, QuietPrintsOnlyErrorsAndVerboseTellsTheSteps) {
  std::string unlit = write("unlit.sf", kUnlit);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "-q", unlit}), 0);
  EXPECT_EQ(err_.str(), "");
  std::string bad = write("bad.sf", "sphere\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "-q", "--format", "short", bad}), 1);
  EXPECT_EQ(err_.str().rfind(bad + ":1:1: error: ", 0), 0u) << err_.str();
  EXPECT_EQ(err_.str().find("checked"), std::string::npos);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "-v", unlit}), 0);
  EXPECT_NE(err_.str().find("sfcheck: " + unlit + ": scene-file, 0 objects, 0 lights"),
            std::string::npos)
      << err_.str();
  std::string scene = write("a.sf", kValidScene);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "-v", scene, path("b.pov")}), 0);
  EXPECT_NE(err_.str().find("sfconvert: read " + scene + " (a scene file, 1 object, 1 light)"),
            std::string::npos)
      << err_.str();
  EXPECT_NE(err_.str().find("sfconvert: converting took "), std::string::npos) << err_.str();
  EXPECT_EQ(run(sfrender, {"sfrender", "-v", scene, "-o", path("a.ppm"), "--width", "4", "--height",
                           "3", "--threads", "1"}),
            0);
  EXPECT_NE(err_.str().find("rendering 4x3 at a vertical field of view of 60"), std::string::npos)
      << err_.str();
  EXPECT_NE(err_.str().find("sfrender: rendering took "), std::string::npos) << err_.str();
}

// Every file in sfcheck's JSON report has the same keys, whatever happened
// to it: read and checked, refused for its size, or unreadable.
TEST_F(StreamsAndFlags, SfcheckJsonKeepsItsShapeForEveryFile) {
  std::string good = write("good.sf", kValidScene);
  std::string big = write("big.sf", kValidScene + kValidScene);
  EXPECT_EQ(
      run(runSfcheck, {"sfcheck", "--format", "json", "--max-file-size",
                       std::to_string(kValidScene.size() + 1), good, big, path("missing.sf")}),
      toInt(ExitCode::IoError));
  nlohmann::json report = nlohmann::json::parse(out_.str());
  ASSERT_EQ(report["files"].size(), 3u);
  for (const nlohmann::json& file : report["files"]) {
    EXPECT_TRUE(file.contains("file")) << file;
    EXPECT_TRUE(file["format"].is_string()) << file;
    EXPECT_TRUE(file["diagnostics"].is_array()) << file;
  }
  EXPECT_EQ(report["files"][0]["format"], "scene-file");
  EXPECT_EQ(report["files"][1]["format"], "unknown");
  EXPECT_EQ(report["files"][1]["diagnostics"][0]["code"], "file-too-large");
  EXPECT_TRUE(report["files"][2].contains("readError"));
}

TEST_F(StreamsAndFlags, JsonGivesTheSpansEnd) {
  std::string bad = write("bad.sf", "CAMERA\n0 0 nan\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--format", "json", bad}), 1);
  nlohmann::json d = nlohmann::json::parse(out_.str())["files"][0]["diagnostics"][0];
  EXPECT_EQ(d["line"], 2);
  EXPECT_EQ(d["column"], 5);
  EXPECT_EQ(d["length"], 3);
  EXPECT_EQ(d["endLine"], 2);
  EXPECT_EQ(d["endColumn"], 8);
}

// Standard input that cannot be read (a folder: read(2) says EISDIR) is a
// read error with its reason, not an empty input, which std::cin alone
// would take it for.
TEST(StandardInput, AnUnreadableOneIsAReadErrorNotAnEmptyInput) {
  int saved = ::dup(STDIN_FILENO);
  int folder = ::open("/", O_RDONLY | O_DIRECTORY);
  ASSERT_GE(saved, 0);
  ASSERT_GE(folder, 0);
  ASSERT_EQ(::dup2(folder, STDIN_FILENO), STDIN_FILENO);
  ::close(folder);
  std::clearerr(stdin);
  std::cin.clear();
  InputText text = readInputText("-", scene::ReadOptions{}, &std::cin);
  ::dup2(saved, STDIN_FILENO);
  ::close(saved);
  std::clearerr(stdin);
  std::cin.clear();
  EXPECT_FALSE(text.text.has_value());
  EXPECT_EQ(text.readError, std::strerror(EISDIR));
}

TEST_F(ToolTest, ExitCodesForUsageAndUnreadableFiles) {
  EXPECT_EQ(run(runSfcheck, {"sfcheck"}), toInt(ExitCode::Usage));
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--bogus", "x"}), toInt(ExitCode::Usage));
  EXPECT_EQ(run(runSfcheck, {"sfcheck", path("missing.sf")}), toInt(ExitCode::IoError));
  EXPECT_NE(err_.str().find("cannot read the file: No such file or directory"), std::string::npos);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--help"}), 0);
  EXPECT_NE(out_.str().find("--werror"), std::string::npos);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "--version"}), 0);
  EXPECT_EQ(out_.str(), std::string("sfconvert ") + SCENEFILE_VERSION + "\n");
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "-V"}), 0);
  EXPECT_EQ(out_.str(), std::string("sfconvert ") + SCENEFILE_VERSION + "\n");
}

TEST_F(ToolTest, EveryReaderToolTakesTheLimitFlags) {
  std::string scene = write("scene.sf", kValidScene);  // one light, one sphere
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--max-objects", "1", scene}), 1);
  EXPECT_NE(err_.str().find(":13:1: error: the file has more than 1 objects and lights"),
            std::string::npos)
      << err_.str();
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--max-objects", "2", scene}), 0);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--max-objects", "0", scene}), toInt(ExitCode::Usage));

  EXPECT_EQ(run(runSfconvert, {"sfconvert", "--max-objects", "1", scene, path("a.txt")}), 1);
  EXPECT_NE(err_.str().find("[too-many-objects]"), std::string::npos) << err_.str();
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "--max-file-size", "10", scene, path("a.txt")}), 1);
  EXPECT_NE(err_.str().find("[file-too-large]"), std::string::npos) << err_.str();
  EXPECT_EQ(files(), std::vector<std::string>{"scene.sf"});  // nothing written
  EXPECT_EQ(run(runSfconvert, {"sfconvert", "--max-objects", "2", "--max-file-size", "1MiB", scene,
                               path("a.txt")}),
            0)
      << err_.str();

  std::vector<std::string> render = {"sfrender", scene,      "-o", path("a.ppm"), "--width",
                                     "8",        "--height", "6",  "--quiet"};
  std::vector<std::string> few = render;
  few.insert(few.end(), {"--max-objects", "1"});
  EXPECT_EQ(run(sfrender, few), 1);
  EXPECT_NE(err_.str().find("[too-many-objects]"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(path("a.ppm")));
  std::vector<std::string> enough = render;
  enough.insert(enough.end(), {"--max-objects", "2"});
  EXPECT_EQ(run(sfrender, enough), 0) << err_.str();
  EXPECT_TRUE(fs::exists(path("a.ppm")));
}

}  // namespace
}  // namespace tools
