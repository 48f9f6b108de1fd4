// One set of defaults for the library and the node, and the check that refuses a residual norm
// that can report "converged" over a field without a path.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "spott_harmonic_planner/local_planner.h"
#include "spott_harmonic_planner/potential_field.h"
#include "spott_harmonic_planner/solver.h"

namespace spott_harmonic_planner {
namespace {

// The value of `key` in the solver section of the node's YAML (keys are unique there).
std::string ConfigValue(const std::string& key) {
  std::ifstream in(SPOTT_HARMONIC_PLANNER_CONFIG);
  std::string line;
  while (std::getline(in, line)) {
    line.erase(0, line.find_first_not_of(' '));
    if (line.rfind(key + ":", 0) != 0) continue;
    std::istringstream s(line.substr(key.size() + 1));
    std::string value;
    s >> value;
    return value;
  }
  return "";
}

TEST(Defaults, LibraryDefaultsAreTheNodeDefaults) {
  const FieldOptions o;
  EXPECT_EQ(o.solver.kind, SolverKind::kMultigridCg);
  EXPECT_EQ(o.norm, ResidualNorm::kRelative);
  EXPECT_DOUBLE_EQ(o.tolerance, 1e-4);
  EXPECT_DOUBLE_EQ(o.start_fraction, 0.1);
  // config/harmonic_planner.yaml, which the node loads, says the same.
  EXPECT_EQ(ConfigValue("kind"), ToString(o.solver.kind));
  EXPECT_EQ(ConfigValue("residual_norm"), "relative");
  EXPECT_EQ(std::stod(ConfigValue("tolerance")), o.tolerance);
  EXPECT_EQ(std::stod(ConfigValue("start_fraction")), o.start_fraction);
  EXPECT_EQ(ConfigValue("stencil"), ToString(o.solver.stencil));
  const PlannerParameters p;
  EXPECT_EQ(p.field.solver.kind, SolverKind::kMultigridCg);
  EXPECT_EQ(p.field.norm, ResidualNorm::kRelative);
}

// What the absolute norm allows: a 5-wide, 300-cell corridor (60:1) from p = 0, goal at the left
// end. The exact p at the far end is about exp(-0.512 * 300) = 5e-67 > 0, but red-black SOR
// reaches an absolute residual below 1e-6 long before the far cells leave 0: "converged" with no
// path from there.
TEST(Defaults, AbsoluteResidualReportsConvergedWhileTheCorridorEndHasNoPath) {
  const int w = 7, h = 302 + 0;  // 5 free rows + ring, 300 free columns + ring
  GridMask mask;
  mask.width = h;
  mask.height = w;
  mask.free.assign(static_cast<std::size_t>(w) * h, 0);
  std::vector<double> p(mask.free.size(), 0.0);
  for (int y = 1; y < w - 1; ++y) {
    p[static_cast<std::size_t>(y) * h + 0] = 1.0;  // the goal: the left end
    for (int x = 1; x < h - 1; ++x) mask.free[static_cast<std::size_t>(y) * h + x] = 1;
  }
  SolverOptions so;
  so.kind = SolverKind::kSorRedBlack;
  auto solver = MakeSolver(so);
  solver->Setup(mask);
  int sweeps = 0;
  while (MaxResidual(Stencil::kFivePoint, mask, p.data()) >= 1e-6 && sweeps < 100000) {
    solver->Iterate(p.data());
    ++sweeps;
  }
  EXPECT_LT(MaxResidual(Stencil::kFivePoint, mask, p.data()), 1e-6);
  EXPECT_LE(p[3 * h + (h - 2)], 0.0) << "the far end still at the initial 0 after " << sweeps;
  // ... which is why the field refuses the absolute norm.
  FieldOptions o;
  o.norm = ResidualNorm::kAbsolute;
  const auto v = ValidateFieldOptions(o);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NE(v[0].find("residual_norm"), std::string::npos) << v[0];
  EXPECT_THROW(PotentialField{o}, std::invalid_argument);
  for (SolverKind kind : {SolverKind::kSorRedBlack, SolverKind::kAdi, SolverKind::kMultigrid,
                          SolverKind::kMultigridCg}) {
    o.solver.kind = kind;
    EXPECT_FALSE(ValidateFieldOptions(o).empty()) << ToString(kind);
  }
}

}  // namespace
}  // namespace spott_harmonic_planner
