#include "lib/scenario/printable_text.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tissu {
namespace {

TEST(PrintableText, FindsTheFirstByteThatIsNotUtf8) {
  EXPECT_EQ(invalid_utf8_offset("plain ascii"), std::string::npos);
  EXPECT_EQ(invalid_utf8_offset("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"), std::string::npos);
  EXPECT_EQ(invalid_utf8_offset("ab\xFF"), 2u);
  EXPECT_EQ(invalid_utf8_offset("a\xC0\xAF"), 1u);          // overlong '/'
  EXPECT_EQ(invalid_utf8_offset("a\xED\xA0\x80"), 1u);      // a UTF-16 surrogate
  EXPECT_EQ(invalid_utf8_offset("a\xF4\x90\x80\x80"), 1u);  // above U+10FFFF
  EXPECT_EQ(invalid_utf8_offset("a\xE2\x82"), 1u);          // cut short
}

TEST(PrintableText, EscapesControlCharactersAndBadBytes) {
  EXPECT_EQ(printable_text("out\nput\t\x01"), "out\\nput\\t\\u0001");
  EXPECT_EQ(printable_text("a\xFF"
                           "b"),
            "a\\xFFb");
  EXPECT_EQ(printable_text("caf\xC3\xA9"), "caf\xC3\xA9");
  const std::string printed = printable_text(std::string(1000, 'x'), 50);
  EXPECT_EQ(printed, std::string(50, 'x') + "...");
}

TEST(PrintableText, CutsAtACharacterBoundary) {
  std::string text;
  for (int i = 0; i < 100; ++i) text += "\xC3\xA9";  // 'e' acute, two bytes
  const std::string printed = printable_text(text, 51);
  EXPECT_EQ(invalid_utf8_offset(printed), std::string::npos);
  EXPECT_EQ(printed.substr(printed.size() - 3), "...");
}

}  // namespace
}  // namespace tissu
