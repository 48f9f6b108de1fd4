#include "spott_tr_plus/checker.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "sat.h"

namespace spott_tr_plus {

using internal::Formula;

std::string ProgramVerdict::Verdict() const {
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
    for (const Program& p : file_.programs) CheckNames(p);
    CheckCallGraph();
    for (const Program& p : file_.programs) {
      report_.programs.push_back(AnalyzeLogic(p));
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

  // Checks arguments of one invocation against its declared parameters. `inputs` tells, per
  // position, whether it is read (true) or bound (false, condition outputs).
  void CheckNames(const Program& p) {
    const std::set<std::string> params(p.params.begin(), p.params.end());
    if (params.size() != p.params.size()) {
      Error(p.where, "program '" + p.name + "' has two parameters with the same name");
    }
    for (size_t i = 0; i < p.rules.size(); ++i) {
      const Rule& r = p.rules[i];
      std::set<std::string> bound = params;
      std::map<std::string, Location> outputs;
      CheckCondition(r.condition, params, outputs);
      for (const auto& [name, where] : outputs) bound.insert(name);
      CheckAction(r.action, bound);
      for (const auto& e : r.effects) {
        const ConditionDecl* d = FindCondition(e.name);
        if (!d) {
          Error(e.where, "effect names an undefined condition '" + e.name + "'");
          continue;
        }
        if (static_cast<int>(e.args.size()) != d->NumInputs()) {
          Error(e.where, "effect '" + e.name + "' needs " + std::to_string(d->NumInputs()) +
                             " input argument(s) (outputs are not named in effects), found " +
                             std::to_string(e.args.size()));
        }
        for (const auto& a : e.args) CheckInput(a, params);
      }
    }
  }

  void CheckInput(const Arg& a, const std::set<std::string>& scope) {
    if (a.kind == Arg::Kind::kVariable && !scope.count(a.text)) {
      Error(a.where, "undefined variable '" + a.text + "' (not a parameter of this program" +
                         std::string(scope.empty() ? "" : " nor a condition output") + ")");
    }
  }

  void CheckCondition(const CondExpr& c, const std::set<std::string>& params,
                      std::map<std::string, Location>& outputs) {
    if (c.op == CondOp::kAtom) {
      const ConditionDecl* d = FindCondition(c.name);
      if (!d) {
        if (FindAction(c.name) || FindProgram(c.name)) {
          Error(c.where, "'" + c.name + "' is an action or program, not a condition");
        } else {
          Error(c.where,
                "undefined condition '" + c.name + "' (declare it: condition " + c.name + ";)");
        }
        return;
      }
      if (c.args.size() != d->params.size()) {
        Error(c.where, "condition '" + c.name + "' takes " + std::to_string(d->params.size()) +
                           " argument(s), found " + std::to_string(c.args.size()));
        return;
      }
      for (size_t k = 0; k < c.args.size(); ++k) {
        const Arg& a = c.args[k];
        if (!d->params[k].is_output) {
          CheckInput(a, params);
          continue;
        }
        if (a.kind != Arg::Kind::kVariable) {
          Error(a.where, "output '" + d->params[k].name + "' of '" + c.name +
                             "' must be bound to a variable name");
        } else if (params.count(a.text)) {
          Error(a.where, "output variable '" + a.text + "' hides a parameter of the program");
        } else if (!outputs.emplace(a.text, a.where).second) {
          Error(a.where, "output variable '" + a.text + "' is bound twice in this condition");
        }
      }
      return;
    }
    if (c.IsBinary() && c.IsTimed() && c.timeout_s <= 0.0) {
      Error(c.where, "a timeout must be > 0 s");
    }
    for (const auto& k : c.children) CheckCondition(k, params, outputs);
    if (c.IsBinary() && c.IsTimed()) WarnSlowOperands(c, c);
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

  void CheckAction(const ActExpr& a, const std::set<std::string>& scope) {
    if (a.op != ActOp::kInvoke) {
      for (const auto& k : a.children) CheckAction(k, scope);
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
    for (const auto& arg : a.args) CheckInput(arg, scope);
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
      case CondOp::kAtom:
        return Formula::Atom(atoms.Get(AtomKey(c.name, FindCondition(c.name), c.args, false)));
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

  static std::string Situation(const Atoms& atoms, const std::vector<int8_t>& model,
                               const std::vector<bool>& relevant) {
    std::string s;
    for (size_t a = 0; a < atoms.names.size(); ++a) {
      if (!relevant[a]) continue;
      s += (s.empty() ? "" : ", ") + atoms.names[a] + (model[a] ? " true" : " false");
    }
    return s.empty() ? "always" : s;
  }

  ProgramVerdict AnalyzeLogic(const Program& p) {
    ProgramVerdict v;
    v.program = p.name;
    const int m = static_cast<int>(p.rules.size());
    v.parent.resize(m);
    for (int i = 0; i < m; ++i) v.parent[i] = i - 1;
    if (m == 0) return v;

    Atoms atoms;
    std::vector<Formula> k;
    k.reserve(m);
    for (const Rule& r : p.rules) k.push_back(ToFormula(r.condition, atoms));
    const int n = static_cast<int>(atoms.names.size());

    // One solver with t_i <-> K_i for every rule; queries are assumptions on the t_i.
    internal::SatSolver solver;
    internal::TseitinEncoder enc(solver, n);
    std::vector<int> t(m);
    for (int i = 0; i < m; ++i) t[i] = enc.Encode(k[i]);
    auto read_model = [&](std::vector<int8_t>& model) {
      for (int a = 0; a < n; ++a) model[a] = solver.ModelValue(enc.atom_var(a)) ? 1 : 0;
    };

    // Reachability, rule by rule, keeping a model of "no rule above fires". A rule whose
    // condition can be made true by setting atoms no higher rule uses is reachable at once;
    // otherwise the solver decides. Linear for programs whose rules share few atoms.
    std::vector<int8_t> model(n, 0);
    std::vector<bool> seen(n, false);
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
          q.push_back(t[i]);
          reachable = solver.Solve(q);
        }
      }
      if (!reachable) {
        v.unreachable_rules.push_back(i);
        ReportUnreachable(p, i, k, prefix_complete, solver, t);
      }
      // Keep the model of "no rule up to i fires".
      if (!prefix_complete) {
        if (!FindFresh(k[i], fresh, model, false)) {
          std::vector<int> q = prefix_assumptions;
          q.push_back(internal::Negate(t[i]));
          if (solver.Solve(q)) {
            read_model(model);
          } else {
            prefix_complete = true;
          }
        }
        prefix_assumptions.push_back(internal::Negate(t[i]));
      }
      for (int a : atoms_of) seen[a] = true;
    }
    v.complete = prefix_complete;
    if (!v.complete) {
      std::vector<bool> relevant(n, true);
      Warning(p.where, "program '" + p.name + "' is not complete: no rule fires when " +
                           Situation(atoms, model, relevant));
    }

    // Regression, for rules that declare effects.
    bool regression = m >= 1;
    for (int i = 1; i < m; ++i) {
      const Rule& r = p.rules[i];
      if (!r.has_effects) {
        v.rules_without_effects.push_back(i);
        regression = false;
        continue;
      }
      std::vector<int8_t> fixed(n, -1);
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
      int achieved = -1;
      for (int j = i - 1; j >= 0 && known; --j) {
        internal::SatSolver s;
        internal::TseitinEncoder e(s, n);
        s.AddClause({e.Encode(k[i])});
        s.AddClause({internal::Negate(e.Encode(internal::Substitute(k[j], fixed)))});
        if (!s.Solve()) {
          achieved = j;
          break;
        }
      }
      if (achieved >= 0) {
        v.parent[i] = achieved;
      } else {
        regression = false;
        if (known) {
          Warning(r.where, RuleName(p, i) +
                               ": its declared effects do not achieve the condition of any "
                               "higher rule (regression property)");
        }
      }
    }
    v.regression = regression;
    return v;
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

  void ReportUnreachable(const Program& p, int i, const std::vector<Formula>& k,
                         bool prefix_complete, internal::SatSolver& solver,
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
    (void)k;
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
