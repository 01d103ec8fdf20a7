#include "renderer/parallel_parts.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace render {
namespace {

TEST(RunParts, RunsEveryPartOnceWhateverTheThreads) {
  for (std::size_t parts : {0u, 1u, 2u, 7u, 100u}) {
    for (int threads : {-1, 0, 1, 2, 3, 16}) {
      std::vector<std::atomic<int>> runs(parts);
      runParts(parts, threads, [&](std::size_t k) { ++runs[k]; });
      for (std::size_t k = 0; k < parts; ++k) {
        EXPECT_EQ(runs[k].load(), 1) << "part " << k << " of " << parts << ", " << threads;
      }
    }
  }
}

TEST(RunParts, AFailingPartStopsNoOtherAndTheFirstFailureIsRethrown) {
  std::vector<std::atomic<int>> runs(9);
  try {
    runParts(runs.size(), 3, [&](std::size_t k) {
      ++runs[k];
      if (k == 4 || k == 7) throw std::runtime_error("part " + std::to_string(k));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "part 4");
  }
  for (std::size_t k = 0; k < runs.size(); ++k) EXPECT_EQ(runs[k].load(), 1) << "part " << k;
}

TEST(ResolveThreads, ZeroOrLessMeansEveryCore) {
  EXPECT_EQ(resolveThreads(3), 3);
  EXPECT_GE(resolveThreads(0), 1);
  EXPECT_EQ(resolveThreads(-2), resolveThreads(0));
}

}  // namespace
}  // namespace render
