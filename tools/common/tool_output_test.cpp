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

// A clean run is quiet: notes print with --verbose only, warnings unless
// --quiet, errors always.
TEST(ToolOutput, NotesPrintOnlyWhenVerbose) {
  scene::DiagnosticList list("a.sf");
  list.note(scene::DiagnosticCode::CameraFov, {}, "decided");
  list.warning(scene::DiagnosticCode::NoLight, {}, "lost");
  list.error(scene::DiagnosticCode::UnknownFormat, {}, "wrong");
  auto shown = [&](CommonFlags flags) {
    std::istringstream in;
    std::ostringstream out, err;
    ToolStreams streams(in, out, err);
    flags.color = "never";
    ToolOutput output("sfcheck", streams, flags);
    DiagnosticPrinter(err, output.diagnosticStyle(DiagnosticFormat::Short)).print(list);
    return err.str();
  };
  const std::string note = "a.sf: note: decided [camera-fov]\n";
  const std::string warning = "a.sf: warning: lost [no-light]\n";
  const std::string error = "a.sf: error: wrong [unknown-format]\n";
  EXPECT_EQ(shown(CommonFlags{}), warning + error);
  EXPECT_EQ(shown(CommonFlags{.quiet = false, .verbose = true}), note + warning + error);
  EXPECT_EQ(shown(CommonFlags{.quiet = true}), error);
}

}  // namespace
}  // namespace tools
