// Running CLI11 with the project's exit codes and the caller's streams.
#pragma once

#include <optional>
#include <ostream>

#include <CLI/CLI.hpp>

#include "tools/common/exit_code.h"

namespace tools {

// Parses the arguments. Returns the exit code to stop with (0 after --help or
// --version, Usage after a mistake, with CLI11's message on `err`), or nothing
// when the tool should go on.
std::optional<ExitCode> parseCommandLine(CLI::App& app, int argc, const char* const* argv,
                                         std::ostream& out, std::ostream& err);

}  // namespace tools
