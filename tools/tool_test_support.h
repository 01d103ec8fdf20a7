// What the tools' in-process tests share: valid scenes, sfrender as a test
// runs it, a scratch folder of each test's own, and the fixture that runs a
// tool there.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "tools/common/file_io.h"
#include "tools/common/tool_streams.h"
#include "tools/sfrender/sfrender.h"

namespace tools {

// A camera, a light and a red sphere: valid without a warning.
inline const std::string kValidScene =
    "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n"
    "LIGHT\n1 1 1\n1 0 0 3\n0 1 0 3\n0 0 1 3\n0 0 0 1\n"
    "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";

// A valid instruction file whose OUTPUT_FILE is `outputFile`.
inline std::string instructionsWriting(const std::string& outputFile) {
  return "OUTPUT_FILE " + outputFile +
         "\n\nSTART CAMERA\n  LOCATION 4 3 6\n  LOOK_AT 0 0.5 0\nEND CAMERA\n\n"
         "START LIGHT\n  LOCATION 5 8 5\n  COLOUR 1 1 1\nEND LIGHT\n\n"
         "START OBJECT PLANE\n  START MATERIAL\n    COLOUR 0.8 0.8 0.8\n  END MATERIAL\n"
         "END OBJECT\n";
}

// sfrender as a test runs it, with the memory as the machine has it.
inline int sfrender(int argc, const char* const* argv, const ToolStreams& streams) {
  return runSfrender(argc, argv, streams);
}

// An empty folder for the running test alone, `prefix`-PID-TEST under the
// system's temporary folder, so that tests run in parallel never meet.
inline std::filesystem::path freshTestFolder(const std::string& prefix) {
  std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                 (prefix + "-" + std::to_string(::getpid()) + "-" +
                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

// Runs a tool's entry point (runSfcheck, sfrender, ...) on `args`, the
// program's name first, with `out` and `err` emptied first, `input` as
// standard input and no stream a terminal.
template <typename Tool>
int runTool(Tool tool, const std::vector<std::string>& args, std::ostringstream& out,
            std::ostringstream& err, const std::string& input = "") {
  out.str("");
  err.str("");
  std::istringstream in(input);
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  return tool(static_cast<int>(argv.size()), argv.data(), ToolStreams(in, out, err));
}

// The names in a folder, sorted: to see that nothing half-written stayed.
inline std::vector<std::string> fileNamesIn(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// An instruction file: a camera, a light and a blue cube, drawn to pic.ppm.
inline const std::string kInstructions =
    "OUTPUT_FILE pic.ppm\nSTART CAMERA\nLOCATION 0 0 5\nLOOK_AT 0 0 0\nEND CAMERA\n"
    "START LIGHT\nLOCATION 3 3 3\nCOLOUR 1 1 1\nEND LIGHT\n"
    "START OBJECT CUBE\nSTART MATERIAL\nCOLOUR 0 0 1\nAMBIENT 0.15\nEND MATERIAL\n"
    "START TRANSFORMATION\nSCALE 0.5 0.5 0.5\nROTATE_Y 1.5707963267948966\n"
    "END TRANSFORMATION\nEND OBJECT\n";

// The tools run in-process with their streams captured, as a user runs
// them, in a folder of the test's own.
class ToolTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = freshTestFolder("sftools"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(path(name), std::ios::binary) << content;
    return path(name);
  }

  std::string read(const std::string& name) const {
    return readWholeFile(path(name)).valueOr("<missing>");
  }

  // Files in the folder, to see that nothing half-written stayed behind.
  std::vector<std::string> files() const { return fileNamesIn(dir_); }

  template <typename Tool>
  int run(Tool tool, const std::vector<std::string>& args) {
    return runTool(tool, args, out_, err_);
  }

  std::filesystem::path dir_;
  std::ostringstream out_;
  std::ostringstream err_;
};

}  // namespace tools
