#include "tools/common/standard_streams.h"
#include "tools/common/tool_streams.h"
#include "tools/sfconvert/sfconvert.h"

int main(int argc, char** argv) {
  int status = tools::runSfconvert(argc, argv, tools::processStreams());
  return tools::closeStandardStreams("sfconvert", status);
}
