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
  ASSERT_FALSE(writeFileAtomically(dir / "f", "old"));
  ASSERT_FALSE(writeFileAtomically(dir / "f", std::string(1 << 20, 'x')));
  EXPECT_EQ(readWholeFile(dir / "f")->size(), 1u << 20);
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
  ASSERT_FALSE(writeFileAtomically(dir / "big", text));
  tools::Outcome<std::string> read = tools::readWholeFile(dir / "big");
  ASSERT_TRUE(read) << read.failure().message;
  EXPECT_TRUE(*read == text);
  tools::Outcome<std::string> cut = tools::readWholeFile(dir / "big", 30u << 20);
  ASSERT_TRUE(cut) << cut.failure().message;
  EXPECT_EQ(cut->size(), (30u << 20) + 1);
  EXPECT_TRUE(cut->compare(0, cut->size(), text, 0, cut->size()) == 0);
  fs::remove_all(dir);
}

TEST(FileIo, ReadingStopsOneBytePastTheLimit) {
  fs::path dir = fs::temp_directory_path() / ("sflimit-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "f", std::ios::binary) << std::string(200'000, 'x');
  EXPECT_EQ(readWholeFile(dir / "f", 100)->size(), 101u);
  EXPECT_EQ(readWholeFile(dir / "f", 199'999)->size(), 200'000u);
  EXPECT_EQ(readWholeFile(dir / "f", 200'000)->size(), 200'000u);
  EXPECT_EQ(readWholeFile(dir / "f")->size(), 200'000u);
  fs::remove_all(dir);
}

// The exit status is decided where the read or write fails, so that no
// caller picks one; the file is named as given, the message is the reason.
TEST(FileIo, AFailureCarriesTheStatusOfAFileThatCannotBeReadOrWritten) {
  fs::path dir = fs::temp_directory_path() / ("sffailure-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Outcome<std::string> read = readWholeFile(dir / "missing.sf");
  ASSERT_FALSE(read);
  EXPECT_EQ(read.failure().code, ExitCode::IoError);
  EXPECT_EQ(read.failure().file, (dir / "missing.sf").string());
  EXPECT_EQ(read.failure().message, "No such file or directory");
  MaybeFailure written = writeFileAtomically(dir / "missing" / "x.sf", "x");
  ASSERT_TRUE(written);
  EXPECT_EQ(written->code, ExitCode::IoError);
  EXPECT_EQ(written->file, (dir / "missing" / "x.sf").string());
  EXPECT_EQ(written->message, "its folder '" + (dir / "missing").string() + "' does not exist");
  MaybeFailure notAFile = regularFileProblem(dir);
  ASSERT_TRUE(notAFile);
  EXPECT_EQ(notAFile->code, ExitCode::IoError);
  EXPECT_EQ(notAFile->message, "it is a directory");
  fs::remove_all(dir);
}

// A file that changed since it was read is left as it is, and the new
// text goes nowhere: no temporary stays beside it.
TEST(FileIo, ReplaceIfUnchangedRefusesAFileThatChanged) {
  fs::path dir = fs::temp_directory_path() / ("sfunchanged-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  ASSERT_FALSE(writeFileAtomically(dir / "f", "as read"));
  ASSERT_FALSE(replaceFileIfUnchanged(dir / "f", "as read", "fixed"));
  EXPECT_EQ(*readWholeFile(dir / "f"), "fixed");
  MaybeFailure refused = replaceFileIfUnchanged(dir / "f", "as read", "fixed again");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->code, ExitCode::IoError);
  EXPECT_EQ(refused->message, kChangedSinceReadMessage);
  EXPECT_EQ(*readWholeFile(dir / "f"), "fixed");
  // Longer by a byte, or gone.
  EXPECT_TRUE(replaceFileIfUnchanged(dir / "f", "fixe", "x"));
  fs::remove(dir / "f");
  EXPECT_TRUE(replaceFileIfUnchanged(dir / "f", "fixed", "x"));
  EXPECT_FALSE(fs::exists(dir / "f"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tools
