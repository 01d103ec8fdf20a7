#include "tools/sfls/document.h"

#include <gtest/gtest.h>

#include <random>

namespace sfls {
namespace {

TEST(Document, IndexesLinesWithAnyEnding) {
  Document document("file:///a.sf", 1, "one\r\ntwo\n\nthree");
  EXPECT_EQ(document.lineCount(), 4u);
  EXPECT_EQ(document.lineText(0), "one");
  EXPECT_EQ(document.lineText(1), "two");
  EXPECT_EQ(document.lineText(2), "");
  EXPECT_EQ(document.lineText(3), "three");
  EXPECT_EQ(document.lineOffset(3), 10u);
  EXPECT_EQ(document.lineOffset(9), document.text().size());
}

TEST(Document, CountsUtf16UnitsOfEachCodePoint) {
  // é is 2 bytes and 1 unit, 😀 4 bytes and 2 units.
  Document document("file:///a.sf", 1, "é😀x\n");
  EXPECT_EQ(document.toLsp(1, 1), (LspPosition{0, 0}));
  EXPECT_EQ(document.toLsp(1, 3), (LspPosition{0, 1}));
  EXPECT_EQ(document.toLsp(1, 7), (LspPosition{0, 3}));
  EXPECT_EQ(document.toLsp(1, 8), (LspPosition{0, 4}));
  EXPECT_EQ(document.toSource({0, 3}).column, 7u);
  EXPECT_EQ(document.toSource({0, 4}).column, 8u);
  // Inside the surrogate pair: the pair's start.
  EXPECT_EQ(document.toSource({0, 2}).column, 3u);
  // Past the line's end: its end.
  EXPECT_EQ(document.toSource({0, 99}).column, 8u);
}

// The library counts the first line's columns after a byte-order mark; the
// protocol counts the mark, U+FEFF, as one character.
TEST(Document, CountsTheFirstLinesColumnsAfterAByteOrderMark) {
  Document document("file:///a.sf", 1,
                    "\xEF\xBB\xBF"
                    "camera\ncamera\n");
  EXPECT_EQ(document.toLsp(scene::SourceSpan{1, 1, 6}), (LspRange{{0, 1}, {0, 7}}));
  EXPECT_EQ(document.toLsp(scene::SourceSpan{2, 1, 6}), (LspRange{{1, 0}, {1, 6}}));
  EXPECT_EQ(document.toSource({0, 1}).column, 1u);
  EXPECT_EQ(document.toSource({0, 0}).column, 1u);
  EXPECT_EQ(document.toSource({0, 7}).column, 7u);
  EXPECT_EQ(document.toSource({1, 0}).column, 1u);
  EXPECT_EQ(document.offsetOf({0, 1}), 3u);
}

TEST(Document, CountsEachInvalidByteAsOneUnit) {
  // A stray continuation byte, an overlong '/', a sequence cut short.
  Document document("file:///a.sf", 1, "\x80\xC0\xAF\xE2\x82x");
  EXPECT_EQ(document.toLsp(1, 7), (LspPosition{0, 6}));
  EXPECT_EQ(document.toSource({0, 5}).column, 6u);
}

TEST(Document, MapsSpansAndUnknownSpans) {
  Document document("file:///a.sf", 1, "SPHERE\n1 2 3\n");
  EXPECT_EQ(document.toLsp(scene::SourceSpan{2, 3, 1}), (LspRange{{1, 2}, {1, 3}}));
  EXPECT_EQ(document.toLsp(scene::SourceSpan{2, 6, 0}), (LspRange{{1, 5}, {1, 5}}));
  EXPECT_EQ(document.toLsp(scene::SourceSpan{}), (LspRange{}));
}

TEST(Document, AppliesFullAndIncrementalChanges) {
  Document document("file:///a.sf", 1, "abc\ndef\nghi\n");
  document.applyChange(LspRange{{0, 1}, {1, 2}}, "X\nY\nZ");
  EXPECT_EQ(document.text(), "aX\nY\nZf\nghi\n");
  EXPECT_EQ(document.lineCount(), 5u);
  EXPECT_EQ(document.lineText(2), "Zf");
  EXPECT_EQ(document.lineText(3), "ghi");
  document.applyChange(LspRange{{1, 0}, {3, 0}}, "");
  EXPECT_EQ(document.text(), "aX\nghi\n");
  EXPECT_EQ(document.lineCount(), 3u);
  EXPECT_EQ(document.lineText(1), "ghi");
  document.applyChange(std::nullopt, "whole");
  EXPECT_EQ(document.text(), "whole");
  EXPECT_EQ(document.lineCount(), 1u);
}

TEST(Document, ClampsRangesPastTheEnd) {
  Document document("file:///a.sf", 1, "ab\ncd");
  document.applyChange(LspRange{{1, 1}, {40, 3}}, "!\n");
  EXPECT_EQ(document.text(), "ab\nc!\n");
  EXPECT_EQ(document.lineCount(), 3u);
  document.applyChange(LspRange{{9, 0}, {9, 0}}, "end");
  EXPECT_EQ(document.text(), "ab\nc!\nend");
}

TEST(Document, LeavesASharedTextAsItWas) {
  Document document("file:///a.sf", 1, "old");
  std::shared_ptr<const std::string> shared = document.sharedText();
  document.applyChange(LspRange{{0, 0}, {0, 3}}, "new");
  EXPECT_EQ(*shared, "old");
  EXPECT_EQ(document.text(), "new");
  document.applyChange(std::nullopt, "whole");
  EXPECT_EQ(*shared, "old");
  EXPECT_EQ(document.text(), "whole");
}

TEST(Document, EditsATextNoOneSharesInPlace) {
  Document document("file:///a.sf", 1, "abc\ndef");
  const std::string* before = &document.text();
  document.applyChange(LspRange{{1, 0}, {1, 1}}, "D");
  EXPECT_EQ(&document.text(), before);
  EXPECT_EQ(document.text(), "abc\nDef");
}

// Random edits, some across lines, some past the end, in text with
// multi-byte characters: the lines indexed edit by edit are those of the
// text indexed afresh, and the text is what the offsets of a fresh index say.
TEST(Document, IndexesLinesEditByEditAsAfresh) {
  std::mt19937 random(7);
  const std::vector<std::string> pieces = {"a", "\n", "\r\n", "é", "😀", "", "xy\nz", "\n\n"};
  auto pick = [&](std::size_t n) { return static_cast<std::uint32_t>(random() % n); };
  Document document("file:///a.sf", 1, "first\nsecond é\n\nthird😀\n");
  for (int i = 0; i < 2000; ++i) {
    LspPosition a{pick(document.lineCount() + 1), pick(12)};
    LspPosition b{pick(document.lineCount() + 1), pick(12)};
    if (b.line < a.line || (b.line == a.line && b.character < a.character)) std::swap(a, b);
    std::string inserted = pieces[pick(pieces.size())] + pieces[pick(pieces.size())];
    Document fresh("file:///a.sf", 1, document.text());
    std::string expected = document.text();
    std::size_t start = fresh.offsetOf(a);
    std::size_t end = std::max(start, fresh.offsetOf(b));
    expected.replace(start, end - start, inserted);
    std::shared_ptr<const std::string> holder;
    if (i % 3 == 0) holder = document.sharedText();  // the copying path too
    document.applyChange(LspRange{a, b}, inserted);
    ASSERT_EQ(document.text(), expected) << "edit " << i;
    Document afresh("file:///a.sf", 1, expected);
    ASSERT_EQ(document.lineCount(), afresh.lineCount()) << "edit " << i;
    for (std::uint32_t line = 0; line < afresh.lineCount(); ++line) {
      ASSERT_EQ(document.lineOffset(line), afresh.lineOffset(line)) << "edit " << i;
    }
  }
}

}  // namespace
}  // namespace sfls
