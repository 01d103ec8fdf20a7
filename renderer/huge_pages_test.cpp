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

}  // namespace
}  // namespace render
