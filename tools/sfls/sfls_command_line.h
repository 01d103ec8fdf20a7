// sfls's command line: the tools' common flags (so that its man page and
// bash completion come as theirs do) and --stdio, which clients pass.
#pragma once

#include <memory>

#include "tools/common/command_line.h"
#include "tools/common/tool_streams.h"

namespace sfls {

struct SflsOptions {
  tools::CommonFlags common;
  // Messages over standard input and output: the only transport, which
  // VS Code's client names with --stdio.
  bool stdio = true;
};

std::unique_ptr<CLI::App> makeSflsCommandLine(SflsOptions& options);

// The whole program: the command line, then the server on the streams.
int runSfls(int argc, const char* const* argv, tools::ToolStreams streams);

}  // namespace sfls
