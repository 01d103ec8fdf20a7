#include <unistd.h>

#include <iostream>

#include "tools/sfrender/sfrender.h"

int main(int argc, char** argv) {
  return tools::runSfrender(argc, argv, std::cout, std::cerr, ::isatty(STDERR_FILENO) == 1);
}
