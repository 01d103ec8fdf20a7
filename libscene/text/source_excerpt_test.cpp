// The quoted source line under a diagnostic: the caret under the span's
// bytes whatever stands before them, and long, binary and odd lines.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "libscene/text/source_quote.h"

namespace scene {
namespace {

// The quote of `span` in `text`, as the printer shows it, or nothing.
std::vector<std::string> quote(const std::string& text, SourceSpan span,
                               const FixIt* fixIt = nullptr) {
  DiagnosticList list("f.sf");
  Diagnostic& d = list.error(DiagnosticCode::InvalidNumber, span, "m");
  if (fixIt) d.fixIt = *fixIt;
  SourceExcerpts excerpts;
  excerpts.capture("f.sf", text, list);
  const SourceLine* line = excerpts.find("f.sf", span);
  if (!line) return {};
  return quoteSourceLine(*line, span, fixIt, TerminalPaint(false));
}

TEST(SourceExcerpt, UnderlinesTheSpanOnItsLine) {
  EXPECT_EQ(quote("CAMERA\n0 0 nan\n", {2, 5, 3}),
            (std::vector<std::string>{"    2 | 0 0 nan", "      |     ^~~"}));
  // A span of no length points between characters: one caret.
  EXPECT_EQ(quote("a\nLOCATION 0 1\n", {2, 13, 0}),
            (std::vector<std::string>{"    2 | LOCATION 0 1", "      |             ^"}));
}

TEST(SourceExcerpt, KeepsTheCaretUnderTheByteAfterTabsAndEscapes) {
  // A tab is shown as spaces to the next multiple of 8.
  EXPECT_EQ(quote("1\t2 x\n", {1, 5, 1}),
            (std::vector<std::string>{"    1 | 1       2 x", "      |           ^"}));
  // A control byte is shown as \xNN, four columns wide.
  EXPECT_EQ(quote("a\x01 bad\n", {1, 4, 3}),
            (std::vector<std::string>{"    1 | a\\x01 bad", "      |       ^~~"}));
  // A UTF-8 character is one column.
  EXPECT_EQ(quote("\xC3\xA9 bad\n", {1, 4, 3}),
            (std::vector<std::string>{"    1 | \xC3\xA9 bad", "      |   ^~~"}));
}

TEST(SourceExcerpt, LineEndsAndTheByteOrderMarkAreNotShown) {
  EXPECT_EQ(quote("CAMERA\r\nx y\r\n", {2, 3, 1}),
            (std::vector<std::string>{"    2 | x y", "      |   ^"}));
  EXPECT_EQ(quote("\xEF\xBB\xBF"
                  "camera\n",
                  {1, 1, 6}),
            (std::vector<std::string>{"    1 | camera", "      | ^~~~~~"}));
}

TEST(SourceExcerpt, ShowsTheFixItUnderWhatItReplaces) {
  FixIt fix{{3, 3, 6}, "SPHERE"};
  EXPECT_EQ(quote("a\nb\n  sphere\n", {3, 3, 6}, &fix),
            (std::vector<std::string>{"    3 |   sphere", "      |   ^~~~~~", "      |   SPHERE"}));
}

TEST(SourceExcerpt, ALongLineIsQuotedAroundTheColumnOnly) {
  std::string line(100000, 'x');
  line.replace(70000, 3, "nan");
  std::vector<std::string> quoted = quote(line + "\n", {1, 70001, 3});
  ASSERT_EQ(quoted.size(), 2u);
  EXPECT_LT(quoted[0].size(), 200u);
  EXPECT_EQ(quoted[0].substr(0, 11), "    1 | ...");
  EXPECT_EQ(quoted[0].substr(quoted[0].size() - 3), "...");
  // The caret stands under "nan" in the shown window.
  std::size_t caret = quoted[1].find('^');
  EXPECT_EQ(quoted[0].substr(caret, 3), "nan");
  EXPECT_EQ(quoted[1].substr(caret), "^~~");
}

TEST(SourceExcerpt, BinaryLinesAndMissingLinesAreNotQuoted) {
  EXPECT_TRUE(quote(std::string("glTF\x02\0\0\0", 8), {1, 1, 4}).empty());
  EXPECT_TRUE(quote("\xDC\x04\xAA\x1F\xAD\x1DZ\xDA\xE5\n", {1, 1, 1}).empty());
  // A long line is judged on the window that would be quoted: bytes far
  // from the column neither hide a text window nor show a binary one.
  std::string text(100000, 'x');
  text.replace(10, 8, std::string("\x01\x02\x03\x04\x05\x06\0\x07", 8));
  EXPECT_EQ(quote(text + "\n", {1, 70001, 3}).size(), 2u);
  std::string bytes(100000, '\x01');
  bytes.replace(90000, 3, "nan");
  EXPECT_TRUE(quote(bytes + "\n", {1, 90001, 3}).empty());
  EXPECT_TRUE(quote("one line\n", {5, 1, 1}).empty());
  EXPECT_TRUE(quote("one line\n", {}).empty());
}

TEST(SourceExcerpt, OnlyTheDiagnosticsOfTheNamedFileAreCaptured) {
  DiagnosticList list("main.pov");
  list.error(DiagnosticCode::PovSyntax, {1, 1, 1}, "here");
  DiagnosticList included("other.inc");
  included.error(DiagnosticCode::PovSyntax, {2, 1, 1}, "there");
  list.append(included);
  SourceExcerpts excerpts;
  excerpts.capture("main.pov", "x\ny\n", list);
  EXPECT_NE(excerpts.find("main.pov", {1, 1, 1}), nullptr);
  EXPECT_EQ(excerpts.find("other.inc", {2, 1, 1}), nullptr);
}

}  // namespace
}  // namespace scene
