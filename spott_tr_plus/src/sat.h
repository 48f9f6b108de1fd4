// A small DPLL SAT solver (two watched literals, chronological backtracking) and Tseitin
// encoding of propositional formulas; used by the checker for completeness, reachability and
// regression. Internal to spott_tr_plus.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace spott_tr_plus {
namespace internal {

/// A literal: 2 * var + (negated ? 1 : 0).
inline int PosLit(int var) { return 2 * var; }
inline int NegLit(int var) { return 2 * var + 1; }
inline int Negate(int lit) { return lit ^ 1; }

class SatSolver {
 public:
  int NewVar();
  int num_vars() const { return static_cast<int>(assign_.size()); }
  void AddClause(std::vector<int> lits);
  /// True when the clauses and the assumed literals are satisfiable together.
  bool Solve(const std::vector<int>& assumptions = {});
  /// The model of the last satisfiable Solve().
  bool ModelValue(int var) const { return assign_[var] == 1; }

 private:
  int Value(int lit) const {  // 1 true, 0 false, -1 unassigned
    const int8_t a = assign_[lit >> 1];
    return a < 0 ? -1 : (a ^ (lit & 1));
  }
  void Enqueue(int lit) {
    assign_[lit >> 1] = static_cast<int8_t>((lit & 1) ^ 1);
    trail_.push_back(lit);
  }
  bool Propagate();
  void UndoTo(std::size_t trail_size);

  struct Level {
    std::size_t trail_start;
    int lit;
    bool flippable;
    bool flipped;
  };
  std::vector<std::vector<int>> clauses_;
  std::vector<std::vector<int>> watches_;  // by literal
  std::vector<int> units_;
  bool empty_clause_ = false;
  std::vector<int8_t> assign_;
  std::vector<int> trail_;
  std::size_t qhead_ = 0;
  std::vector<Level> levels_;
  int next_var_ = 0;
};

/// A propositional formula over atoms 0..n-1.
struct Formula {
  enum class Kind { kConst, kAtom, kNot, kAnd, kOr, kXor };
  Kind kind = Kind::kConst;
  bool constant = true;
  int atom = -1;
  std::vector<Formula> kids;

  static Formula Const(bool v) { return Formula{Kind::kConst, v, -1, {}}; }
  static Formula Atom(int a) { return Formula{Kind::kAtom, false, a, {}}; }
  static Formula Not(Formula f);
  static Formula Binary(Kind k, Formula a, Formula b);
};

/// Value under an assignment of the atoms (model[atom] is 0 or 1).
bool Evaluate(const Formula& f, const std::vector<int8_t>& model);
/// Atoms that occur in f, appended to `out` (may repeat).
void CollectAtoms(const Formula& f, std::vector<int>& out);
/// Replaces atoms by constants where `fixed[atom]` is 0 or 1 (-1: keep).
Formula Substitute(const Formula& f, const std::vector<int8_t>& fixed);

/// Encodes formulas into a solver; atom i is solver variable atom_var(i).
class TseitinEncoder {
 public:
  TseitinEncoder(SatSolver& solver, int num_atoms);
  int atom_var(int atom) const { return atom_vars_[atom]; }
  /// A literal equivalent to f.
  int Encode(const Formula& f);

 private:
  SatSolver& solver_;
  std::vector<int> atom_vars_;
  int true_var_ = -1;
};

}  // namespace internal
}  // namespace spott_tr_plus
