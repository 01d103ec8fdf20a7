// sfcheck end to end, in-process with its streams captured: the summary,
// the diagnostics in text and JSON, --werror, and the files it cannot read.
#include "tools/sfcheck/sfcheck.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tools/common/exit_code.h"
#include "tools/tool_test_support.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

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

// A clean file's notes are what was decided on the way: -v shows them; the
// warnings print either way.
TEST_F(ToolTest, SfcheckShowsNotesOnlyWhenVerbose) {
  std::string pov = write("a.pov",
                          "camera { location <0, 1, -5> look_at 0 }\n"
                          "sphere { 0, 1 pigment { color rgb 1 } }\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", pov}), 0);
  EXPECT_NE(err_.str().find("warning: scene has no LIGHT [no-light]"), std::string::npos);
  EXPECT_EQ(err_.str().find("note:"), std::string::npos) << err_.str();
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "-v", pov}), 0);
  EXPECT_NE(err_.str().find("note: the camera shows a vertical field of view"), std::string::npos)
      << err_.str();
  // JSON keeps every diagnostic: a program filters for itself.
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--format", "json", pov}), 0);
  EXPECT_NE(out_.str().find("\"camera-fov\""), std::string::npos) << out_.str();
}

// --info: what each file holds, as `assimp info` says it.
TEST_F(ToolTest, SfcheckInfoSaysWhatEachFileHolds) {
  std::string pov = write("a.pov",
                          "camera { location <0, 1, -5> look_at <0, 1, 0> angle 60 }\n"
                          "light_source { <4, 8, -6> color rgb 1 }\n"
                          "plane { y, 0 pigment { color rgb 1 } }\n"
                          "sphere { <0, 1, 0>, 1 pigment { color rgb <1, 0, 0> } }\n"
                          "sphere { <3, 1, 0>, 1 pigment { color rgb <1, 0, 0> } }\n"
                          "box { <-1, 0, 2>, <1, 2, 4> pigment { color rgb <0, 0, 1> } }\n");
  std::string unlit = write("unlit.sf", "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n");
  std::string bad = write("bad.sf", "CAMERA\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--info", pov, unlit, bad}), 1);
  std::string size = std::to_string(fs::file_size(pov));
  EXPECT_EQ(out_.str(),
            pov + ": a POV-Ray scene, " + size +
                " bytes\n"
                "  objects: 4 (1 plane, 2 spheres, 0 cylinders, 1 cube)\n"
                "  lights: 1\n"
                "  camera: at (0 1 5), looking along (0 0 -1), a vertical field of view of "
                "46.9311 degrees at an aspect ratio of 1.33\n"
                "  box: (-1 0 -4) to (4 2 1), and 1 plane, infinite\n"
                "  materials: 3 distinct\n" +
                unlit +
                ": a scene file, 45 bytes\n"
                "  objects: 0 (0 planes, 0 spheres, 0 cylinders, 0 cubes)\n"
                "  lights: 0\n"
                "  camera: at (0 0 5), looking along (0 0 -1)\n"
                "  box: none\n"
                "  materials: 0 distinct\n")
      << err_.str();
  // JSON: each file's info, exact, null where the file has errors.
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--info", "--format", "json", pov, bad}), 1);
  nlohmann::json report = nlohmann::json::parse(out_.str());
  const nlohmann::json& info = report["files"][0]["info"];
  EXPECT_EQ(info["bytes"], fs::file_size(pov));
  EXPECT_EQ(
      info["objects"],
      (nlohmann::json{{"total", 4}, {"plane", 1}, {"sphere", 2}, {"cylinder", 0}, {"cube", 1}}));
  EXPECT_EQ(info["lights"], 1);
  EXPECT_EQ(info["materials"], 3);
  EXPECT_EQ(info["bounds"]["high"], (nlohmann::json{4.0, 2.0, 1.0}));
  EXPECT_EQ(info["unbounded"], 1);
  // POV-Ray's world is left-handed: z is mirrored.
  EXPECT_EQ(info["camera"]["position"], (nlohmann::json{0.0, 1.0, 5.0}));
  EXPECT_TRUE(info["camera"].contains("verticalFov"));
  EXPECT_TRUE(report["files"][1]["info"].is_null());
  // Without --info, no info.
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--format", "json", pov}), 0);
  EXPECT_FALSE(nlohmann::json::parse(out_.str())["files"][0].contains("info"));
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

// Two keywords in lower case, each with its fix-it, in a file that is
// valid once they are fixed.
const std::string kLowerCaseKeywords =
    "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n"
    "light\n1 1 1\n1 0 0 3\n0 1 0 3\n0 0 1 3\n0 0 0 1\n"
    "sphere\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";

// The file's inode: a file written again, through a rename, gets a new one.
ino_t inodeOf(const std::string& file) {
  struct stat status {};
  return ::stat(file.c_str(), &status) == 0 ? status.st_ino : 0;
}

TEST_F(ToolTest, SfcheckFixAppliesEveryFixItInPlaceOnce) {
  std::string scene = write("lower.sf", kLowerCaseKeywords);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--fix", scene}), 0) << err_.str();
  EXPECT_EQ(read("lower.sf"), kValidScene);
  EXPECT_EQ(err_.str(), "sfcheck: fixed " + scene +
                            " (2 fixes)\nsfcheck: 1 file checked, 2 fixes applied, 0 errors, 0 "
                            "warnings\n");
  // Written whole: no temporary stays beside it.
  EXPECT_EQ(files(), std::vector<std::string>{"lower.sf"});
  // Fixed again, nothing changes, and the file is not written again.
  ino_t written = inodeOf(scene);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--fix", scene}), 0);
  EXPECT_EQ(err_.str(), "sfcheck: 1 file checked, 0 fixes applied, 0 errors, 0 warnings\n");
  EXPECT_EQ(inodeOf(scene), written);
  EXPECT_EQ(read("lower.sf"), kValidScene);
}

// What no fix-it mends is reported after the fixes, at its place in the
// fixed file, and a file with no fix-it is left untouched.
TEST_F(ToolTest, SfcheckFixReportsWhatIsLeftAndLeavesAFileWithoutFixItsAlone) {
  std::string scene = write("left.sf", kLowerCaseKeywords + "CUBE\n1 0 0\n");
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--fix", "--format", "short", scene}),
            toInt(ExitCode::InvalidInput));
  EXPECT_EQ(read("left.sf"), kValidScene + "CUBE\n1 0 0\n");
  EXPECT_NE(err_.str().find("1 file checked, 2 fixes applied, 1 error"), std::string::npos)
      << err_.str();
  std::string unlit = write("unlit.sf", "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n");
  ino_t before = inodeOf(unlit);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--fix", unlit}), 0);
  EXPECT_EQ(inodeOf(unlit), before);
}

TEST_F(ToolTest, SfcheckFixDryRunPrintsADiffThatPatchApplies) {
  std::string scene = write("lower.sf", kLowerCaseKeywords);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--fix", "--dry-run", scene}),
            toInt(ExitCode::InvalidInput));
  EXPECT_EQ(read("lower.sf"), kLowerCaseKeywords);
  EXPECT_EQ(out_.str(),
            "--- a/" + scene + "\n+++ b/" + scene +
                "\n@@ -4,13 +4,13 @@\n 0 1 0 0\n 0 0 1 5\n 0 0 0 1\n-light\n+LIGHT\n 1 1 1\n 1 0 "
                "0 3\n 0 1 0 3\n 0 0 1 3\n 0 0 0 1\n-sphere\n+SPHERE\n 1 0 0\n 1 0 0 "
                "0\n 0 1 0 0\n");
  EXPECT_NE(err_.str().find("sfcheck: " + scene + ": 2 fixes to apply\n"), std::string::npos);
  EXPECT_NE(err_.str().find("1 file checked, 2 fixes to apply, 2 errors"), std::string::npos);
  std::string diff = write("fix.diff", out_.str());
  std::string copy = write("copy.sf", kLowerCaseKeywords);
  ASSERT_EQ(std::system(("patch --quiet -p1 " + copy + " < " + diff).c_str()), 0);
  EXPECT_EQ(read("copy.sf"), kValidScene);
  // In the JSON report, each file's diff and the fixes it would apply.
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--fix", "--dry-run", "--format", "json", scene}), 1);
  nlohmann::json report = nlohmann::json::parse(out_.str());
  EXPECT_EQ(report["files"][0]["fixable"], 2);
  EXPECT_EQ(report["files"][0]["diff"], read("fix.diff"));
  EXPECT_EQ(report["summary"]["fixable"], 2);
}

TEST_F(ToolTest, SfcheckFixInJsonAndOnStandardInput) {
  std::string scene = write("lower.sf", kLowerCaseKeywords);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--fix", "--format", "json", scene}), 0);
  nlohmann::json report = nlohmann::json::parse(out_.str());
  EXPECT_EQ(report["files"][0]["fixed"], 2);
  EXPECT_EQ(report["summary"]["fixed"], 2);
  // Standard input's fixed text goes to standard output, as a filter's.
  EXPECT_EQ(runTool(runSfcheck, {"sfcheck", "--fix", "-"}, out_, err_, kLowerCaseKeywords), 0);
  EXPECT_EQ(out_.str(), kValidScene);
  EXPECT_EQ(runTool(runSfcheck, {"sfcheck", "--fix", "-"}, out_, err_, kValidScene), 0);
  EXPECT_EQ(out_.str(), kValidScene);
  EXPECT_EQ(runTool(runSfcheck, {"sfcheck", "--fix", "--format", "json", "-"}, out_, err_, "x"),
            toInt(ExitCode::Usage));
}

TEST_F(ToolTest, SfcheckDryRunNeedsFix) {
  std::string scene = write("lower.sf", kLowerCaseKeywords);
  EXPECT_EQ(run(runSfcheck, {"sfcheck", "--dry-run", scene}), toInt(ExitCode::Usage));
  EXPECT_NE(err_.str().find("--dry-run"), std::string::npos) << err_.str();
  EXPECT_EQ(read("lower.sf"), kLowerCaseKeywords);
}

}  // namespace
}  // namespace tools
