#include "tools/common/tool_streams.h"

#include <unistd.h>

#include <cstdlib>
#include <iostream>

namespace tools {

namespace {

std::optional<std::string> environmentVariable(const char* name) {
  const char* value = std::getenv(name);
  if (!value) return std::nullopt;
  return std::string(value);
}

}  // namespace

ToolStreams processStreams() {
  ToolStreams streams{std::cin, std::cout, std::cerr};
  streams.inIsTerminal = ::isatty(STDIN_FILENO) == 1;
  streams.outIsTerminal = ::isatty(STDOUT_FILENO) == 1;
  streams.errIsTerminal = ::isatty(STDERR_FILENO) == 1;
  streams.noColor = environmentVariable("NO_COLOR");
  streams.term = environmentVariable("TERM");
  return streams;
}

}  // namespace tools
