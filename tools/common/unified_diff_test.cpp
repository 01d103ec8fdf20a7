#include "tools/common/unified_diff.h"

#include <gtest/gtest.h>

#include <string>

namespace tools {
namespace {

// Lines "1\n" to "N\n".
std::string numbered(int n) {
  std::string text;
  for (int i = 1; i <= n; ++i) text += std::to_string(i) + "\n";
  return text;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

TEST(UnifiedDiff, EqualTextsHaveNone) {
  EXPECT_EQ(unifiedDiff("a\nb\n", "a\nb\n", "f"), "");
  EXPECT_EQ(unifiedDiff("", "", "f"), "");
}

TEST(UnifiedDiff, OneLineWithThreeLinesAroundAsDiffPrintsIt) {
  EXPECT_EQ(unifiedDiff(numbered(10), replaced(numbered(10), "5\n", "five\n"), "x.sf"),
            "--- a/x.sf\n+++ b/x.sf\n@@ -2,7 +2,7 @@\n 2\n 3\n 4\n-5\n+five\n 6\n 7\n 8\n");
}

TEST(UnifiedDiff, ChangesFarApartAreTwoHunksAndNearOnesOne) {
  std::string after = replaced(replaced(numbered(20), "2\n", "two\n"), "19\n", "nineteen\n");
  EXPECT_EQ(unifiedDiff(numbered(20), after, "f"),
            "--- a/f\n+++ b/f\n"
            "@@ -1,5 +1,5 @@\n 1\n-2\n+two\n 3\n 4\n 5\n"
            "@@ -16,5 +16,5 @@\n 16\n 17\n 18\n-19\n+nineteen\n 20\n");
  // Six lines apart: the contexts touch, one hunk.
  after = replaced(replaced(numbered(20), "\n5\n", "\nfive\n"), "12\n", "twelve\n");
  EXPECT_EQ(unifiedDiff(numbered(20), after, "f"),
            "--- a/f\n+++ b/f\n@@ -2,14 +2,14 @@\n 2\n 3\n 4\n-5\n+five\n 6\n 7\n 8\n 9\n 10\n "
            "11\n-12\n+twelve\n 13\n 14\n 15\n");
}

TEST(UnifiedDiff, LinesAddedAndRemoved) {
  EXPECT_EQ(unifiedDiff("a\nb\n", "a\nb\nc\n", "f"),
            "--- a/f\n+++ b/f\n@@ -1,2 +1,3 @@\n a\n b\n+c\n");
  EXPECT_EQ(unifiedDiff("a\nb\nc\n", "a\nc\n", "f"),
            "--- a/f\n+++ b/f\n@@ -1,3 +1,2 @@\n a\n-b\n c\n");
  // An empty side starts at the line before it, as GNU diff writes it.
  EXPECT_EQ(unifiedDiff("", "a\n", "f"), "--- a/f\n+++ b/f\n@@ -0,0 +1 @@\n+a\n");
}

TEST(UnifiedDiff, ALastLineWithoutNewlineIsMarked) {
  EXPECT_EQ(unifiedDiff("a\nb", "a\nc", "f"),
            "--- a/f\n+++ b/f\n@@ -1,2 +1,2 @@\n a\n-b\n\\ No newline at end of file\n+c\n"
            "\\ No newline at end of file\n");
  EXPECT_EQ(unifiedDiff("a\nb", "a\nb\n", "f"),
            "--- a/f\n+++ b/f\n@@ -1,2 +1,2 @@\n a\n-b\n\\ No newline at end of file\n+b\n");
}

// Repeated lines (a scene file's matrix rows) do not make the texts meet
// again at the wrong place: one line changed is one line in the diff.
TEST(UnifiedDiff, RepeatedLinesDoNotMisplaceAChange) {
  std::string block = "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  std::string before = block + block + block;
  std::string after = block + replaced(block, "SPHERE", "CUBE") + block;
  EXPECT_EQ(unifiedDiff(before, after, "f"),
            "--- a/f\n+++ b/f\n@@ -4,7 +4,7 @@\n 0 1 0 0\n 0 0 1 0\n 0 0 0 1\n-SPHERE\n+CUBE\n"
            " 1 0 0\n 1 0 0 0\n 0 1 0 0\n");
}

}  // namespace
}  // namespace tools
