// sfcheck: validates scene files and instruction files.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "scenefile/read.h"
#include "tools/common/cli_forward.h"
#include "tools/common/command_line.h"
#include "tools/common/tool_streams.h"

namespace tools {

struct SfcheckOptions {
  CommonFlags common;
  std::vector<std::string> files;
  bool werror = false;
  std::string format = "text";
  bool fix = false;     // --fix: every fix-it applied, in place
  bool dryRun = false;  // --dry-run: with --fix, the fixes printed as a diff instead
  bool info = false;    // --info: what each file holds, on standard output
  scene::ReadOptions read;
};

// sfcheck's command line, bound to `options`: what --help, the man page and
// the bash completion show.
std::unique_ptr<CLI::App> makeSfcheckCommandLine(SfcheckOptions& options);

// The whole tool, with its streams passed in so that tests can run it.
int runSfcheck(int argc, const char* const* argv, const ToolStreams& streams);

}  // namespace tools
