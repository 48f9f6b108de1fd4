// The S-expression reader: data, locations, and every syntax error with file:line:column.
#include <gtest/gtest.h>

#include "rpl_executive/rpl/reader.h"

namespace rpl_executive {
namespace rpl {
namespace {

std::string FirstError(const std::string& text) {
  const ReadResult r = ReadPlanText(text, "plan.rpl");
  if (r.diagnostics.empty()) return "";
  return r.diagnostics[0].ToString();
}

TEST(RplReader, ReadsNestedListsWithLocationsAndFoldsSymbolsToUpperCase) {
  const ReadResult r =
      ReadPlanText("; a comment\n(with-policy (WAIT-for x*)\n  \"Text\" -0.8)", "p");
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  ASSERT_EQ(r.forms.size(), 1u);
  const Datum& d = r.forms[0];
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 1);
  EXPECT_EQ(d.Head(), "WITH-POLICY");
  ASSERT_EQ(d.items.size(), 4u);
  EXPECT_EQ(d.items[1].Head(), "WAIT-FOR");
  EXPECT_EQ(d.items[1].items[1].text, "X*");
  EXPECT_EQ(d.items[1].items[1].column, 24);
  EXPECT_EQ(d.items[2].kind, Datum::Kind::kString);
  EXPECT_EQ(d.items[2].text, "Text");  // strings keep their case
  EXPECT_EQ(d.items[2].line, 3);
  EXPECT_EQ(d.items[2].column, 3);
  EXPECT_EQ(d.items[3].kind, Datum::Kind::kNumber);
  EXPECT_DOUBLE_EQ(d.items[3].number, -0.8);
}

TEST(RplReader, QuoteReadsAsQuoteForm) {
  const ReadResult r = ReadPlanText("'(19.6 6)", "p");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(PrintDatum(r.forms[0]), "(QUOTE (19.6 6))");
}

TEST(RplReader, PrintedDataReadBackTheSame) {
  const std::string text =
      "(LOOP (TRY-ALL (WAIT-FOR EXECUTION-INTERRUPTED?) (G&E \"a \\\"b\\\"\\n\" 1e-3 :FAST))"
      " UNTIL (<= 0.8 POS-CERTAINTY*)) #| block |# ()";
  const ReadResult r = ReadPlanText(text, "p");
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  std::string printed;
  for (const auto& d : r.forms) printed += PrintDatum(d) + "\n";
  const ReadResult again = ReadPlanText(printed, "p");
  ASSERT_TRUE(again.ok());
  std::string reprinted;
  for (const auto& d : again.forms) reprinted += PrintDatum(d) + "\n";
  EXPECT_EQ(printed, reprinted);
  EXPECT_NE(printed.find("0.001"), std::string::npos);
}

TEST(RplReader, UnclosedListIsReportedAtItsOpeningParenthesis) {
  EXPECT_EQ(FirstError("(SEQ\n  (WAIT-FOR X*)\n"),
            "plan.rpl:1:1: unclosed '(': the text ends before its ')'");
  EXPECT_EQ(FirstError("(SEQ (A)\n   (B"),
            "plan.rpl:2:4: unclosed '(': the text ends before its ')'");
}

TEST(RplReader, StrayClosingParenthesisIsReportedWhereItIs) {
  EXPECT_EQ(FirstError("(A)\n  )"), "plan.rpl:2:3: unexpected ')' with no list open");
}

TEST(RplReader, UnterminatedStringAndBadEscapeAreLocated) {
  EXPECT_EQ(FirstError("(FAIL \"no end)"), "plan.rpl:1:7: unterminated string: no closing '\"'");
  EXPECT_EQ(FirstError("(FAIL \"a\\tb\")"),
            "plan.rpl:1:9: unknown escape '\\t' in a string (use \\\", \\\\ or \\n)");
}

TEST(RplReader, MalformedNumbersAndBadCharactersAreLocated) {
  EXPECT_EQ(FirstError("(<= X 0.8.1)"), "plan.rpl:1:7: malformed number '0.8.1'");
  EXPECT_EQ(FirstError("(A 1e999)"), "plan.rpl:1:4: number '1e999' is out of range");
  EXPECT_EQ(FirstError("(A\n b[0])"),
            "plan.rpl:2:3: unexpected character '[' (symbols are letters, digits and - * + / < "
            "> = ? ! & % $ : _ . ~ ^ @)");
  EXPECT_EQ(FirstError("(A \x01)"),
            "plan.rpl:1:4: unexpected character byte 0x01 (symbols are letters, digits and - * + "
            "/ < > = ? ! & % $ : _ . ~ ^ @)");
  EXPECT_EQ(FirstError("(A FOO:BAR)"),
            "plan.rpl:1:4: symbol 'FOO:BAR' has a ':' inside (only keywords start with ':'; "
            "there are no packages)");
}

TEST(RplReader, UnterminatedBlockCommentIsLocated) {
  EXPECT_EQ(FirstError("(A)\n #| never closed"),
            "plan.rpl:2:2: unterminated block comment '#|' (no '|#' follows)");
}

TEST(RplReader, DeepNestingIsAnErrorNotAStackOverflow) {
  std::string deep(100000, '(');
  const ReadResult r = ReadPlanText(deep, "deep.rpl");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].where.line, 1);
  EXPECT_EQ(r.diagnostics[0].where.column, kMaxNestingDepth + 1);
}

TEST(RplReader, ReportsEveryErrorNotOnlyTheFirst) {
  const ReadResult r = ReadPlanText(")\n(A 1.2.3)\n(B \"x", "p");
  ASSERT_EQ(r.diagnostics.size(), 3u) << FormatDiagnostics(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].where.line, 1);
  EXPECT_EQ(r.diagnostics[1].where.line, 2);
  EXPECT_EQ(r.diagnostics[2].where.line, 3);
}

}  // namespace
}  // namespace rpl
}  // namespace rpl_executive
