#include <unistd.h>

#include <iostream>

#include "tools/common/standard_streams.h"
#include "tools/sfrender/sfrender.h"

int main(int argc, char** argv) {
  int status = tools::runSfrender(argc, argv, std::cout, std::cerr, ::isatty(STDERR_FILENO) == 1);
  return tools::closeStandardStreams("sfrender", status);
}
