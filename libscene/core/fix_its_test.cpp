#include "scenefile/fix_its.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

using scene::testing::readText;

FixIt fix(std::uint32_t line, std::uint32_t column, std::uint32_t length, std::string text) {
  return FixIt{SourceSpan{line, column, length}, std::move(text)};
}

TEST(ApplyFixIts, ReplacesEachSpanOnItsLine) {
  std::vector<FixIt> fixIts = {fix(1, 1, 6, "CAMERA"), fix(3, 3, 1, "7"), fix(3, 6, 0, " 8")};
  EXPECT_EQ(applyFixIts("camera\n0 0 0\n1 2 3\n", fixIts), "CAMERA\n0 0 0\n1 7 3 8\n");
}

TEST(ApplyFixIts, KeepsCrlfAndCountsColumnsAfterTheByteOrderMark) {
  std::vector<FixIt> fixIts = {fix(1, 1, 6, "CAMERA"), fix(2, 3, 1, "9")};
  EXPECT_EQ(applyFixIts("\xEF\xBB\xBF"
                        "camera\r\n0 0 0\r\n",
                        fixIts),
            "\xEF\xBB\xBF"
            "CAMERA\r\n0 9 0\r\n");
}

TEST(ApplyFixIts, LeavesOutASpanPastItsLineOrTheText) {
  std::vector<FixIt> fixIts = {fix(1, 2, 3, "x"),   // past the end of "ab"
                               fix(1, 3, 0, "c"),   // at the end: an insertion
                               fix(2, 1, 2, "y"),   // over the CR and the newline
                               fix(9, 1, 1, "z")};  // no such line
  EXPECT_EQ(applyFixIts("ab\r\n\r\n", fixIts), "abc\r\n\r\n");
  EXPECT_EQ(applyFixIts("", fixIts), "");
}

TEST(ApplicableFixIts, SortsThemAndDropsOnesThatOverlap) {
  DiagnosticList list;
  list.error(DiagnosticCode::UnknownKeyword, {3, 1, 4}, "a").fixIt = fix(3, 1, 4, "LATER");
  list.error(DiagnosticCode::UnknownKeyword, {1, 1, 4}, "b").fixIt = fix(1, 1, 4, "FIRST");
  list.error(DiagnosticCode::UnknownKeyword, {3, 4, 2}, "c").fixIt = fix(3, 4, 2, "CLASH");
  list.error(DiagnosticCode::UnknownKeyword, {3, 5, 0}, "d").fixIt = fix(3, 5, 0, "TOUCH");
  list.error(DiagnosticCode::UnknownKeyword, {2, 1, 1}, "no fix-it");
  std::vector<FixIt> expected = {fix(1, 1, 4, "FIRST"), fix(3, 1, 4, "LATER"),
                                 fix(3, 5, 0, "TOUCH")};
  EXPECT_EQ(applicableFixIts(list), expected);
}

// The fix-its the readers propose, applied, leave a text in which the
// problems they fixed are gone.
TEST(ApplyFixIts, TheReadersFixItsFixWhatTheyReport) {
  const char* files[] = {"bom-then-lower-case-camera.sf",
                         "lower-case-keywords.sf",
                         "lower-case-keywords.txt",
                         "unknown-record-name.sf",
                         "unknown-object-kind.txt",
                         "lower-case-and-unknown-sections.txt",
                         "unknown-keywords-outside-properties.txt"};
  for (const char* name : files) {
    SCOPED_TRACE(name);
    std::string text = readText(std::filesystem::path(SCENE_TESTDATA_DIR) / "invalid" / name);
    ReadResult before = parseScene(text, name);
    std::vector<FixIt> fixIts = applicableFixIts(before.diagnostics);
    ASSERT_FALSE(fixIts.empty());
    std::string fixed = applyFixIts(text, fixIts);
    ReadResult after = parseScene(fixed, name);
    for (const Diagnostic& d : after.diagnostics.items()) {
      EXPECT_FALSE(d.fixIt) << d.span.line << ":" << d.span.column << " " << d.message;
    }
    EXPECT_LT(after.diagnostics.errorCount(), before.diagnostics.errorCount());
    // Applying nothing more changes nothing.
    EXPECT_EQ(applyFixIts(fixed, applicableFixIts(after.diagnostics)), fixed);
  }
}

}  // namespace
}  // namespace scene
