// What messages quote of a value (issue 29, item 4): one short line whatever the value.
#include <string>

#include <gtest/gtest.h>

#include "engine/text/excerpt.hpp"

namespace curvefold {
namespace {

TEST(Excerpt, EscapesWhatWouldBreakTheLine) {
  EXPECT_EQ(quotedExcerpt("rotational:6"), "\"rotational:6\"");
  EXPECT_EQ(quotedExcerpt("a\nb\tc\"d\\e"), R"("a\nb\tc\"d\\e")");
  EXPECT_EQ(quotedExcerpt(std::string("\x01\x7f", 2)), R"("\u0001\u007f")");
  // UTF-8 stays as it is; a byte that is not UTF-8 is shown, not passed on.
  EXPECT_EQ(quotedExcerpt("caf\xc3\xa9"), "\"caf\xc3\xa9\"");
  EXPECT_EQ(quotedExcerpt("\xff"
                          "a"),
            R"("\xffa")");
  EXPECT_EQ(quotedExcerpt("\xc3"), R"("\xc3")");
}

TEST(Excerpt, IsCutToItsLengthWithoutSplittingACharacterOrAnEscape) {
  const std::string huge(1'000'000, '9');
  const std::string cut = quotedExcerpt(huge);
  EXPECT_EQ(cut.size(), kExcerptLength);
  std::string expected = "\"";  // built piece by piece: GCC 12's -Wrestrict on "x" + string
  expected.append(kExcerptLength - 4, '9').append("...");
  EXPECT_EQ(cut, expected);
  EXPECT_EQ(quotedExcerpt(std::string(9, '9'), 10), "\"999999...");
  // The cut falls before an escape or a two-byte character, never inside it.
  EXPECT_EQ(quotedExcerpt("abcdef\n\n", 11), "\"abcdef...");
  EXPECT_EQ(quotedExcerpt("abcde\xc3\xa9xyz", 10), "\"abcde...");
  // Exactly fitting values are whole.
  EXPECT_EQ(quotedExcerpt(std::string(8, 'x'), 10), "\"xxxxxxxx\"");
}

}  // namespace
}  // namespace curvefold
