// The TR+ program checker (SPOTT III.C.1): names, unreachable rules, completeness and the
// regression property.
//
// - Names: undefined conditions, actions and subroutines, wrong numbers of arguments, input
//   variables that are not in scope, output variables bound twice or under `not` (or used
//   where they may have no value), duplicate declarations; warnings for declared conditions
//   and actions no rule uses. An output feeds inputs to its right across a sequential `and`.
// - Unreachable rules: rule i can never fire when K_i implies K_1 v ... v K_{i-1} (in
//   particular when it implies one higher rule's condition, which the warning then names).
// - Completeness: K_1 v ... v K_m is a tautology over the program's atomic conditions (the
//   paper: "a clause containing complementary literals"), decided exactly with a small SAT
//   solver on the negation; an incomplete program is reported with a situation in which no
//   rule fires.
// - Regression: where a rule declares its effects (`effects { ... }`), executing its action in
//   K_i must achieve some higher K_j: K_i AND NOT K_j[effects] is unsatisfiable. A program has
//   the regression property when every rule below the first declares effects that do so.
// Each program is reported universal (complete and regression), complete, regression or
// neither. Atomic conditions are named conditions with their input arguments; a timed operator
// adds a fresh atom (it may time out whatever its operands say).
#pragma once

#include <string>
#include <vector>

#include "spott_tr_plus/ast.h"
#include "spott_tr_plus/diagnostic.h"

namespace spott_tr_plus {

struct ProgramVerdict {
  std::string program;
  /// False when the program has errors in its names or variables: its logic is not analysed
  /// and it has no verdict.
  bool analyzed = false;
  bool complete = false;
  bool regression = false;
  bool universal() const { return complete && regression; }
  /// "universal", "complete", "regression" or "neither"; "no verdict (the program has errors)"
  /// when it was not analysed.
  std::string Verdict() const;
  std::vector<int> unreachable_rules;      ///< 0-based rule indices.
  std::vector<int> rules_without_effects;  ///< Rules below the first that declare no effects.
  /// For each rule, the higher rule whose condition its action achieves: the regression target
  /// when effects are declared and achieve one, else the rule just above; -1 for the first.
  std::vector<int> parent;
};

struct CheckReport {
  std::vector<ProgramVerdict> programs;  ///< In file order.
  std::vector<Diagnostic> diagnostics;   ///< Errors and warnings, in file order.
  bool ok() const { return !HasErrors(diagnostics); }
  const ProgramVerdict* Find(const std::string& program) const;
  /// "NAME: verdict" one per line.
  std::string Summary() const;
};

/// Checks a parsed program file. Logic analysis (completeness, reachability, regression) runs
/// on every program whose names and variables are free of errors; the others get no verdict.
CheckReport CheckProgram(const ProgramFile& file);

}  // namespace spott_tr_plus
