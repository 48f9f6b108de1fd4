// DOT export: TR trees (Fig. 2(a): conditions are nodes, actions are arcs to the condition they
// achieve), TR sequences (Fig. 2(b)), live highlighting, and rendering with Graphviz.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>

#include "../src/render/dot_render.h"
#include "spott_tr_plus/checker.h"
#include "spott_tr_plus/dot_export.h"
#include "spott_tr_plus/parser.h"

namespace spott_tr_plus {
namespace {

const char* kProgram =
    "condition a; condition b; action x; action y;\n"
    "main m {\n  a -> nil;\n  not a and b -> x effects { a };\n"
    "  not a and not b -> y effects { b };\n}\n";

struct Fixture {
  ParseResult parsed = ParseProgramText(kProgram, "d.tr");
  CheckReport report = CheckProgram(parsed.program);
  const Program& main() const { return parsed.program.programs[0]; }
};

bool Has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(DotExport, TreeArcsGoFromAConditionToTheConditionItsActionAchieves) {
  Fixture f;
  ASSERT_TRUE(f.report.ok());
  const std::string dot = TrTreeDot(f.main(), f.report.Find("m")->parent);
  EXPECT_TRUE(Has(dot, "K1 [label=\"K1: a\"]"));
  EXPECT_TRUE(Has(dot, "K1 -> top [label=\"a1: nil\"]"));
  EXPECT_TRUE(Has(dot, "K2 -> K1 [label=\"a2: x\"]"));
  EXPECT_TRUE(Has(dot, "K3 -> K2 [label=\"a3: y\"]"));  // y achieves b: K3 regresses to K2
  EXPECT_FALSE(Has(dot, "filled"));
  EXPECT_FALSE(Has(dot, "color=red"));
}

TEST(DotExport, LiveStateShadesTrueConditionsAndMarksTheFiringArc) {
  Fixture f;
  DotLiveState live;
  live.rule_values = {false, true, false};
  live.firing_rule = 1;
  const std::string dot = TrTreeDot(f.main(), f.report.Find("m")->parent, &live);
  EXPECT_TRUE(Has(dot, "K2 [label=\"K2: not a and b\", style=filled"));
  EXPECT_TRUE(Has(dot, "K1 [label=\"K1: a\"];"));
  EXPECT_TRUE(Has(dot, "K2 -> K1 [label=\"a2: x\", color=red"));
  EXPECT_TRUE(Has(dot, "K3 -> K2 [label=\"a3: y\"];"));
}

TEST(DotExport, SequenceChainsTheRulesInEvaluationOrder) {
  Fixture f;
  const std::string dot = TrSequenceDot(f.main());
  EXPECT_TRUE(Has(dot, "K1 -> K2 [label=\"false\", style=dashed]"));
  EXPECT_TRUE(Has(dot, "K2 -> K3 [label=\"false\", style=dashed]"));
  EXPECT_FALSE(Has(dot, "K3 -> K4"));
  EXPECT_TRUE(Has(dot, "K3 -> a3 [label=\"true\"]"));
}

TEST(DotExport, LabelsAreEscaped) {
  const ParseResult r = ParseProgramText(
      "condition at(p); action say(t);\nmain m { at(\"a\\\"b\") -> nil; true -> say(\"x\"); }",
      "e.tr");
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  const std::string dot = TrTreeDot(r.program.programs[0], {-1, 0});
  EXPECT_TRUE(Has(dot, "K1: at(\\\"a\\\\\\\"b\\\")")) << dot;
}

TEST(DotExport, RendersPngAndSvgWithGraphviz) {
  Fixture f;
  const std::string dot = ProgramFileDot(f.parsed.program, f.report);
  EXPECT_TRUE(Has(dot, "label=\"m (universal)\""));
  const std::string png = testing::TempDir() + "/tr_tree.png";
  const std::string svg = testing::TempDir() + "/tr_tree.svg";
  ASSERT_EQ(RenderDot(dot, "png", png), "");
  ASSERT_EQ(RenderDot(dot, "svg", svg), "");
  std::ifstream in(png, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 8u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  std::ifstream s(svg);
  std::string text((std::istreambuf_iterator<char>(s)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(Has(text, "<svg"));
  EXPECT_TRUE(Has(text, "a2: x"));
  EXPECT_NE(RenderDot("digraph {", "png", png), "");
}

}  // namespace
}  // namespace spott_tr_plus
