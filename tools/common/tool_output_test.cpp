#include "tools/common/tool_output.h"

#include <gtest/gtest.h>

#include <sstream>

namespace tools {
namespace {

// A failure prints as the tool's error, the file's error or (told already)
// not at all, and ends the run with its own exit status.
TEST(ToolOutput, ReportsAFailureAndGivesItsExitStatus) {
  std::istringstream in;
  std::ostringstream out, err;
  ToolStreams streams(in, out, err);
  CommonFlags flags;
  flags.color = "never";
  ToolOutput output("sfrender", streams, flags);
  EXPECT_EQ(output.report(toolFailure(ExitCode::Usage, "--merge needs -o FILE", "name it")), 2);
  EXPECT_EQ(err.str(), "sfrender: error: --merge needs -o FILE\n  hint: name it\n");
  err.str("");
  EXPECT_EQ(output.report(fileFailure(ExitCode::IoError, "a.png", "cannot write the image: full")),
            3);
  EXPECT_EQ(err.str(), "a.png: error: cannot write the image: full\n");
  err.str("");
  EXPECT_EQ(output.report(toldFailure(ExitCode::InvalidInput)), 1);
  EXPECT_EQ(err.str(), "");
  EXPECT_EQ(output.report(toolFailure(ExitCode::OutOfResources, "out of memory")), 4);
  EXPECT_EQ(err.str(), "sfrender: error: out of memory\n");
}

}  // namespace
}  // namespace tools
