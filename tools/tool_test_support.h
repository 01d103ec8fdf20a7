// What the tools' in-process tests share: valid scenes, sfrender as a test
// runs it, and a scratch folder of each test's own.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

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

}  // namespace tools
