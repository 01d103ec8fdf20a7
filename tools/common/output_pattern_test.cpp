#include "tools/common/output_pattern.h"

#include <gtest/gtest.h>

namespace tools {
namespace {

// The usage failure's message; empty when the pattern expands.
template <class T>
std::string refusal(const Outcome<T>& outcome) {
  if (outcome) return "";
  EXPECT_EQ(outcome.failure().code, ExitCode::Usage);
  return outcome.failure().message;
}

TEST(OutputPattern, ExpandsEachPlaceholder) {
  std::string error;
  EXPECT_EQ(expandOutputPattern("out/{stem}.png", "scenes/a.b.sf"), "out/a.b.png");
  EXPECT_EQ(expandOutputPattern("{dir}/{name}.ppm", "scenes/a.sf"), "scenes/a.sf.ppm");
  EXPECT_EQ(expandOutputPattern("{dir}/{stem}-{stem}", "a.sf"), "./a-a");
  EXPECT_EQ(expandOutputPattern("plain.png", "a.sf"), "plain.png");
  error = refusal(expandOutputPattern("out/{base}.png", "a.sf"));
  EXPECT_EQ(error, "-o: '{base}' is no placeholder; use {stem}, {name} or {dir}");
  EXPECT_NE(refusal(expandOutputPattern("out/{stem", "a.sf")), "");
}

TEST(OutputPattern, RefusesWhatCannotMakeOneFileAnInput) {
  std::string error;
  error = refusal(batchOutputs("out.png", {"a.sf", "b.sf"}));
  EXPECT_EQ(error,
            "-o 'out.png' names one file for 2 inputs; give a pattern such as "
            "'out/{stem}.png'");
  error = refusal(batchOutputs("{stem}.png", {"a.sf", "-"}));
  EXPECT_EQ(error, "standard input (-) cannot be one of several inputs");
  error = refusal(batchOutputs("{stem}.png", {"-", "-"}));
  EXPECT_EQ(error, "standard input (-) cannot be one of several inputs");
  EXPECT_EQ(batchInputsRefusal({"a.sf", "b.sf", "-"}).value_or(ToolFailure{}).message,
            "standard input (-) cannot be one of several inputs");
  EXPECT_FALSE(batchInputsRefusal({"-"}));
  // Two inputs onto one output are output_plan.h's to find.
  EXPECT_EQ(batchOutputs("{stem}.png", {"x/a.sf", "y/a.sf"}),
            (std::vector<std::string>{"a.png", "a.png"}));
  auto outputs = batchOutputs("{dir}/{stem}.png", {"x/a.sf", "y/a.sf"});
  ASSERT_TRUE(outputs);
  EXPECT_EQ(*outputs, (std::vector<std::string>{"x/a.png", "y/a.png"}));
  EXPECT_EQ(batchOutputs("one.png", {"a.sf"}), std::vector<std::string>{"one.png"});
}

TEST(OutputPattern, NoPlaceholderBecomesAPathStep) {
  std::string error;
  for (const char* input : {"...sf", "x/...sf", "..sf", "...", "x/..", "x/.", "x/", "."}) {
    error = refusal(expandOutputPattern("out/sub/{stem}/x.ppm", input));
    EXPECT_NE(error.find("which is no file name"), std::string::npos) << error;
  }
  for (const char* input : {"x/..", "x/.", "x/", ".", ".."}) {
    EXPECT_NE(error = refusal(expandOutputPattern("out/{name}.sf", input)), "") << input;
  }
  EXPECT_EQ(error,
            "-o: {name} of '..' would be '..', which is no file name (a placeholder never expands "
            "to nothing, '.' or '..'); rename the input or use another placeholder");
  // Dots that are names.
  EXPECT_EQ(expandOutputPattern("out/{name}.sf", "..."), "out/....sf");
  EXPECT_EQ(expandOutputPattern("out/{stem}.sf", ".sf"), "out/.sf.sf");
  EXPECT_EQ(expandOutputPattern("out/{stem}.sf", "a..sf"), "out/a..sf");
  EXPECT_EQ(expandOutputPattern("out/{stem}.sf", "new\nline.sf"), "out/new\nline.sf");
  // {dir} climbs only where it begins the pattern.
  EXPECT_EQ(expandOutputPattern("{dir}/{stem}.png", "../x/a.sf"), "../x/a.png");
  EXPECT_EQ(expandOutputPattern("out/{dir}/{stem}.png", "/abs/a.sf"), "out//abs/a.png");
  for (const char* input : {"../a.sf", "x/../a.sf", "x/../../a.sf", "../../a.sf"}) {
    EXPECT_NE(error = refusal(expandOutputPattern("out/{dir}/{stem}.png", input)), "") << input;
    EXPECT_NE(error = refusal(expandOutputPattern("x{dir}/{stem}.png", input)), "") << input;
  }
  EXPECT_EQ(error,
            "-o: {dir} of '../../a.sf' is '../..': after the pattern's own folder, {dir} may not "
            "hold '..', which could climb out of it; start the pattern with {dir} to write beside "
            "the input");
}

TEST(OutputPattern, StandardInputHasNoName) {
  std::string error;
  for (const char* pattern : {"out/{stem}.png", "{name}.png", "{dir}/x.png"}) {
    error = refusal(expandOutputPattern(pattern, "-"));
    EXPECT_NE(error.find("standard input has no name"), std::string::npos) << error;
  }
  EXPECT_EQ(expandOutputPattern("out/x.png", "-"), "out/x.png");
}

TEST(OutputPattern, SumsUp) {
  EXPECT_EQ(batchSummary("sfrender", 18, 20, "scenes rendered"),
            "sfrender: 18 of 20 scenes rendered, 2 failed");
}

}  // namespace
}  // namespace tools
