#include "tools/common/terminal_style.h"

#include <gtest/gtest.h>

#include <sstream>

#include "tools/common/tool_streams.h"

namespace tools {
namespace {

// --color auto colours a terminal only, and not under a set NO_COLOR or
// TERM=dumb; always and never hold whatever the stream and the environment.
TEST(TerminalStyle, ColourIsForATerminalUnlessTheFlagOrTheEnvironmentSaysOtherwise) {
  std::istringstream in;
  std::ostringstream out, err;
  ToolStreams streams(in, out, err);
  EXPECT_TRUE(useColor(ColorMode::Auto, true, streams));
  EXPECT_FALSE(useColor(ColorMode::Auto, false, streams));
  EXPECT_TRUE(useColor(ColorMode::Always, false, streams));
  streams.noColor = "";
  EXPECT_TRUE(useColor(ColorMode::Auto, true, streams));  // set but empty: no effect
  streams.noColor = "1";
  EXPECT_FALSE(useColor(ColorMode::Auto, true, streams));
  EXPECT_TRUE(useColor(ColorMode::Always, true, streams));
  streams.noColor.reset();
  streams.term = "dumb";
  EXPECT_FALSE(useColor(ColorMode::Auto, true, streams));
  EXPECT_FALSE(useColor(ColorMode::Never, true, ToolStreams(in, out, err)));
  EXPECT_EQ(colorModeFromName("always"), ColorMode::Always);
  EXPECT_EQ(colorModeFromName("yes"), std::nullopt);
}

TEST(TerminalStyle, PaintsOnlyWhenEnabled) {
  EXPECT_EQ(TerminalStyle(true).severity(scene::Severity::Error, "error:"),
            "\x1b[1;31merror:\x1b[0m");
  EXPECT_EQ(TerminalStyle(true).location(""), "");
  EXPECT_EQ(TerminalStyle(false).severity(scene::Severity::Warning, "warning:"), "warning:");
}

}  // namespace
}  // namespace tools
