// sfconvert: converts between the project's scene formats.
#pragma once

#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "scenefile/mesh.h"
#include "scenefile/read.h"
#include "tools/common/cli_forward.h"
#include "tools/common/command_line.h"
#include "tools/common/tool_streams.h"

namespace tools {

struct SfconvertOptions {
  CommonFlags common;
  // The positionals: INPUT OUTPUT, or with -o the inputs alone.
  std::vector<std::string> files;
  std::string outputPattern;  // -o: the output of each input (output_pattern.h)
  std::string input;          // the one converted
  std::string output;
  std::string to;
  std::string format = "text";
  bool noLoss = false;
  bool noClobber = false;
  bool approximate = false;
  bool transpose = false;
  std::optional<double> fov;
  int width = 0;
  int height = 0;
  bool externalBuffers = false;
  int tessellation = scene::kDefaultSegments;
  bool flat = false;
  bool skipUnsupported = false;
  scene::ReadOptions read;
};

// sfconvert's command line, bound to `options`.
std::unique_ptr<CLI::App> makeSfconvertCommandLine(SfconvertOptions& options);

int runSfconvert(int argc, const char* const* argv, const ToolStreams& streams);

}  // namespace tools
