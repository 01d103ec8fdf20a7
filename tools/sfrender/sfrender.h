// sfrender: ray traces a scene file, an instruction file or the default scene.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "image/image_formats.h"
#include "renderer/render.h"
#include "renderer/render_memory.h"
#include "scenefile/read.h"
#include "tools/common/cli_forward.h"
#include "tools/common/command_line.h"
#include "tools/common/tool_streams.h"

namespace tools {

// The memory check is the renderer's (renderer/render_memory.h).
using render::AvailableMemoryProbe;

// What one render may ask for; the flags raise them (docs/FORMATS.md, "Limits").
struct RenderLimits {
  std::int64_t maxPixels = std::int64_t{8192} * 8192;
  int maxSpp = 1024;
  int maxDepth = 64;
};

struct SfrenderOptions {
  CommonFlags common;
  // The scenes on the command line; with --merge, the regions to merge.
  std::vector<std::string> inputs;
  std::string input;   // the one rendered: empty, the default scene; "-", standard input
  std::string output;  // empty: from the input's name; "-": standard output (PPM); a pattern
                       // with several inputs (output_pattern.h)
  bool merge = false;  // --merge: put the regions in `inputs` together into `output`
  // Given on the command line, or nothing: the scene's view (a POV-Ray or
  // glTF camera's) or the defaults of render::RenderSettings decide.
  std::optional<int> width;
  std::optional<int> height;
  std::optional<double> fov;
  render::RenderSettings settings;  // --adaptive among them
  // --region x0,y0,x1,y1 and --tile i/N, as given (checked when parsed).
  std::string region;
  std::string tile;
  image::ImageOptions image;  // --bits, --alpha
  bool stats = false;
  bool noClobber = false;
  RenderLimits limits;
  scene::ReadOptions read;
};

// sfrender's command line, bound to `options`.
std::unique_ptr<CLI::App> makeSfrenderCommandLine(SfrenderOptions& options);

// `availableMemory` says how much memory a render may take (tests pass their
// own figure).
int runSfrender(int argc, const char* const* argv, const ToolStreams& streams,
                const AvailableMemoryProbe& availableMemory = render::readAvailableMemory);

}  // namespace tools
