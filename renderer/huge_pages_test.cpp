// Advice for huge pages changes no byte of the memory it is given, written
// or not, nor around it.
#include "renderer/huge_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace render {
namespace {

TEST(HugePages, AdviceChangesNoByteInTheRangeOrAroundIt) {
  // Several huge pages' worth, written in part, the range's ends off any
  // page boundary, and fresh room past the writes.
  std::vector<std::uint8_t> bytes;
  bytes.reserve(5 * kHugePageBytes);
  for (std::size_t i = 0; i < 2 * kHugePageBytes + 123; ++i) {
    bytes.push_back(static_cast<std::uint8_t>(i * 7 + 1));
  }
  adviseHugePages(bytes.data() + 17, bytes.data() + bytes.capacity() - 5);
  adviseHugePages(bytes.data() + 100, bytes.data() + 50);  // empty: nothing
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    ASSERT_EQ(bytes[i], static_cast<std::uint8_t>(i * 7 + 1)) << i;
  }
  // The room past them takes writes as before.
  std::size_t written = bytes.size();
  bytes.resize(bytes.capacity(), 0xA5);
  for (std::size_t i = written; i < bytes.size(); ++i) ASSERT_EQ(bytes[i], 0xA5) << i;
}

TEST(HugePageAllocator, BigArraysStartOnAHugePageAndHoldWhatIsWrittenAsSmallOnesDo) {
  // Below half a huge page, at it, past one huge page and a half, and
  // grown through those sizes by push_back.
  for (std::size_t count : {std::size_t{1000}, kHugePageBytes / 2 / sizeof(double),
                            3 * kHugePageBytes / 2 / sizeof(double) + 7}) {
    std::vector<double, HugePageAllocator<double>> values(count, 0.5);
    bool big = kHugePagesAdvised && count * sizeof(double) >= kHugePageBytes / 2;
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values.data()) % kHugePageBytes == 0, big) << count;
    for (std::size_t i = 0; i < count; ++i) values[i] = static_cast<double>(i) * 0.25;
    for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(values[i], static_cast<double>(i) * 0.25);
  }
  std::vector<std::uint32_t, HugePageAllocator<std::uint32_t>> grown;
  for (std::uint32_t i = 0; i < kHugePageBytes; ++i) grown.push_back(i ^ 0x5a5a5a5au);
  for (std::uint32_t i = 0; i < kHugePageBytes; ++i) ASSERT_EQ(grown[i], i ^ 0x5a5a5a5au);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(grown.data()) % kHugePageBytes == 0,
            kHugePagesAdvised);
  EXPECT_TRUE(HugePageAllocator<int>() == HugePageAllocator<double>());
}

}  // namespace
}  // namespace render
