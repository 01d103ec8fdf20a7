#include "tools/common/output_pattern.h"

#include <gtest/gtest.h>

namespace tools {
namespace {

TEST(OutputPattern, ExpandsEachPlaceholder) {
  std::string error;
  EXPECT_EQ(expandOutputPattern("out/{stem}.png", "scenes/a.b.sf", error), "out/a.b.png");
  EXPECT_EQ(expandOutputPattern("{dir}/{name}.ppm", "scenes/a.sf", error), "scenes/a.sf.ppm");
  EXPECT_EQ(expandOutputPattern("{dir}/{stem}-{stem}", "a.sf", error), "./a-a");
  EXPECT_EQ(expandOutputPattern("plain.png", "a.sf", error), "plain.png");
  EXPECT_FALSE(expandOutputPattern("out/{base}.png", "a.sf", error));
  EXPECT_EQ(error, "-o: '{base}' is no placeholder; use {stem}, {name} or {dir}");
  EXPECT_FALSE(expandOutputPattern("out/{stem", "a.sf", error));
}

TEST(OutputPattern, RefusesWhatCannotMakeOneFileAnInput) {
  std::string error;
  EXPECT_FALSE(batchOutputs("out.png", {"a.sf", "b.sf"}, error));
  EXPECT_EQ(error,
            "-o 'out.png' names one file for 2 inputs; give a pattern such as "
            "'out/{stem}.png'");
  EXPECT_FALSE(batchOutputs("{stem}.png", {"a.sf", "-"}, error));
  EXPECT_EQ(error, "standard input (-) cannot be one of several inputs");
  EXPECT_FALSE(batchOutputs("{stem}.png", {"x/a.sf", "y/a.sf"}, error));
  EXPECT_EQ(error, "'x/a.sf' and 'y/a.sf' would both write 'a.png'; use {dir} or {name} in -o");
  auto outputs = batchOutputs("{dir}/{stem}.png", {"x/a.sf", "y/a.sf"}, error);
  ASSERT_TRUE(outputs);
  EXPECT_EQ(*outputs, (std::vector<std::string>{"x/a.png", "y/a.png"}));
  EXPECT_EQ(batchOutputs("one.png", {"a.sf"}, error), std::vector<std::string>{"one.png"});
}

TEST(OutputPattern, SumsUp) {
  EXPECT_EQ(batchSummary("sfrender", 18, 20, "scenes rendered"),
            "sfrender: 18 of 20 scenes rendered, 2 failed");
}

}  // namespace
}  // namespace tools
