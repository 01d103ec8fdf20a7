#include "scenefile/printable_text.h"

#include <gtest/gtest.h>

#include <string>

namespace scene {
namespace {

TEST(PrintableText, EscapesControlBytesAndWhatIsNotUtf8) {
  EXPECT_EQ(printableText("plain text, \xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"),
            "plain text, \xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");
  EXPECT_EQ(printableText(std::string("a\0b\tc\x7F", 6)), "a\\x00b\\x09c\\x7F");
  EXPECT_EQ(printableText("\xC0\xAF"), "\\xC0\\xAF");                    // overlong '/'
  EXPECT_EQ(printableText("\xED\xA0\x80"), "\\xED\\xA0\\x80");           // a surrogate
  EXPECT_EQ(printableText("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(printableText("\xE2\x82"), "\\xE2\\x82");                    // cut short
  EXPECT_EQ(printableText("x\xFF"), "x\\xFF");
}

}  // namespace
}  // namespace scene
