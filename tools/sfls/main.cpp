#include <csignal>
#include <iostream>

#include "tools/common/standard_streams.h"
#include "tools/common/tool_streams.h"
#include "tools/sfls/sfls_command_line.h"

int main(int argc, char** argv) {
  // A client that goes away closes the pipe: the write fails and the
  // server stops at the end of its input, rather than dying of SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  std::ios::sync_with_stdio(false);
  int status = sfls::runSfls(argc, argv, tools::processStreams());
  return tools::closeStandardStreams("sfls", status);
}
