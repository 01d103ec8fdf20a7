// The standard streams and the environment a tool runs in, passed in rather
// than taken from the process, so that a test can run a tool on strings and
// say whether each stream is a terminal.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

namespace tools {

struct ToolStreams {
  // No terminal, and the environment empty: what a test runs a tool with.
  ToolStreams(std::istream& input, std::ostream& output, std::ostream& error)
      : in(input), out(output), err(error) {}

  std::istream& in;   // standard input, read for an input named "-"
  std::ostream& out;  // standard output
  std::ostream& err;  // standard error: diagnostics, messages, progress
  bool inIsTerminal = false;
  bool outIsTerminal = false;
  bool errIsTerminal = false;
  // The environment variables that change how a tool prints: NO_COLOR
  // (https://no-color.org) and TERM ("dumb" has no colours). Unset is nothing.
  std::optional<std::string> noColor;
  std::optional<std::string> term;
};

// The process's own: std::cin, std::cout and std::cerr, isatty() of each
// descriptor, and the variables from the environment.
ToolStreams processStreams();

// The name diagnostics and messages give standard input when it is read as
// the input "-", as compilers do.
inline constexpr const char* kStandardInputName = "<stdin>";

// Whether a command-line input or output names a standard stream.
inline bool isStandardStream(const std::string& name) {
  return name == "-";
}

}  // namespace tools
