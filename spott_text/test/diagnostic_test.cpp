#include "spott_text/diagnostic.h"

#include <gtest/gtest.h>

namespace spott_text {
namespace {

TEST(Diagnostic, NamesFileLineAndColumnAndSaysWarning) {
  const Diagnostic e{Diagnostic::Severity::kError, "plan.rpl", {3, 14}, "unbound variable X"};
  EXPECT_EQ(e.ToString(), "plan.rpl:3:14: unbound variable X");
  const Diagnostic w{Diagnostic::Severity::kWarning, "m.mission", {2, 1}, "never used"};
  EXPECT_EQ(w.ToString(), "m.mission:2:1: warning: never used");
}

TEST(Diagnostic, LeavesOutWhatIsUnknown) {
  EXPECT_EQ(LocationText("a.tr", {7, 0}), "a.tr:7");
  EXPECT_EQ(LocationText("a.tr", {}), "a.tr");
  EXPECT_EQ(LocationText("", {1, 2}), "<input>:1:2");
}

TEST(Diagnostic, FormatsOnePerLineAndFindsErrors) {
  std::vector<Diagnostic> d{{Diagnostic::Severity::kWarning, "f", {1, 1}, "w"}};
  EXPECT_FALSE(HasErrors(d));
  d.push_back({Diagnostic::Severity::kError, "f", {2, 5}, "e"});
  EXPECT_TRUE(HasErrors(d));
  EXPECT_EQ(FormatDiagnostics(d), "f:1:1: warning: w\nf:2:5: e");
  EXPECT_EQ(FormatDiagnostics({}), "");
}

}  // namespace
}  // namespace spott_text
