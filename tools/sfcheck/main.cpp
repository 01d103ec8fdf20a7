#include <iostream>

#include "tools/common/standard_streams.h"
#include "tools/sfcheck/sfcheck.h"

int main(int argc, char** argv) {
  int status = tools::runSfcheck(argc, argv, std::cout, std::cerr);
  return tools::closeStandardStreams("sfcheck", status);
}
