#include "spott_text/lexemes.h"

#include <gtest/gtest.h>

namespace spott_text {
namespace {

TEST(IsNumberSyntax, AcceptsDecimalNumbers) {
  for (const char* s : {"0", "-1", "+2.", "3.25", ".5", "-.5", "1e3", "2.5E-2", "7e+10"})
    EXPECT_TRUE(IsNumberSyntax(s)) << s;
}

TEST(IsNumberSyntax, RefusesSymbolsThatStartLikeNumbers) {
  for (const char* s :
       {"", "+", "-", ".", "-.", "e3", "1e", "1e+", "1.2.3", "12a", "0x10", "1-2", "inf", "nan"})
    EXPECT_FALSE(IsNumberSyntax(s)) << s;
}

TEST(QuoteString, EscapesQuotesBackslashesAndNewlines) {
  EXPECT_EQ(QuoteString("plain"), "\"plain\"");
  EXPECT_EQ(QuoteString("say \"hi\""), "\"say \\\"hi\\\"\"");
  EXPECT_EQ(QuoteString("a\\b"), "\"a\\\\b\"");
  EXPECT_EQ(QuoteString("two\nlines"), "\"two\\nlines\"");
}

}  // namespace
}  // namespace spott_text
