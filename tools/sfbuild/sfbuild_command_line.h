// sfbuild's command line, apart from the window, so that its help, man page
// and completion come from the same place as those of the other tools.
#pragma once

#include <memory>
#include <string>

#include "scenefile/read.h"
#include "tools/common/cli_forward.h"
#include "tools/common/command_line.h"

namespace sfbuild {

struct SfbuildOptions {
  tools::CommonFlags common;
  std::string input;
  int width = 640;
  int height = 480;
  bool idView = false;
  scene::ReadOptions read;
};

std::unique_ptr<CLI::App> makeSfbuildCommandLine(SfbuildOptions& options);

}  // namespace sfbuild
