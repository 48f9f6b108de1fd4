#include "rpl_executive/noreils_chatila/checker.h"

#include <set>

#include "rpl_executive/noreils_chatila/vocabulary.h"

namespace rpl_executive::noreils_chatila {

bool IsTerminal(const Monitor& monitor) {
  for (const Statement& r : monitor.reflex) {
    if (r.kind != Statement::Kind::kCommand) continue;
    const OperatorSpec* spec = FindOperator(r.op);
    if (spec != nullptr && spec->halts_current_action) return true;
  }
  return false;
}

namespace {

// Where a statement sits decides what it may be.
struct Context {
  bool in_control = false;  // a monitor's control action (NEXT, FAIL, resume-order, MNTR)
  bool in_main = false;     // a MAIN: body (sub-missions)
  bool in_env = false;      // ENV: only set
};

bool MentionsDecision(const std::vector<Statement>& body) {
  for (const Statement& s : body) {
    if (s.kind == Statement::Kind::kNext || s.kind == Statement::Kind::kFail) return true;
    if (s.kind == Statement::Kind::kCommand && s.op == "resume-order") return true;
    if ((s.kind == Statement::Kind::kIf || s.kind == Statement::Kind::kWhile) &&
        (MentionsDecision(s.then_body) || MentionsDecision(s.else_body))) {
      return true;
    }
  }
  return false;
}

void CollectSetTargets(const std::vector<Statement>& body, std::set<std::string>* out);

void CollectMonitorTargets(const Monitor& m, std::set<std::string>* out) {
  CollectSetTargets(m.control, out);
}

void CollectMissionTargets(const Mission& m, std::set<std::string>* out) {
  CollectSetTargets(m.env, out);
  for (const Monitor& mon : m.lsurv) CollectMonitorTargets(mon, out);
  CollectSetTargets(m.main, out);
}

void CollectSetTargets(const std::vector<Statement>& body, std::set<std::string>* out) {
  for (const Statement& s : body) {
    if (s.kind == Statement::Kind::kSet) out->insert(s.target);
    CollectSetTargets(s.then_body, out);
    CollectSetTargets(s.else_body, out);
    for (const Monitor& m : s.monitors) CollectMonitorTargets(m, out);
    if (s.monitor) CollectMonitorTargets(*s.monitor, out);
    if (s.mission) CollectMissionTargets(*s.mission, out);
  }
}

class Checker {
 public:
  Checker(const MissionFile& file, const CheckOptions& options) : file_(file), options_(options) {}

  std::vector<Diagnostic> Run() {
    std::map<std::string, const Definition*> defined;
    for (const Definition& d : file_.definitions) {
      auto it = defined.find(d.name);
      if (it != defined.end()) {
        Error(d.where, "'" + d.name + "' is already defined at line " +
                           std::to_string(it->second->where.line));
        continue;
      }
      for (const std::string& b : BuiltinVariables()) {
        if (b == d.name)
          Error(d.where, "'" + d.name +
                             "' is a variable of the executive: it "
                             "cannot be defined");
      }
      auto w = options_.world_variables.find(d.name);
      if (w != options_.world_variables.end() && w->second != d.value) {
        Warning(d.where, "'" + d.name + "' overrides the world's " + d.name + " " +
                             w->second.ToText() + " with " + d.value.ToText());
      }
      defined[d.name] = &d;
    }
    for (const auto& [name, d] : defined) values_[name] = d->value;
    for (const auto& [name, v] : options_.world_variables) values_.emplace(name, v);
    for (const std::string& b : BuiltinVariables()) runtime_.insert(b);
    for (const Mission& m : file_.missions) CollectMissionTargets(m, &runtime_);
    for (const Monitor& m : file_.o_surveillances) CollectMonitorTargets(m, &runtime_);
    for (const auto& [name, v] : values_) runtime_.erase(name);

    for (const Mission& m : file_.missions) CheckMission(m);
    for (const Monitor& m : file_.o_surveillances) CheckMonitor(m);
    return std::move(diagnostics_);
  }

 private:
  void Error(Location where, std::string message) {
    Diagnostic d;
    d.file = file_.file;
    d.where = where;
    d.message = std::move(message);
    diagnostics_.push_back(std::move(d));
  }
  void Warning(Location where, std::string message) {
    Error(where, std::move(message));
    diagnostics_.back().severity = Diagnostic::Severity::kWarning;
  }

  Lookup Resolve(const std::string& name) const {
    Lookup l;
    auto it = values_.find(name);
    if (it != values_.end()) {
      l.kind = Lookup::Kind::kValue;
      l.value = it->second;
    } else if (runtime_.count(name) != 0) {
      l.kind = Lookup::Kind::kUnknownValue;
    }
    return l;
  }
  Resolver resolver() const {
    return [this](const std::string& name) { return Resolve(name); };
  }
  bool Known(const std::string& name) const {
    return values_.count(name) != 0 || runtime_.count(name) != 0;
  }

  void CheckMission(const Mission& m) {
    for (const Test& t : m.pre) CheckTest(t);
    Context env;
    env.in_env = true;
    for (const Statement& s : m.env) {
      if (s.kind != Statement::Kind::kSet) {
        Error(s.where, "ENV: holds (set <variable> <value>) statements only");
        continue;
      }
      CheckStatement(s, env);
    }
    for (const Monitor& mon : m.lsurv) CheckMonitor(mon);
    Context main;
    main.in_main = true;
    if (m.main.empty()) Warning(m.where, "MISSION " + m.name + ": MAIN: is empty");
    for (const Statement& s : m.main) CheckStatement(s, main);
  }

  void CheckMonitor(const Monitor& m) {
    CheckCondition(m.condition);
    for (const Statement& r : m.reflex) {
      if (r.kind != Statement::Kind::kCommand) {
        Error(r.where,
              "a reflex action holds operator calls only (set-speed, stop, draw); "
              "decisions belong to the control action");
        continue;
      }
      const OperatorSpec* spec = FindOperator(r.op);
      if (spec == nullptr) {
        Error(r.op_where, "unknown operator '" + r.op + "'");
        continue;
      }
      if (!spec->reflex_allowed) {
        Error(r.op_where, "'" + r.op +
                              "' cannot be a reflex action: a reflex is immediate "
                              "(set-speed, stop, draw)");
        continue;
      }
      if (!r.monitors.empty()) {
        Error(r.monitors[0].where, "a reflex action carries no monitors");
      }
      CheckOperatorArguments(r);
    }
    Context control;
    control.in_control = true;
    for (const Statement& s : m.control) CheckStatement(s, control);
    if (IsTerminal(m) && !MentionsDecision(m.control)) {
      Warning(m.where, "terminal monitor " + m.condition.ToText() +
                           ": its control action holds no NEXT, FAIL or resume-order; the "
                           "stopped command ends and the mission goes on with the next one");
    }
  }

  void CheckOperatorArguments(const Statement& s) {
    Decoded<OperatorCommand> d = DecodeOperator(s, resolver());
    if (d.status == Decoded<OperatorCommand>::Status::kError) {
      Error(d.where.line > 0 ? d.where : s.where, d.error);
    }
  }

  void CheckStatement(const Statement& s, const Context& ctx) {
    switch (s.kind) {
      case Statement::Kind::kCommand:
      case Statement::Kind::kRun: {
        const OperatorSpec* spec = FindOperator(s.op);
        if (spec == nullptr) {
          std::string known;
          for (const OperatorSpec& o : Operators()) known += (known.empty() ? "" : ", ") + o.name;
          Error(s.op_where, "unknown operator '" + s.op + "' (known: " + known + ")");
          return;
        }
        if (s.op == "resume-order") {
          if (!ctx.in_control) {
            Error(s.op_where, "resume-order belongs in a monitor's control action");
          }
          if (!s.args.empty()) Error(s.op_where, "resume-order takes no arguments");
          if (!s.monitors.empty()) Error(s.monitors[0].where, "resume-order carries no monitors");
          return;
        }
        if (ctx.in_env) {
          Error(s.where, "ENV: holds (set <variable> <value>) statements only");
          return;
        }
        CheckOperatorArguments(s);
        for (const Monitor& m : s.monitors) CheckMonitor(m);
        if (s.kind == Statement::Kind::kRun && s.monitors.empty()) {
          Warning(s.where, "RUN (" + s.op +
                               "): a process never stops by itself (section 3.3); "
                               "without a monitor the command ends only if the process fails");
        }
        if (!spec->long_running && !s.monitors.empty()) {
          Warning(s.monitors[0].where, "'" + s.op +
                                           "' is done at once: its monitors are killed "
                                           "as soon as they are set");
        }
        return;
      }
      case Statement::Kind::kSet:
        CheckValue(s.value);
        return;
      case Statement::Kind::kIf:
        CheckTest(s.test);
        for (const Statement& b : s.then_body) CheckStatement(b, ctx);
        for (const Statement& b : s.else_body) CheckStatement(b, ctx);
        return;
      case Statement::Kind::kWhile:
        CheckTest(s.test);
        for (const Statement& b : s.then_body) CheckStatement(b, ctx);
        return;
      case Statement::Kind::kNext:
      case Statement::Kind::kFail:
        if (!ctx.in_control) {
          Error(s.where, std::string(s.kind == Statement::Kind::kNext ? "NEXT" : "FAIL") +
                             " is a key-word of control actions (section 5): it belongs after "
                             "'=>' and the reflex action");
        }
        return;
      case Statement::Kind::kMonitor:
        if (!ctx.in_control) {
          Error(s.where,
                "a nested (MNTR ...) is created by a control action; on a command, "
                "write MNTR after the operator's arguments");
          return;
        }
        CheckMonitor(*s.monitor);
        return;
      case Statement::Kind::kMission:
        if (!ctx.in_main) {
          Error(s.where, "a sub-mission belongs in a MAIN: body");
          return;
        }
        CheckMission(*s.mission);
        return;
    }
  }

  void CheckValue(const ValueExpr& v) {
    if (v.kind == ValueExpr::Kind::kDeref && !Known(v.name)) {
      Error(v.where, "'$" + v.name + "' names no variable");
    }
  }

  void CheckTest(const Test& t) {
    switch (t.kind) {
      case Test::Kind::kEq:
        CheckValue(t.lhs);
        CheckValue(t.rhs);
        if (t.lhs.kind == ValueExpr::Kind::kName && !Known(t.lhs.name)) {
          Warning(t.lhs.where, "'" + t.lhs.name +
                                   "' is not a variable: eq compares it as the "
                                   "symbol itself");
        }
        return;
      case Test::Kind::kNot:
      case Test::Kind::kAnd:
      case Test::Kind::kOr:
        for (const Test& c : t.children) CheckTest(c);
        return;
      case Test::Kind::kVariable:
        if (!Known(t.variable)) {
          Error(t.where, "unknown variable '" + t.variable +
                             "' (not defined, set, served by the "
                             "world, nor one of the executive's)");
        }
        return;
      case Test::Kind::kSensor:
        for (const ConditionNode& c : t.sensor) CheckCondition(c);
        return;
    }
  }

  void CheckCondition(const ConditionNode& c) {
    if (c.kind != ConditionNode::Kind::kAtom) {
      for (const ConditionNode& child : c.children) CheckCondition(child);
      return;
    }
    Decoded<CompiledCondition> d = DecodeCondition(c, resolver(), options_.sonar_count);
    if (d.status == Decoded<CompiledCondition>::Status::kError) {
      Error(d.where.line > 0 ? d.where : c.where, d.error);
    }
  }

  const MissionFile& file_;
  const CheckOptions& options_;
  std::map<std::string, Value> values_;
  std::set<std::string> runtime_;
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace

std::vector<Diagnostic> CheckMissionFile(const MissionFile& file, const CheckOptions& options) {
  return Checker(file, options).Run();
}

}  // namespace rpl_executive::noreils_chatila

namespace rpl_executive::noreils_chatila {

std::set<std::string> AssignedVariables(const MissionFile& file) {
  std::set<std::string> out;
  for (const Mission& m : file.missions) CollectMissionTargets(m, &out);
  for (const Monitor& m : file.o_surveillances) CollectMonitorTargets(m, &out);
  return out;
}

}  // namespace rpl_executive::noreils_chatila
