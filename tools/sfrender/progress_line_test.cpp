#include "tools/sfrender/progress_line.h"

#include <gtest/gtest.h>

#include <sstream>

namespace tools {
namespace {

TEST(ProgressLine, ClockTextIsMinutesAndSecondsThenHours) {
  EXPECT_EQ(clockText(0), "0:00");
  EXPECT_EQ(clockText(7.9), "0:07");
  EXPECT_EQ(clockText(754), "12:34");
  EXPECT_EQ(clockText(3723), "1:02:03");
  EXPECT_EQ(clockText(-1), "0:00");
  EXPECT_EQ(clockText(1.0 / 0.0), "0:00");
}

// The time left is the elapsed time scaled by the share left over the share
// done.
TEST(ProgressLine, SaysTheShareTheTimeTakenAndTheTimeLeft) {
  EXPECT_EQ(progressText(43, 100, 1.5), "sfrender: rendering  43%, 0:01 elapsed, 0:01 left");
  EXPECT_EQ(progressText(25, 100, 10), "sfrender: rendering  25%, 0:10 elapsed, 0:30 left");
  EXPECT_EQ(progressText(1, 1000, 2), "sfrender: rendering   0%, 0:02 elapsed, 33:18 left");
  EXPECT_EQ(progressText(100, 100, 61), "sfrender: rendering 100%, 1:01 elapsed");
  // Within the first second there is no estimate yet.
  EXPECT_EQ(progressText(1, 100, 0.5), "sfrender: rendering   1%, 0:00 elapsed");
}

TEST(ProgressLine, RewritesOneLineAndEndsItOnceDone) {
  std::ostringstream out;
  ProgressLine line(out);
  line.update(1, 4, 3723);
  line.update(1, 4, 3723.2);  // the same text: not written again
  line.update(2, 4, 4000);
  line.update(1, 4, 4000.5);  // reported late by its thread: not written
  line.update(4, 4, 4001);
  EXPECT_EQ(out.str(),
            "\rsfrender: rendering  25%, 1:02:03 elapsed, 3:06:09 left"
            "\rsfrender: rendering  50%, 1:06:40 elapsed, 1:06:40 left"
            "\rsfrender: rendering 100%, 1:06:41 elapsed" +
                std::string(14, ' ') + "\n");
}

}  // namespace
}  // namespace tools
