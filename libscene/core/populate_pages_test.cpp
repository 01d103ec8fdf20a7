// Faulting pages in ahead of their writes changes no byte of them.
#include "libscene/core/populate_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace scene {
namespace {

TEST(PopulatePages, WritesNothingInTheRangeOrAroundIt) {
  // Pages already written, and fresh room past them, with ends that are
  // not on page boundaries.
  std::vector<std::uint8_t> bytes;
  bytes.reserve(std::size_t{3} << 20);
  for (std::size_t i = 0; i < (std::size_t{1} << 20) + 123; ++i) {
    bytes.push_back(static_cast<std::uint8_t>(i * 7 + 1));
  }
  populatePagesForWriting(bytes.data() + 17, bytes.data() + bytes.capacity() - 5);
  populatePagesForWriting(bytes.data() + 100, bytes.data() + 50);  // empty: nothing
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    ASSERT_EQ(bytes[i], static_cast<std::uint8_t>(i * 7 + 1)) << i;
  }
  // The room past them takes writes as before.
  std::size_t written = bytes.size();
  bytes.resize(bytes.capacity(), 0xA5);
  for (std::size_t i = written; i < bytes.size(); ++i) ASSERT_EQ(bytes[i], 0xA5) << i;
}

}  // namespace
}  // namespace scene
