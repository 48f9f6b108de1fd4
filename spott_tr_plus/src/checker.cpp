#include "spott_tr_plus/checker.h"

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <unordered_map>

#include "sat.h"

namespace spott_tr_plus {

using internal::Formula;

std::string ProgramVerdict::Verdict() const {
  if (!analyzed) return "no verdict (the program has errors)";
  if (universal()) return "universal";
  if (complete) return "complete";
  if (regression) return "regression";
  return "neither";
}

const ProgramVerdict* CheckReport::Find(const std::string& program) const {
  for (const auto& p : programs) {
    if (p.program == program) return &p;
  }
  return nullptr;
}

std::string CheckReport::Summary() const {
  std::string s;
  for (const auto& p : programs) s += p.program + ": " + p.Verdict() + "\n";
  return s;
}

namespace {

std::string RuleName(const Program& p, int i) {
  return "rule " + std::to_string(i + 1) + " of " + p.name + " (line " +
         std::to_string(p.rules[i].where.line) + ")";
}

class Checker {
 public:
  explicit Checker(const ProgramFile& file) : file_(file) {
    // Name indexes: ProgramFile's Find* are linear, which made checking a 10,000-rule program
    // quadratic. The first declaration of a name wins, as in ProgramFile.
    for (const auto& c : file_.conditions) conditions_.emplace(c.name, &c);
    for (const auto& a : file_.actions) actions_.emplace(a.name, &a);
    for (size_t i = 0; i < file_.programs.size(); ++i) {
      programs_.emplace(file_.programs[i].name, static_cast<int>(i));
    }
  }

  CheckReport Run() {
    CheckDeclarations();
    std::vector<bool> names_ok;
    for (const Program& p : file_.programs) {
      const size_t before = ErrorCount();
      CheckNames(p);
      names_ok.push_back(ErrorCount() == before && !p.rules.empty());
    }
    CheckCallGraph();
    WarnUnused();
    // A program whose names or variables are wrong gets no verdict: its conditions are not
    // the ones the author meant.
    for (size_t i = 0; i < file_.programs.size(); ++i) {
      if (names_ok[i]) {
        report_.programs.push_back(AnalyzeLogic(file_.programs[i]));
      } else {
        ProgramVerdict v;
        v.program = file_.programs[i].name;
        report_.programs.push_back(v);
      }
    }
    std::stable_sort(report_.diagnostics.begin(), report_.diagnostics.end(),
                     [](const Diagnostic& a, const Diagnostic& b) {
                       return std::tie(a.where.line, a.where.column) <
                              std::tie(b.where.line, b.where.column);
                     });
    return std::move(report_);
  }

 private:
  void Error(Location where, std::string message) {
    report_.diagnostics.push_back(
        Diagnostic{Diagnostic::Severity::kError, file_.file, where, std::move(message)});
  }
  size_t ErrorCount() const {
    return std::count_if(report_.diagnostics.begin(), report_.diagnostics.end(),
                         [](const Diagnostic& d) { return d.IsError(); });
  }
  void Warning(Location where, std::string message) {
    report_.diagnostics.push_back(
        Diagnostic{Diagnostic::Severity::kWarning, file_.file, where, std::move(message)});
  }

  void CheckDeclarations() {
    std::map<std::string, Location> seen;
    auto declare = [&](const std::string& name, Location where, const char* what) {
      auto [it, fresh] = seen.emplace(name, where);
      if (!fresh) {
        Error(where, std::string(what) + " '" + name + "' is already declared at line " +
                         std::to_string(it->second.line));
      }
    };
    for (const auto& c : file_.conditions) {
      declare(c.name, c.where, "condition");
      std::set<std::string> params;
      for (const auto& p : c.params) {
        if (!params.insert(p.name).second) {
          Error(c.where, "condition '" + c.name + "' has two parameters named '" + p.name + "'");
        }
      }
    }
    for (const auto& a : file_.actions) declare(a.name, a.where, "action");
    int mains = 0;
    for (const auto& p : file_.programs) {
      declare(p.name, p.where, p.is_main ? "main program" : "subroutine");
      if (p.is_main) {
        if (++mains > 1) Error(p.where, "a file has one main program; '" + p.name + "' is another");
        if (!p.params.empty()) Error(p.where, "the main program takes no parameters");
      }
      if (p.rules.empty()) Error(p.where, "program '" + p.name + "' has no rules");
    }
    if (mains == 0 && !file_.programs.empty()) {
      Warning(file_.programs.front().where, "no main program: only subroutines are defined");
    }
  }

  // --- Names and variables -------------------------------------------------------------------
  //
  // Variables of a rule (README "The TR+ language", arguments): a program's parameters, and the
  // output variables its condition binds. An output is bound only where its condition is
  // known TRUE when the rule fires: in a conjunctive position (every operator above it is
  // `and` or `&`). Under `not` it would have no value (an error); under `or`, `|` or `^` it
  // may have none (an error where it is used). A sequential `and` computes its left operand
  // first, so the outputs bound on its left feed the inputs of the conditions on its right
  // (SPOTT Fig. 13: "find a new room", then "in that room"); concurrent operators compute
  // their operands together and pass nothing between them.

  struct OutputVar {
    Location where;
    std::string condition;  ///< the condition that binds it
    std::string unsure;     ///< empty: has a value when the rule fires; else the operator ("or")
  };
  using Outputs = std::map<std::string, OutputVar>;

  void CheckNames(const Program& p) {
    const std::set<std::string> params(p.params.begin(), p.params.end());
    if (params.size() != p.params.size()) {
      Error(p.where, "program '" + p.name + "' has two parameters with the same name");
    }
    for (const Rule& r : p.rules) {
      Outputs outputs;
      std::set<std::string> visible = params;
      CheckCondition(r.condition, visible, "", false, params, outputs);
      // The action and the effects see the parameters and the outputs that surely have values.
      std::set<std::string> scope = params;
      for (const auto& [name, v] : outputs) {
        if (v.unsure.empty()) scope.insert(name);
      }
      CheckAction(r.action, scope, outputs);
      for (const auto& e : r.effects) CheckEffect(e, scope, outputs);
    }
  }

  void CheckEffect(const EffectLiteral& e, const std::set<std::string>& scope,
                   const Outputs& outputs) {
    const ConditionDecl* d = FindCondition(e.name);
    if (!d) {
      Error(e.where, "effect names an undefined condition '" + e.name + "'");
      return;
    }
    if (static_cast<int>(e.args.size()) != d->NumInputs()) {
      Error(e.where, "effect '" + e.name + "' needs " + std::to_string(d->NumInputs()) +
                         " input argument(s) (outputs are not named in effects), found " +
                         std::to_string(e.args.size()));
    }
    for (const auto& a : e.args) CheckInput(a, scope, outputs);
  }

  // A variable read as an input or an action argument must be in `scope`.
  void CheckInput(const Arg& a, const std::set<std::string>& scope, const Outputs& outputs) {
    if (a.kind != Arg::Kind::kVariable || scope.count(a.text)) return;
    auto it = outputs.find(a.text);
    if (it == outputs.end()) {
      Error(a.where, "undefined variable '" + a.text +
                         "' (neither a parameter of this program nor an output variable bound "
                         "by this rule's condition)");
    } else if (!it->second.unsure.empty()) {
      Error(a.where, "variable '" + a.text + "' may have no value here: '" + it->second.condition +
                         "' binds it under '" + it->second.unsure + "' (line " +
                         std::to_string(it->second.where.line) + ", column " +
                         std::to_string(it->second.where.column) +
                         "), which the rule can fire without; only outputs of conditions joined "
                         "by 'and' or '&' reach the action");
    } else {
      Error(a.where, "variable '" + a.text + "' is read before it is bound: '" +
                         it->second.condition + "' binds it at line " +
                         std::to_string(it->second.where.line) + ", column " +
                         std::to_string(it->second.where.column) +
                         "; an output feeds an input only to its right across a sequential "
                         "'and' (concurrent operators compute their operands together)");
    }
  }

  // Checks `c` and returns the output variables it surely binds when it is TRUE. `visible`:
  // the variables its inputs may read. `unsure`: the nearest enclosing `or`, `|` or `^` (an
  // output bound below it may have no value). `negated`: below a `not`.
  std::set<std::string> CheckCondition(const CondExpr& c, const std::set<std::string>& visible,
                                       const std::string& unsure, bool negated,
                                       const std::set<std::string>& params, Outputs& outputs) {
    switch (c.op) {
      case CondOp::kTrue:
      case CondOp::kFalse:
        return {};
      case CondOp::kAtom:
        return CheckAtom(c, visible, unsure, negated, params, outputs);
      case CondOp::kNot:
        CheckCondition(c.children[0], visible, unsure, true, params, outputs);
        return {};
      default:
        break;
    }
    if (c.IsTimed() && c.timeout_s <= 0.0) Error(c.where, "a timeout must be > 0 s");
    const char* op = c.op == CondOp::kSeqOr ? "or" : c.op == CondOp::kParOr ? "|" : "^";
    const bool conjunction = c.op == CondOp::kSeqAnd || c.op == CondOp::kParAnd;
    const std::string below = conjunction ? unsure : (unsure.empty() ? op : unsure);
    std::set<std::string> left =
        CheckCondition(c.children[0], visible, below, negated, params, outputs);
    std::set<std::string> right_visible = visible;
    if (c.op == CondOp::kSeqAnd) right_visible.insert(left.begin(), left.end());
    std::set<std::string> right =
        CheckCondition(c.children[1], right_visible, below, negated, params, outputs);
    if (c.IsTimed()) WarnSlowOperands(c, c);
    if (!conjunction) return {};
    left.insert(right.begin(), right.end());
    return left;
  }

  std::set<std::string> CheckAtom(const CondExpr& c, const std::set<std::string>& visible,
                                  const std::string& unsure, bool negated,
                                  const std::set<std::string>& params, Outputs& outputs) {
    const ConditionDecl* d = FindCondition(c.name);
    if (!d) {
      if (FindAction(c.name) || FindProgram(c.name)) {
        Error(c.where, "'" + c.name + "' is an action or program, not a condition");
      } else {
        Error(c.where,
              "undefined condition '" + c.name + "' (declare it: condition " + c.name + ";)");
      }
      return {};
    }
    if (c.args.size() != d->params.size() && !OutputsOmitted(c, *d)) {
      std::string expected = std::to_string(d->params.size()) + " argument(s)";
      if (d->NumOutputs() > 0) {
        expected += ", or its " + std::to_string(d->NumInputs()) +
                    " input(s) alone when its outputs are not bound";
      }
      Error(c.where, "condition '" + c.name + "' takes " + expected + ", found " +
                         std::to_string(c.args.size()));
      return {};
    }
    std::set<std::string> bound;
    for (size_t k = 0; k < d->params.size(); ++k) {
      const Arg* a = ArgForParam(c, *d, k);
      if (!a) continue;  // an omitted output
      if (!d->params[k].is_output) {
        CheckInput(*a, visible, outputs);
        continue;
      }
      if (a->kind != Arg::Kind::kVariable) {
        Error(a->where, "output '" + d->params[k].name + "' of '" + c.name +
                            "' must be bound to a variable name");
      } else if (params.count(a->text)) {
        Error(a->where, "output variable '" + a->text + "' hides a parameter of the program");
      } else if (negated) {
        Error(a->where, "output variable '" + a->text + "' of '" + c.name +
                            "' is bound under 'not': the rule fires when '" + c.name +
                            "' is FALSE, and then '" + a->text + "' has no value (write '" +
                            c.name + "' with its inputs only, outputs left out)");
      } else if (!outputs.emplace(a->text, OutputVar{a->where, c.name, unsure}).second) {
        Error(a->where, "output variable '" + a->text + "' is bound twice in this condition");
      } else if (unsure.empty()) {
        bound.insert(a->text);
      }
    }
    return bound;
  }

  // A timed operator whose operand recomputes less often than the timeout allows is FALSE
  // between its computations.
  void WarnSlowOperands(const CondExpr& timed, const CondExpr& c) {
    if (c.op == CondOp::kAtom) {
      const ConditionDecl* d = FindCondition(c.name);
      if (d && d->frequency_hz > 0.0 && 1.0 / d->frequency_hz > timed.timeout_s) {
        Warning(c.where, "'" + c.name + "' is computed every " +
                             std::to_string(1.0 / d->frequency_hz) +
                             " s, longer than the timeout of the operator at column " +
                             std::to_string(timed.where.column) +
                             ": the expression is FALSE between its computations");
      }
      return;
    }
    for (const auto& k : c.children) WarnSlowOperands(timed, k);
  }

  void CheckAction(const ActExpr& a, const std::set<std::string>& scope, const Outputs& outputs) {
    if (a.op != ActOp::kInvoke) {
      for (const auto& k : a.children) CheckAction(k, scope, outputs);
      return;
    }
    size_t expected = 0;
    if (const Program* callee = FindProgram(a.name)) {
      if (callee->is_main) {
        Error(a.where, "the main program '" + a.name + "' cannot be called");
        return;
      }
      expected = callee->params.size();
    } else if (const ActionDecl* d = FindAction(a.name)) {
      expected = d->params.size();
    } else if (FindCondition(a.name)) {
      Error(a.where, "'" + a.name + "' is a condition, not an action");
      return;
    } else {
      Error(a.where, "undefined action or subroutine '" + a.name + "'");
      return;
    }
    if (a.args.size() != expected) {
      Error(a.where, "'" + a.name + "' takes " + std::to_string(expected) + " argument(s), found " +
                         std::to_string(a.args.size()));
    }
    for (const auto& arg : a.args) CheckInput(arg, scope, outputs);
  }

  // Declared conditions no rule reads and actions no rule runs (a typo in a rule names an
  // undefined one; the declaration is then left over).
  void WarnUnused() {
    std::set<std::string> read, run;
    std::function<void(const CondExpr&)> conds = [&](const CondExpr& c) {
      if (c.op == CondOp::kAtom) read.insert(c.name);
      for (const auto& k : c.children) conds(k);
    };
    std::function<void(const ActExpr&)> acts = [&](const ActExpr& a) {
      if (a.op == ActOp::kInvoke) run.insert(a.name);
      for (const auto& k : a.children) acts(k);
    };
    for (const Program& p : file_.programs) {
      for (const Rule& r : p.rules) {
        conds(r.condition);
        acts(r.action);
      }
    }
    for (const auto& c : file_.conditions) {
      if (!read.count(c.name)) {
        Warning(c.where, "condition '" + c.name + "' is declared but no rule reads it");
      }
    }
    for (const auto& a : file_.actions) {
      if (!run.count(a.name)) {
        Warning(a.where, "action '" + a.name + "' is declared but no rule runs it");
      }
    }
  }

  void CollectCalls(const ActExpr& a, std::vector<int>& callees) {
    if (a.op == ActOp::kInvoke && a.is_call) {
      const int i = ProgramIndex(a.name);
      if (i >= 0) callees.push_back(i);
    }
    for (const auto& k : a.children) CollectCalls(k, callees);
  }

  void CheckCallGraph() {
    const int n = static_cast<int>(file_.programs.size());
    std::vector<std::vector<int>> calls(n);
    for (int i = 0; i < n; ++i) {
      for (const auto& r : file_.programs[i].rules) CollectCalls(r.action, calls[i]);
    }
    // Reachability from main; recursion.
    std::vector<int> state(n, 0);  // 0 new, 1 on stack, 2 done
    std::vector<bool> reached(n, false);
    std::function<void(int)> visit = [&](int i) {
      state[i] = 1;
      reached[i] = true;
      for (int j : calls[i]) {
        if (state[j] == 1) {
          Warning(file_.programs[i].where, "'" + file_.programs[i].name + "' calls '" +
                                               file_.programs[j].name +
                                               "' recursively (the interpreter limits the depth)");
        } else if (state[j] == 0) {
          visit(j);
        }
      }
      state[i] = 2;
    };
    for (int i = 0; i < n; ++i) {
      if (file_.programs[i].is_main) visit(i);
    }
    const bool has_main = file_.Main() != nullptr;
    for (int i = 0; i < n && has_main; ++i) {
      if (!reached[i]) {
        Warning(file_.programs[i].where,
                "subroutine '" + file_.programs[i].name + "' is never called from main");
      }
    }
  }

  // --- Logic --------------------------------------------------------------------------------

  struct Atoms {
    std::unordered_map<std::string, int> ids;
    std::vector<std::string> names;
    int Get(const std::string& key) {
      auto [it, fresh] = ids.emplace(key, static_cast<int>(names.size()));
      if (fresh) names.push_back(key);
      return it->second;
    }
    int Fresh(const std::string& label) {
      names.push_back(label);
      return static_cast<int>(names.size()) - 1;
    }
  };

  static std::string AtomKey(const std::string& name, const ConditionDecl* d,
                             const std::vector<Arg>& args, bool inputs_only_given) {
    std::string key = name;
    std::string inputs;
    if (inputs_only_given || !d) {
      for (const auto& a : args) inputs += (inputs.empty() ? "" : ", ") + a.ToString();
    } else {
      for (size_t k = 0; k < args.size() && k < d->params.size(); ++k) {
        if (!d->params[k].is_output) {
          inputs += (inputs.empty() ? "" : ", ") + args[k].ToString();
        }
      }
    }
    if (!inputs.empty()) key += "(" + inputs + ")";
    return key;
  }

  Formula ToFormula(const CondExpr& c, Atoms& atoms) {
    switch (c.op) {
      case CondOp::kTrue:
        return Formula::Const(true);
      case CondOp::kFalse:
        return Formula::Const(false);
      case CondOp::kAtom: {
        const ConditionDecl* d = FindCondition(c.name);
        const bool inputs_only = d && OutputsOmitted(c, *d);
        return Formula::Atom(atoms.Get(AtomKey(c.name, d, c.args, inputs_only)));
      }
      case CondOp::kNot:
        return Formula::Not(ToFormula(c.children[0], atoms));
      default:
        break;
    }
    Formula::Kind k = Formula::Kind::kAnd;
    if (c.op == CondOp::kSeqOr || c.op == CondOp::kParOr) k = Formula::Kind::kOr;
    if (c.op == CondOp::kXor) k = Formula::Kind::kXor;
    // Operands in source order, so atoms are numbered left to right.
    Formula left = ToFormula(c.children[0], atoms);
    Formula right = ToFormula(c.children[1], atoms);
    Formula f = Formula::Binary(k, std::move(left), std::move(right));
    if (c.IsTimed()) {
      // The timed operator may be FALSE whatever the operands compute: AND a fresh atom.
      const int tau = atoms.Fresh("<in time: operator at line " + std::to_string(c.where.line) +
                                  ", column " + std::to_string(c.where.column) + ">");
      f = Formula::Binary(Formula::Kind::kAnd, std::move(f), Formula::Atom(tau));
    }
    return f;
  }

  static std::string Situation(const Atoms& atoms, const std::vector<int8_t>& model) {
    std::string s;
    for (size_t a = 0; a < atoms.names.size(); ++a) {
      s += (s.empty() ? "" : ", ") + atoms.names[a] + (model[a] ? " true" : " false");
    }
    return s.empty() ? "always" : s;
  }

  // The rules' conditions K_1..K_m as formulas over the program's atoms, and a solver that
  // holds t_i <-> K_i for every rule (queries are assumptions on the t_i).
  struct Logic {
    Atoms atoms;
    std::vector<Formula> k;
    internal::SatSolver solver;
    std::unique_ptr<internal::TseitinEncoder> enc;
    std::vector<int> t;
    int num_atoms() const { return static_cast<int>(atoms.names.size()); }
  };

  void EncodeRules(const Program& p, Logic& logic) {
    logic.k.reserve(p.rules.size());
    for (const Rule& r : p.rules) logic.k.push_back(ToFormula(r.condition, logic.atoms));
    logic.enc = std::make_unique<internal::TseitinEncoder>(logic.solver, logic.num_atoms());
    for (const Formula& f : logic.k) logic.t.push_back(logic.enc->Encode(f));
  }

  ProgramVerdict AnalyzeLogic(const Program& p) {
    ProgramVerdict v;
    v.program = p.name;
    v.analyzed = true;
    const int m = static_cast<int>(p.rules.size());
    v.parent.resize(m);
    for (int i = 0; i < m; ++i) v.parent[i] = i - 1;
    if (m == 0) return v;
    Logic logic;
    EncodeRules(p, logic);
    std::vector<int8_t> model(logic.num_atoms(), 0);
    v.complete = CheckReachability(p, logic, v, model);
    if (!v.complete) {
      Warning(p.where, "program '" + p.name + "' is not complete: no rule fires when " +
                           Situation(logic.atoms, model));
    }
    v.regression = CheckRegression(p, logic, v);
    return v;
  }

  // Reachability, rule by rule, keeping in `model` a situation in which no rule above fires.
  // A rule whose condition can be made true by setting atoms no higher rule uses is reachable
  // at once; otherwise the solver decides. Linear for programs whose rules share few atoms.
  // Returns completeness: whether some prefix of the rules (hence the whole program) covers
  // every situation; `model` then holds one that no rule covers when it does not.
  bool CheckReachability(const Program& p, Logic& logic, ProgramVerdict& v,
                         std::vector<int8_t>& model) {
    const int m = static_cast<int>(p.rules.size());
    const std::vector<Formula>& k = logic.k;
    internal::SatSolver& solver = logic.solver;
    std::vector<bool> seen(logic.num_atoms(), false);
    bool prefix_complete = false;
    std::vector<int> prefix_assumptions;
    std::vector<int> atoms_of;
    for (int i = 0; i < m; ++i) {
      atoms_of.clear();
      CollectAtoms(k[i], atoms_of);
      std::sort(atoms_of.begin(), atoms_of.end());
      atoms_of.erase(std::unique(atoms_of.begin(), atoms_of.end()), atoms_of.end());
      std::vector<int> fresh;
      for (int a : atoms_of) {
        if (!seen[a]) fresh.push_back(a);
      }
      bool reachable = false;
      if (!prefix_complete) {
        reachable = FindFresh(k[i], fresh, model, true);
        if (!reachable) {
          std::vector<int> q = prefix_assumptions;
          q.push_back(logic.t[i]);
          reachable = solver.Solve(q);
        }
      }
      if (!reachable) {
        v.unreachable_rules.push_back(i);
        ReportUnreachable(p, i, prefix_complete, solver, logic.t);
      }
      // Keep the model of "no rule up to i fires".
      if (!prefix_complete) {
        if (!FindFresh(k[i], fresh, model, false)) {
          std::vector<int> q = prefix_assumptions;
          q.push_back(internal::Negate(logic.t[i]));
          if (solver.Solve(q)) {
            for (int a = 0; a < logic.num_atoms(); ++a) {
              model[a] = solver.ModelValue(logic.enc->atom_var(a)) ? 1 : 0;
            }
          } else {
            prefix_complete = true;
          }
        }
        prefix_assumptions.push_back(internal::Negate(logic.t[i]));
      }
      for (int a : atoms_of) seen[a] = true;
    }
    return prefix_complete;
  }

  // Regression, for rules that declare effects: K_i AND NOT K_j[effects] is unsatisfiable for
  // some higher j. Sets v.parent and v.rules_without_effects; true when every rule below the
  // first has the property.
  bool CheckRegression(const Program& p, const Logic& logic, ProgramVerdict& v) {
    const int m = static_cast<int>(p.rules.size());
    const int n = logic.num_atoms();
    bool regression = m >= 1;
    for (int i = 1; i < m; ++i) {
      const Rule& r = p.rules[i];
      if (!r.has_effects) {
        v.rules_without_effects.push_back(i);
        regression = false;
        continue;
      }
      std::vector<int8_t> fixed(n, -1);
      if (!FixEffects(r, logic.atoms, fixed)) {
        regression = false;
        continue;
      }
      int achieved = -1;
      for (int j = i - 1; j >= 0; --j) {
        internal::SatSolver s;
        internal::TseitinEncoder e(s, n);
        s.AddClause({e.Encode(logic.k[i])});
        s.AddClause({internal::Negate(e.Encode(internal::Substitute(logic.k[j], fixed)))});
        if (!s.Solve()) {
          achieved = j;
          break;
        }
      }
      if (achieved >= 0) {
        v.parent[i] = achieved;
      } else {
        regression = false;
        Warning(r.where, RuleName(p, i) +
                             ": its declared effects do not achieve the condition of any "
                             "higher rule (regression property)");
      }
    }
    return regression;
  }

  // The atoms a rule's effects make true (1) or false (0); false (with an error) when they
  // contradict each other.
  bool FixEffects(const Rule& r, const Atoms& atoms, std::vector<int8_t>& fixed) {
    bool known = true;
    for (const auto& e : r.effects) {
      const std::string key = AtomKey(e.name, FindCondition(e.name), e.args, true);
      auto it = atoms.ids.find(key);
      if (it == atoms.ids.end()) continue;  // an effect on an atom no condition reads
      if (fixed[it->second] >= 0 && fixed[it->second] != (e.positive ? 1 : 0)) {
        Error(e.where, "effects make '" + key + "' both true and false");
        known = false;
      }
      fixed[it->second] = e.positive ? 1 : 0;
    }
    return known;
  }

  // Tries to set the fresh atoms so that k has value `want` (other atoms as in `model`); on
  // success `model` holds the assignment.
  static bool FindFresh(const Formula& k, const std::vector<int>& fresh, std::vector<int8_t>& model,
                        bool want) {
    if (fresh.size() > 10) return false;
    const uint32_t combos = 1u << fresh.size();
    std::vector<int8_t> saved;
    for (int a : fresh) saved.push_back(model[a]);
    for (uint32_t bits = 0; bits < combos; ++bits) {
      for (size_t b = 0; b < fresh.size(); ++b) model[fresh[b]] = (bits >> b) & 1u;
      if (internal::Evaluate(k, model) == want) return true;
    }
    for (size_t b = 0; b < fresh.size(); ++b) model[fresh[b]] = saved[b];
    return false;
  }

  void ReportUnreachable(const Program& p, int i, bool prefix_complete, internal::SatSolver& solver,
                         const std::vector<int>& t) {
    if (!solver.Solve({t[i]})) {
      Warning(p.rules[i].where, RuleName(p, i) + " can never fire: its condition is never true");
      return;
    }
    for (int j = 0; j < i; ++j) {
      if (!solver.Solve({t[i], internal::Negate(t[j])})) {
        Warning(p.rules[i].where, RuleName(p, i) + " can never fire: its condition implies " +
                                      "the condition of " + RuleName(p, j));
        return;
      }
    }
    Warning(p.rules[i].where,
            RuleName(p, i) + " can never fire: " +
                (prefix_complete ? std::string("the rules above it are already complete")
                                 : std::string("whenever its condition holds, a rule above "
                                               "it holds")));
  }

  const ConditionDecl* FindCondition(const std::string& name) const {
    auto it = conditions_.find(name);
    return it == conditions_.end() ? nullptr : it->second;
  }
  const ActionDecl* FindAction(const std::string& name) const {
    auto it = actions_.find(name);
    return it == actions_.end() ? nullptr : it->second;
  }
  int ProgramIndex(const std::string& name) const {
    auto it = programs_.find(name);
    return it == programs_.end() ? -1 : it->second;
  }
  const Program* FindProgram(const std::string& name) const {
    const int i = ProgramIndex(name);
    return i < 0 ? nullptr : &file_.programs[i];
  }

  const ProgramFile& file_;
  std::unordered_map<std::string, const ConditionDecl*> conditions_;
  std::unordered_map<std::string, const ActionDecl*> actions_;
  std::unordered_map<std::string, int> programs_;
  CheckReport report_;
};

}  // namespace

CheckReport CheckProgram(const ProgramFile& file) { return Checker(file).Run(); }

}  // namespace spott_tr_plus
