#include "tools/common/standard_streams.h"
#include "tools/common/tool_streams.h"
#include "tools/sfrender/sfrender.h"

int main(int argc, char** argv) {
  int status = tools::runSfrender(argc, argv, tools::processStreams());
  return tools::closeStandardStreams("sfrender", status);
}
