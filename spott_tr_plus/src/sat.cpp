#include "sat.h"

#include <algorithm>
#include <utility>

namespace spott_tr_plus {
namespace internal {

int SatSolver::NewVar() {
  assign_.push_back(-1);
  watches_.emplace_back();
  watches_.emplace_back();
  return static_cast<int>(assign_.size()) - 1;
}

void SatSolver::AddClause(std::vector<int> lits) {
  std::sort(lits.begin(), lits.end());
  lits.erase(std::unique(lits.begin(), lits.end()), lits.end());
  for (size_t i = 0; i + 1 < lits.size(); ++i) {
    if ((lits[i] ^ 1) == lits[i + 1]) return;  // x or not x: always satisfied
  }
  if (lits.empty()) {
    empty_clause_ = true;
    return;
  }
  if (lits.size() == 1) {
    units_.push_back(lits[0]);
    return;
  }
  const int index = static_cast<int>(clauses_.size());
  watches_[lits[0]].push_back(index);
  watches_[lits[1]].push_back(index);
  clauses_.push_back(std::move(lits));
}

bool SatSolver::Propagate() {
  while (qhead_ < trail_.size()) {
    const int p = trail_[qhead_++];
    const int false_lit = p ^ 1;
    std::vector<int>& ws = watches_[false_lit];
    size_t i = 0, j = 0;
    while (i < ws.size()) {
      const int ci = ws[i++];
      std::vector<int>& c = clauses_[ci];
      if (c[0] == false_lit) std::swap(c[0], c[1]);
      if (Value(c[0]) == 1) {
        ws[j++] = ci;
        continue;
      }
      bool moved = false;
      for (size_t k = 2; k < c.size(); ++k) {
        if (Value(c[k]) != 0) {
          std::swap(c[1], c[k]);
          watches_[c[1]].push_back(ci);
          moved = true;
          break;
        }
      }
      if (moved) continue;
      ws[j++] = ci;
      if (Value(c[0]) == 0) {
        while (i < ws.size()) ws[j++] = ws[i++];
        ws.resize(j);
        return false;
      }
      Enqueue(c[0]);
    }
    ws.resize(j);
  }
  return true;
}

void SatSolver::UndoTo(size_t trail_size) {
  while (trail_.size() > trail_size) {
    const int var = trail_.back() >> 1;
    assign_[var] = -1;
    next_var_ = std::min(next_var_, var);
    trail_.pop_back();
  }
  qhead_ = std::min(qhead_, trail_.size());
}

bool SatSolver::Solve(const std::vector<int>& assumptions) {
  std::fill(assign_.begin(), assign_.end(), -1);
  trail_.clear();
  levels_.clear();
  qhead_ = 0;
  next_var_ = 0;
  if (empty_clause_) return false;
  for (int u : units_) {
    const int v = Value(u);
    if (v == 0) return false;
    if (v < 0) Enqueue(u);
  }
  if (!Propagate()) return false;
  for (int a : assumptions) {
    const int v = Value(a);
    if (v == 0) return false;
    if (v < 0) {
      Enqueue(a);
      if (!Propagate()) return false;
    }
  }
  const int n = num_vars();
  while (true) {
    while (next_var_ < n && assign_[next_var_] >= 0) ++next_var_;
    if (next_var_ >= n) return true;
    const int lit = NegLit(next_var_);
    levels_.push_back(Level{trail_.size(), lit, true, false});
    Enqueue(lit);
    while (!Propagate()) {
      while (true) {
        if (levels_.empty()) return false;
        const Level level = levels_.back();
        levels_.pop_back();
        UndoTo(level.trail_start);
        if (!level.flipped) {
          levels_.push_back(Level{trail_.size(), Negate(level.lit), true, true});
          Enqueue(Negate(level.lit));
          break;
        }
      }
    }
  }
}

Formula Formula::Not(Formula f) {
  if (f.kind == Kind::kConst) return Const(!f.constant);
  if (f.kind == Kind::kNot) return std::move(f.kids[0]);
  Formula n{Kind::kNot, false, -1, {}};
  n.kids.push_back(std::move(f));
  return n;
}

Formula Formula::Binary(Kind k, Formula a, Formula b) {
  Formula f{k, false, -1, {}};
  f.kids.push_back(std::move(a));
  f.kids.push_back(std::move(b));
  return f;
}

bool Evaluate(const Formula& f, const std::vector<int8_t>& model) {
  switch (f.kind) {
    case Formula::Kind::kConst:
      return f.constant;
    case Formula::Kind::kAtom:
      return model[f.atom] != 0;
    case Formula::Kind::kNot:
      return !Evaluate(f.kids[0], model);
    case Formula::Kind::kAnd:
      return Evaluate(f.kids[0], model) && Evaluate(f.kids[1], model);
    case Formula::Kind::kOr:
      return Evaluate(f.kids[0], model) || Evaluate(f.kids[1], model);
    case Formula::Kind::kXor:
      return Evaluate(f.kids[0], model) != Evaluate(f.kids[1], model);
  }
  return false;
}

void CollectAtoms(const Formula& f, std::vector<int>& out) {
  if (f.kind == Formula::Kind::kAtom) out.push_back(f.atom);
  for (const Formula& k : f.kids) CollectAtoms(k, out);
}

Formula Substitute(const Formula& f, const std::vector<int8_t>& fixed) {
  if (f.kind == Formula::Kind::kAtom) {
    if (f.atom < static_cast<int>(fixed.size()) && fixed[f.atom] >= 0) {
      return Formula::Const(fixed[f.atom] != 0);
    }
    return f;
  }
  Formula g{f.kind, f.constant, f.atom, {}};
  for (const Formula& k : f.kids) g.kids.push_back(Substitute(k, fixed));
  return g;
}

TseitinEncoder::TseitinEncoder(SatSolver& solver, int num_atoms) : solver_(solver) {
  atom_vars_.reserve(num_atoms);
  for (int i = 0; i < num_atoms; ++i) atom_vars_.push_back(solver_.NewVar());
}

int TseitinEncoder::Encode(const Formula& f) {
  switch (f.kind) {
    case Formula::Kind::kConst:
      if (true_var_ < 0) {
        true_var_ = solver_.NewVar();
        solver_.AddClause({PosLit(true_var_)});
      }
      return f.constant ? PosLit(true_var_) : NegLit(true_var_);
    case Formula::Kind::kAtom:
      return PosLit(atom_vars_[f.atom]);
    case Formula::Kind::kNot:
      return Negate(Encode(f.kids[0]));
    default:
      break;
  }
  const int a = Encode(f.kids[0]);
  const int b = Encode(f.kids[1]);
  const int t = PosLit(solver_.NewVar());
  const int nt = Negate(t), na = Negate(a), nb = Negate(b);
  switch (f.kind) {
    case Formula::Kind::kAnd:
      solver_.AddClause({nt, a});
      solver_.AddClause({nt, b});
      solver_.AddClause({t, na, nb});
      break;
    case Formula::Kind::kOr:
      solver_.AddClause({nt, a, b});
      solver_.AddClause({t, na});
      solver_.AddClause({t, nb});
      break;
    default:  // kXor
      solver_.AddClause({nt, a, b});
      solver_.AddClause({nt, na, nb});
      solver_.AddClause({t, na, b});
      solver_.AddClause({t, a, nb});
      break;
  }
  return t;
}

}  // namespace internal
}  // namespace spott_tr_plus
