// The tools run in-process with their streams captured, as a user runs them.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "image/image_file.h"
#include "renderer/render.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/exit_code.h"
#include "tools/common/file_io.h"
#include "tools/common/output_file_format.h"
#include "tools/common/resource_guard.h"
#include "tools/sfcheck/sfcheck.h"
#include "tools/sfconvert/sfconvert.h"
#include "tools/sfrender/sfrender.h"
#include "tools/sfrender/thread_probe.h"
#include "tools/tool_test_support.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

const std::string kInstructions =
    "OUTPUT_FILE pic.ppm\nSTART CAMERA\nLOCATION 0 0 5\nLOOK_AT 0 0 0\nEND CAMERA\n"
    "START LIGHT\nLOCATION 3 3 3\nCOLOUR 1 1 1\nEND LIGHT\n"
    "START OBJECT CUBE\nSTART MATERIAL\nCOLOUR 0 0 1\nAMBIENT 0.15\nEND MATERIAL\n"
    "START TRANSFORMATION\nSCALE 0.5 0.5 0.5\nROTATE_Y 1.5707963267948966\n"
    "END TRANSFORMATION\nEND OBJECT\n";

class ToolTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = freshTestFolder("sftools"); }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(path(name), std::ios::binary) << content;
    return path(name);
  }

  std::string read(const std::string& name) const {
    std::string error;
    return readWholeFile(path(name), error).value_or("<missing>");
  }

  // Files in the folder, to see that nothing half-written stayed behind.
  std::vector<std::string> files() const { return fileNamesIn(dir_); }

  template <typename Tool>
  int run(Tool tool, const std::vector<std::string>& args) {
    return runTool(tool, args, out_, err_);
  }

  fs::path dir_;
  std::ostringstream out_;
  std::ostringstream err_;
};

TEST_F(ToolTest, SfcheckSumsUpAndExitsZeroOnValidFiles) {
  std::string a = write("a.sf", kValidScene);
  std::string b = write("b.txt", kInstructions);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", a, b}), 0);
  EXPECT_EQ(err_.str(), "sfcheck: 2 files checked, 0 errors, 0 warnings\n");
}

TEST_F(ToolTest, SfcheckPrintsDiagnosticsInTheCompilersForm) {
  std::string bad = write("bad.sf",
                          "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n"
                          "sphere\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", bad}), toInt(ExitCode::InvalidInput));
  // The source line quoted, the span underlined, the fix-it under it.
  EXPECT_EQ(err_.str(),
            bad +
                ":7:1: error: unknown keyword 'sphere', expected a record name (CAMERA, LIGHT, "
                "PLANE, SPHERE, CYLINDER or CUBE) [unknown-keyword]\n"
                "    7 | sphere\n"
                "      | ^~~~~~\n"
                "      | SPHERE\n"
                "  hint: keywords are upper case: did you mean 'SPHERE'?\n"
                "sfcheck: 1 file checked, 1 error, 0 warnings\n");
  // The short form: a line a diagnostic.
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--format", "short", bad}), toInt(ExitCode::InvalidInput));
  EXPECT_EQ(err_.str(),
            bad +
                ":7:1: error: unknown keyword 'sphere', expected a record name (CAMERA, LIGHT, "
                "PLANE, SPHERE, CYLINDER or CUBE) [unknown-keyword]\n"
                "  hint: keywords are upper case: did you mean 'SPHERE'?\n"
                "sfcheck: 1 file checked, 1 error, 0 warnings\n");
}

TEST_F(ToolTest, SfcheckWerrorAndJson) {
  std::string unlit = write("unlit.sf", "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", unlit}), 0);
  EXPECT_NE(err_.str().find("warning: scene has no LIGHT [no-light]"), std::string::npos);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--werror", unlit}), 1);
  EXPECT_NE(err_.str().find("error: scene has no LIGHT [no-light]"), std::string::npos);

  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--format", "json", unlit}), 0);
  nlohmann::json report = nlohmann::json::parse(out_.str());
  EXPECT_EQ(report["summary"]["warnings"], 1);
  EXPECT_EQ(report["files"][0]["format"], "scene-file");
  const nlohmann::json& d = report["files"][0]["diagnostics"][0];
  EXPECT_EQ(d["code"], "no-light");
  EXPECT_EQ(d["severity"], "warning");
  EXPECT_EQ(d["line"], 1);
  EXPECT_EQ(d["column"], 1);
}

// A file's bytes quoted in a message (a POV-Ray #include name here) must not
// reach the terminal raw, nor break the JSON report with invalid UTF-8.
TEST_F(ToolTest, QuotedBytesArePrintableInTextAndJson) {
  std::string pov = write("escape.pov", "#include \"a\x1B[31mb\xFF\xC3\xA9.inc\"\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", pov}), 1);
  EXPECT_NE(err_.str().find("'#include \"a\\x1B[31mb\\xFF\xC3\xA9.inc\"' would read another file"),
            std::string::npos)
      << err_.str();
  EXPECT_EQ(err_.str().find('\x1B'), std::string::npos);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--format", "json", pov}), 1);
  nlohmann::json report = nlohmann::json::parse(out_.str());
  std::string message = report["files"][0]["diagnostics"][0]["message"];
  EXPECT_NE(message.find("a\\x1B[31mb\\xFF\xC3\xA9.inc"), std::string::npos) << message;
}

TEST(PrintableText, EscapesControlBytesAndWhatIsNotUtf8) {
  EXPECT_EQ(printableText("plain text, \xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"),
            "plain text, \xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");
  EXPECT_EQ(printableText(std::string("a\0b\tc\x7F", 6)), "a\\x00b\\x09c\\x7F");
  EXPECT_EQ(printableText("\xC0\xAF"), "\\xC0\\xAF");                    // overlong '/'
  EXPECT_EQ(printableText("\xED\xA0\x80"), "\\xED\\xA0\\x80");           // a surrogate
  EXPECT_EQ(printableText("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(printableText("\xE2\x82"), "\\xE2\\x82");                    // cut short
  EXPECT_EQ(printableText("x\xFF"), "x\\xFF");
}

TEST_F(ToolTest, SfcheckWarnsWhenOutputFileLeavesItsFolder) {
  std::string escape = write("e.txt",
                             "OUTPUT_FILE ../../x.ppm\nSTART CAMERA\nLOCATION 0 0 5\n"
                             "LOOK_AT 0 0 0\nEND CAMERA\nSTART LIGHT\nLOCATION 1 1 1\n"
                             "COLOUR 1 1 1\nEND LIGHT\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", escape}), 0);
  EXPECT_NE(err_.str().find(":1:13: warning: OUTPUT_FILE '../../x.ppm' leaves the instruction "
                            "file's folder [output-file-escapes]"),
            std::string::npos)
      << err_.str();
  // Through a link that leads out of the folder.
  fs::create_directory_symlink(fs::temp_directory_path(), dir_ / "out");
  std::string linked = write("l.txt",
                             "OUTPUT_FILE out/x.ppm\nSTART CAMERA\nLOCATION 0 0 5\n"
                             "LOOK_AT 0 0 0\nEND CAMERA\nSTART LIGHT\nLOCATION 1 1 1\n"
                             "COLOUR 1 1 1\nEND LIGHT\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--werror", linked}), 1);
  std::string inside = write("i.txt",
                             "OUTPUT_FILE sub/../x.ppm\nSTART CAMERA\nLOCATION 0 0 5\n"
                             "LOOK_AT 0 0 0\nEND CAMERA\nSTART LIGHT\nLOCATION 1 1 1\n"
                             "COLOUR 1 1 1\nEND LIGHT\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--werror", inside}), 0) << err_.str();
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
    ASSERT_EQ(run(runSfconvert, {"sfconvert", path(name), path(std::string(name) + ".sf")}), 0)
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

// The manual's three ways of running the renderer: no file, a scene file,
// an instruction file.
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
  ASSERT_EQ(run(runSfconvert, {"sfconvert", path("a.pov"), path("c.sf")}), 0);
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
  EXPECT_EQ(run(runSfcheck, {"sfcheck", empty}), 0) << err_.str();
  EXPECT_NE(err_.str().find("POV-Ray's default camera"), std::string::npos) << err_.str();
}

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
  EXPECT_TRUE(fs::exists(dir_ / "ball.ppm"));
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

TEST(ImageFile, QuantizesToTheNearestLevelWithoutGamma) {
  EXPECT_EQ(quantizeChannel(0.0f), 0);
  EXPECT_EQ(quantizeChannel(-3.0f), 0);
  EXPECT_EQ(quantizeChannel(1.0f), 255);
  EXPECT_EQ(quantizeChannel(7.0f), 255);
  EXPECT_EQ(quantizeChannel(0.5f), 128);  // 127.5 rounds up
  EXPECT_EQ(quantizeChannel(0.25f), 64);  // 63.75
  EXPECT_EQ(quantizeChannel(0.2f), 51);
  EXPECT_EQ(quantizeChannel(std::numeric_limits<float>::quiet_NaN()), 0);
}

// quantizeChannel rounds inline as std::lround rounds the same float
// product: every level's halfway point and its float neighbours, and a
// stride through all the floats of [0, 1].
TEST(ImageFile, QuantizesAsLroundDoes) {
  auto byLround = [](float v) {
    return static_cast<unsigned char>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  for (int level = 0; level < 255; ++level) {
    float half = (static_cast<float>(level) + 0.5f) / 255.0f;
    float v = half;
    for (int step = 0; step < 8; ++step) v = std::nextafter(v, 0.0f);
    for (int step = 0; step < 16; ++step, v = std::nextafter(v, 2.0f)) {
      ASSERT_EQ(quantizeChannel(v), byLround(v)) << v;
    }
  }
  for (std::uint32_t bits = 0; bits <= 0x3F800000u; bits += 997) {
    float v = std::bit_cast<float>(bits);
    ASSERT_EQ(quantizeChannel(v), byLround(v)) << v;
  }
}

// quantizeChannels (which quantizeChannel calls for one value) gives each
// value the level that rounding in double gives, apart from its float
// steps: every level's halfway point and its float neighbours, and a
// stride through all 2^32 bit patterns (negatives, infinities and NaNs
// among them), in runs of 1 to 38 values, so that the vector loop's tails
// are exercised too.
TEST(ImageFile, QuantizesInBulkAsOneByOne) {
  // A float plus 0.5 is exact in double, and its truncation rounds halves
  // up for a value of at least 0; not a number gives 0.
  auto byDouble = [](float v) {
    float level = std::clamp(v, 0.0f, 1.0f) * 255.0f;
    if (!(level >= 0.0f)) return static_cast<unsigned char>(0);
    return static_cast<unsigned char>(static_cast<int>(static_cast<double>(level) + 0.5));
  };
  std::vector<float> values;
  for (int level = 0; level < 256; ++level) {
    float v = (static_cast<float>(level) + 0.5f) / 255.0f;
    for (int step = 0; step < 8; ++step) v = std::nextafter(v, 0.0f);
    for (int step = 0; step < 16; ++step, v = std::nextafter(v, 2.0f)) values.push_back(v);
  }
  for (std::uint64_t bits = 0; bits <= 0xFFFFFFFFu; bits += 4099) {
    values.push_back(std::bit_cast<float>(static_cast<std::uint32_t>(bits)));
  }
  for (float special :
       {0.0f, -0.0f, 1.0f, std::numeric_limits<float>::infinity(),
        -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
        std::numeric_limits<float>::denorm_min(), 0.5f / 255.0f}) {
    values.push_back(special);
  }
  std::vector<unsigned char> levels(values.size(), 0xAB);
  for (std::size_t first = 0, run = 1; first < values.size(); first += run, run = run % 37 + 2) {
    std::size_t count = std::min(run, values.size() - first);
    quantizeChannels(values.data() + first, count, levels.data() + first);
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    ASSERT_EQ(levels[i], byDouble(values[i])) << values[i];
    ASSERT_EQ(quantizeChannel(values[i]), levels[i]) << values[i];
  }
}

// sfrender writes .ppm by hand: the file must be the one OpenImageIO writes
// (.pnm goes through it) and read back through OpenImageIO identically.
TEST(ImageFile, HandWrittenPpmMatchesOpenImageIO) {
  render::Image image;
  image.width = 7;
  image.height = 5;
  for (int i = 0; i < image.width * image.height * 3; ++i) {
    image.rgb.push_back(static_cast<float>(i % 23) / 19.0f - 0.1f);
  }
  fs::path dir = fs::temp_directory_path() / ("sfppm-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string error;
  ASSERT_TRUE(writeImageFile(image, dir / "hand.ppm", error)) << error;
  ASSERT_TRUE(writeImageFile(image, dir / "oiio.pnm", error)) << error;
  std::optional<std::string> hand = readWholeFile(dir / "hand.ppm", error);
  std::optional<std::string> oiio = readWholeFile(dir / "oiio.pnm", error);
  ASSERT_TRUE(hand && oiio);
  EXPECT_EQ(*hand, *oiio);

  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open((dir / "hand.ppm").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, image.width);
  EXPECT_EQ(in->spec().height, image.height);
  EXPECT_EQ(in->spec().nchannels, 3);
  std::vector<unsigned char> pixels(image.rgb.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data()));
  in->close();
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    ASSERT_EQ(pixels[i], quantizeChannel(image.rgb[i])) << i;
  }
  fs::remove_all(dir);
}

TEST(FileIo, AtomicWriteReplacesWholeAndLeavesNoTemporary) {
  fs::path dir = fs::temp_directory_path() / ("sfatomic-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string error;
  ASSERT_TRUE(writeFileAtomically(dir / "f", "old", error)) << error;
  ASSERT_TRUE(writeFileAtomically(dir / "f", std::string(1 << 20, 'x'), error)) << error;
  EXPECT_EQ(readWholeFile(dir / "f", error)->size(), 1u << 20);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

// A file big enough that the later half of its buffer is faulted in on a
// thread of its own while the first half is read comes back byte for byte,
// and so does one cut short by the byte limit.
TEST(FileIo, ABigFileIsReadWholeWhileItsLaterPagesAreFaultedIn) {
  fs::path dir = fs::temp_directory_path() / ("sfbigread-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string text(40u << 20, '\0');
  for (std::size_t i = 0; i < text.size(); ++i) text[i] = static_cast<char>('a' + (i * 7919) % 26);
  std::string error;
  ASSERT_TRUE(writeFileAtomically(dir / "big", text, error)) << error;
  std::optional<std::string> read = readWholeFile(dir / "big", error);
  ASSERT_TRUE(read.has_value()) << error;
  EXPECT_TRUE(*read == text);
  std::optional<std::string> cut = readWholeFile(dir / "big", error, 30u << 20);
  ASSERT_TRUE(cut.has_value()) << error;
  EXPECT_EQ(cut->size(), (30u << 20) + 1);
  EXPECT_TRUE(cut->compare(0, cut->size(), text, 0, cut->size()) == 0);
  fs::remove_all(dir);
}

// The limits (docs/FORMATS.md, "Limits"): each over its default or lowered
// limit, then raised.

TEST_F(ToolTest, SfcheckRefusesAFileAboveMaxFileSizeUnread) {
  std::string scene = write("scene.sf", kValidScene);
  std::string size = std::to_string(kValidScene.size());
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--max-file-size", "100", scene}),
            toInt(ExitCode::InvalidInput));
  EXPECT_EQ(err_.str(), scene + ": error: the file is " + size +
                            " bytes, more than the limit of 100 [file-too-large]\n"
                            "  hint: raise the limit with --max-file-size if the file is meant "
                            "to be this large\n"
                            "sfcheck: 1 file checked, 1 error, 0 warnings\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--format", "json", "--max-file-size", "100", scene}), 1);
  nlohmann::json report = nlohmann::json::parse(out_.str());
  EXPECT_EQ(report["files"][0]["diagnostics"][0]["code"], "file-too-large");
  EXPECT_EQ(report["summary"]["errors"], 1);
  // Size suffixes, and the limit itself is allowed.
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--max-file-size", "1kib", scene}), 0) << err_.str();
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--max-file-size", size, scene}), 0) << err_.str();
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--max-file-size", "-5", scene}), toInt(ExitCode::Usage));
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

// A file that cannot be read is no "0 errors": counted as an error, and
// named in the summary (text) or counted under "unreadable" (JSON).
TEST_F(ToolTest, SfcheckCountsAnUnreadableFileAsAnError) {
  std::string good = write("good.sf", kValidScene);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", good, path("missing.sf")}), toInt(ExitCode::IoError));
  EXPECT_NE(err_.str().find("sfcheck: 2 files checked, 1 error, 0 warnings (1 file could not be "
                            "read)\n"),
            std::string::npos)
      << err_.str();
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--format", "json", path("missing.sf"), dir_.string()}),
            toInt(ExitCode::IoError));
  nlohmann::json report = nlohmann::json::parse(out_.str());
  EXPECT_EQ(report["summary"]["errors"], 2);
  EXPECT_EQ(report["summary"]["unreadable"], 2);
  EXPECT_EQ(report["files"][1]["readError"], "it is a directory");
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

TEST(ResourceGuard, OutOfMemoryAndThreadsAreMessagesAndAnExitCode) {
  std::ostringstream err;
  Stage stage;
  stage.set("reading big.txt");
  EXPECT_EQ(runGuarded("sfcheck", err, stage, []() -> int { throw std::bad_alloc(); }),
            toInt(ExitCode::OutOfResources));
  EXPECT_EQ(err.str(), "sfcheck: error: out of memory while reading big.txt\n");
  err.str("");
  stage.set("starting 1024 threads");
  EXPECT_EQ(runGuarded("sfrender", err, stage,
                       []() -> int {
                         throw std::system_error(
                             std::make_error_code(std::errc::resource_unavailable_try_again));
                       }),
            toInt(ExitCode::OutOfResources));
  EXPECT_EQ(err.str(),
            "sfrender: error: starting 1024 threads: Resource temporarily unavailable\n");
  err.str("");
  EXPECT_EQ(runGuarded("sfconvert", err, stage,
                       []() -> int {
                         throw fs::filesystem_error(
                             "x", "/some/file", std::make_error_code(std::errc::permission_denied));
                       }),
            toInt(ExitCode::IoError));
  EXPECT_EQ(err.str(), "sfconvert: error: /some/file: Permission denied\n");
  EXPECT_EQ(runGuarded("sfcheck", err, stage, [] { return 1; }), 1);
}

TEST(ThreadProbe, StartsTheThreadsItIsAskedFor) {
  EXPECT_EQ(threadStartFailure(1), std::nullopt);
  EXPECT_EQ(threadStartFailure(64), std::nullopt);
  EXPECT_GE(renderThreadCount(0), 1);
  EXPECT_EQ(renderThreadCount(7), 7);
}

TEST(FileIo, ReadingStopsOneBytePastTheLimit) {
  fs::path dir = fs::temp_directory_path() / ("sflimit-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "f", std::ios::binary) << std::string(200'000, 'x');
  std::string error;
  EXPECT_EQ(readWholeFile(dir / "f", error, 100)->size(), 101u);
  EXPECT_EQ(readWholeFile(dir / "f", error, 199'999)->size(), 200'000u);
  EXPECT_EQ(readWholeFile(dir / "f", error, 200'000)->size(), 200'000u);
  EXPECT_EQ(readWholeFile(dir / "f", error)->size(), 200'000u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tools
