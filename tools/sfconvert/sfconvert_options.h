// What sfconvert's command line asks for: the tool's own options, and
// through conversion_options.h what they ask of each conversion.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scenefile/mesh.h"
#include "scenefile/read.h"
#include "tools/common/command_line.h"

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
  bool noLights = false;
  bool noExtras = false;
  std::string lightFalloff = "inverse-square";
  bool flat = false;
  bool skipUnsupported = false;
  scene::ReadOptions read;
};

}  // namespace tools
