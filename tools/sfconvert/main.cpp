#include <iostream>

#include "tools/sfconvert/sfconvert.h"

int main(int argc, char** argv) { return tools::runSfconvert(argc, argv, std::cout, std::cerr); }
