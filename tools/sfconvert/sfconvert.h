// sfconvert: converts between the project's scene formats.
#pragma once

#include <memory>

#include "tools/common/cli_forward.h"
#include "tools/common/tool_streams.h"
#include "tools/sfconvert/sfconvert_options.h"

namespace tools {

// sfconvert's command line, bound to `options`.
std::unique_ptr<CLI::App> makeSfconvertCommandLine(SfconvertOptions& options);

int runSfconvert(int argc, const char* const* argv, const ToolStreams& streams);

}  // namespace tools
