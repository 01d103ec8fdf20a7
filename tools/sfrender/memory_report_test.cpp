#include "tools/sfrender/memory_report.h"

#include <gtest/gtest.h>

#include <vector>

namespace tools {
namespace {

TEST(MemoryReport, SaysEachStageInMegabytesAndBytesAnObject) {
  std::vector<StageMemory> stages = {{"text", 8'000'000}, {"records", 96'000'000}};
  EXPECT_EQ(memoryReportText(stages, 290'000'000, 1'000'000),
            "held at most: text 8.0 MB (8 B/object), records 96.0 MB (96 B/object); peak "
            "resident 290.0 MB (290 B/object)");
  // No objects: by one, not by zero.
  EXPECT_EQ(memoryReportText({}, 1'000'000, 0),
            "held at most:; peak resident 1.0 MB (1000000 B/object)");
}

TEST(MemoryReport, ThePeakIsAtLeastWhatThisProcessTouched) {
  std::vector<char> touched(64 << 20, 1);
  EXPECT_GE(peakResidentBytes(), touched.size());
}

}  // namespace
}  // namespace tools
