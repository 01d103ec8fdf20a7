#include <iostream>

#include "tools/sfcheck/sfcheck.h"

int main(int argc, char** argv) { return tools::runSfcheck(argc, argv, std::cout, std::cerr); }
