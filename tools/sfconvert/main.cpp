#include <iostream>

#include "tools/common/standard_streams.h"
#include "tools/sfconvert/sfconvert.h"

int main(int argc, char** argv) {
  int status = tools::runSfconvert(argc, argv, std::cout, std::cerr);
  return tools::closeStandardStreams("sfconvert", status);
}
