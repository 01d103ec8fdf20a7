// The shared lexical layer: the first word a line format is detected by, and
// lines and columns from byte offsets.
#include "libscene/text/text_lines.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace scene {
namespace {

TEST(FirstWordOutsideComments, SkipsBlankAndCommentLines) {
  EXPECT_EQ(firstWordOutsideComments("\n \t\n# note\n// note\n  CAMERA 1 2\n"), "CAMERA");
  EXPECT_EQ(firstWordOutsideComments("\xEF\xBB\xBF\tSTART\r\n"), "START");
  EXPECT_EQ(firstWordOutsideComments("#x\n\n"), std::nullopt);
  EXPECT_EQ(firstWordOutsideComments(""), std::nullopt);
  // A word is what stands between blanks, bytes that are not ASCII included.
  EXPECT_EQ(firstWordOutsideComments("ab\x01\xC3 cd"), "ab\x01\xC3");
}

TEST(FirstWordOutsideComments, AgreesWithTheTokensOfTheLine) {
  std::mt19937 random(7);
  const std::string alphabet = " \t\n#/aZ\x01\xFF";
  for (int round = 0; round < 2000; ++round) {
    std::string text;
    for (int i = random() % 24; i > 0; --i) text += alphabet[random() % alphabet.size()];
    std::optional<std::string_view> expected;
    LineCursor cursor(text);
    while (cursor.next()) {
      if (cursor.blank()) continue;
      std::string_view first = cursor.token(0).text;
      if (first.starts_with("#") || first.starts_with("//")) continue;
      expected = first;
      break;
    }
    EXPECT_EQ(firstWordOutsideComments(text), expected) << "text: " << text;
  }
}

// Counted one byte at a time, as the definition says.
SourceSpan spanByCounting(std::string_view text, std::size_t byte) {
  SourceSpan span{1, 1, 0};
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++span.line;
      span.column = 1;
    } else {
      ++span.column;
    }
  }
  return span;
}

TEST(LineColumnCounter, AgreesWithCountingByteByByteInAnyOrder) {
  std::mt19937 random(11);
  for (int round = 0; round < 200; ++round) {
    std::string text;
    for (int i = random() % 300; i > 0; --i) text += random() % 5 == 0 ? '\n' : 'x';
    LineColumnCounter counter(text);
    for (int ask = 0; ask < 20; ++ask) {
      // Mostly forward, sometimes back, sometimes past the end.
      std::size_t byte = random() % (text.size() + 10);
      SourceSpan span = counter.at(byte);
      SourceSpan expected = spanByCounting(text, byte);
      EXPECT_EQ(span.line, expected.line) << "byte " << byte << " of " << text.size();
      EXPECT_EQ(span.column, expected.column) << "byte " << byte << " of " << text.size();
      EXPECT_EQ(span.length, 0u);
    }
  }
}

}  // namespace
}  // namespace scene
