#include "tools/common/file_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace tools {
namespace {

namespace fs = std::filesystem;

TEST(FileIo, AtomicWriteReplacesWholeAndLeavesNoTemporary) {
  fs::path dir = fs::temp_directory_path() / ("sfatomic-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string error;
  ASSERT_TRUE(writeFileAtomically(dir / "f", "old", error)) << error;
  ASSERT_TRUE(writeFileAtomically(dir / "f", std::string(1 << 20, 'x'), error)) << error;
  EXPECT_EQ(readWholeFile(dir / "f", error)->size(), 1u << 20);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

// A file big enough that the later half of its buffer is faulted in on a
// thread of its own while the first half is read comes back byte for byte,
// and so does one cut short by the byte limit.
TEST(FileIo, ABigFileIsReadWholeWhileItsLaterPagesAreFaultedIn) {
  fs::path dir = fs::temp_directory_path() / ("sfbigread-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string text(40u << 20, '\0');
  for (std::size_t i = 0; i < text.size(); ++i) text[i] = static_cast<char>('a' + (i * 7919) % 26);
  std::string error;
  ASSERT_TRUE(writeFileAtomically(dir / "big", text, error)) << error;
  std::optional<std::string> read = readWholeFile(dir / "big", error);
  ASSERT_TRUE(read.has_value()) << error;
  EXPECT_TRUE(*read == text);
  std::optional<std::string> cut = readWholeFile(dir / "big", error, 30u << 20);
  ASSERT_TRUE(cut.has_value()) << error;
  EXPECT_EQ(cut->size(), (30u << 20) + 1);
  EXPECT_TRUE(cut->compare(0, cut->size(), text, 0, cut->size()) == 0);
  fs::remove_all(dir);
}

TEST(FileIo, ReadingStopsOneBytePastTheLimit) {
  fs::path dir = fs::temp_directory_path() / ("sflimit-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "f", std::ios::binary) << std::string(200'000, 'x');
  std::string error;
  EXPECT_EQ(readWholeFile(dir / "f", error, 100)->size(), 101u);
  EXPECT_EQ(readWholeFile(dir / "f", error, 199'999)->size(), 200'000u);
  EXPECT_EQ(readWholeFile(dir / "f", error, 200'000)->size(), 200'000u);
  EXPECT_EQ(readWholeFile(dir / "f", error)->size(), 200'000u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tools
