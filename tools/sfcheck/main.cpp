#include "tools/common/standard_streams.h"
#include "tools/common/tool_streams.h"
#include "tools/sfcheck/sfcheck.h"

int main(int argc, char** argv) {
  int status = tools::runSfcheck(argc, argv, tools::processStreams());
  return tools::closeStandardStreams("sfcheck", status);
}
