#include "tools/sfrender/thread_probe.h"

#include <gtest/gtest.h>

#include <optional>

namespace tools {
namespace {

TEST(ThreadProbe, StartsTheThreadsItIsAskedFor) {
  EXPECT_FALSE(threadStartFailure(1));
  EXPECT_FALSE(threadStartFailure(64));
  EXPECT_GE(renderThreadCount(0), 1);
  EXPECT_EQ(renderThreadCount(7), 7);
}

}  // namespace
}  // namespace tools
