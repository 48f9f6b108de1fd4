// The checker and compiler of RPL plans: resolves every name, checks every arity and shape, and
// builds the Form tree the runtime interprets. Nothing runs before this has passed.
#include <algorithm>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <unordered_map>

#include "rpl_executive/rpl/plan.h"

namespace rpl_executive {
namespace rpl {

const char* FailureClassName(FailureClass c) {
  switch (c) {
    case FailureClass::kModuleFailure:
      return "MODULE-FAILURE";
    case FailureClass::kInterrupted:
      return "INTERRUPTED";
    case FailureClass::kPlanFailure:
      return "PLAN-FAILURE";
    case FailureClass::kRuntimeError:
      return "RUNTIME-ERROR";
    case FailureClass::kAllFailed:
      return "ALL-FAILED";
  }
  return "FAILURE";
}

int Vocabulary::FindFluent(const std::string& name) const {
  for (size_t i = 0; i < fluents.size(); ++i) {
    if (fluents[i].name == name) return static_cast<int>(i);
  }
  return -1;
}
int Vocabulary::FindModule(const std::string& name) const {
  for (size_t i = 0; i < modules.size(); ++i) {
    if (modules[i].name == name) return static_cast<int>(i);
  }
  return -1;
}
int Vocabulary::FindFunction(const std::string& name) const {
  for (size_t i = 0; i < functions.size(); ++i) {
    if (functions[i].name == name) return static_cast<int>(i);
  }
  return -1;
}
int Vocabulary::FindValve(const std::string& name) const {
  for (size_t i = 0; i < valves.size(); ++i) {
    if (valves[i] == name) return static_cast<int>(i);
  }
  return -1;
}

int Plan::FindProcedure(const std::string& name) const {
  for (size_t i = 0; i < procedures.size(); ++i) {
    if (procedures[i].name == name) return static_cast<int>(i);
  }
  return -1;
}
int Plan::FindGlobal(const std::string& name) const {
  for (size_t i = 0; i < globals.size(); ++i) {
    if (globals[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::string Plan::Text(const Form& f) {
  if (f.datum) return PrintDatum(*f.datum);
  if (f.kind == FormKind::kSeq) return "(SEQ ...)";
  return "<form>";
}

namespace {

struct SpecialForm {
  const char* name;
  FormKind kind;
};
const SpecialForm kSpecialForms[] = {
    {"QUOTE", FormKind::kConstant},
    {"IF", FormKind::kIf},
    {"AND", FormKind::kAnd},
    {"OR", FormKind::kOr},
    {"SEQ", FormKind::kSeq},
    {"PAR", FormKind::kPar},
    {"TRY-ALL", FormKind::kTryAll},
    {"TRY-IN-ORDER", FormKind::kTryInOrder},
    {"LOOP", FormKind::kLoop},
    {"WHENEVER", FormKind::kWhenever},
    {"WAIT-FOR", FormKind::kWaitFor},
    {"WAIT-TIME", FormKind::kWaitTime},
    {"WITH-POLICY", FormKind::kWithPolicy},
    {"WITH-VALVE", FormKind::kWithValve},
    {"EVAP-PROTECT", FormKind::kEvapProtect},
    {"PROCESS", FormKind::kProcess},
    {"LET", FormKind::kLet},
    {"SETF", FormKind::kSetfLocal},
    {"EXECUTE", FormKind::kExecute},
    {"ACTIVATE", FormKind::kActivate},
    {"DEACTIVATE", FormKind::kDeactivate},
    {"VERIFY-CONDITION", FormKind::kVerifyCondition},
    {"FAIL", FormKind::kFail},
    {"PULSE", FormKind::kPulse},
    {"WITH-FAILURE-HANDLING", FormKind::kWithFailureHandling},
};

struct BuiltinSpec {
  const char* name;
  Builtin op;
  int min_args;
  int max_args;  // -1: any
};
const BuiltinSpec kBuiltins[] = {
    {"+", Builtin::kAdd, 0, -1},         {"-", Builtin::kSub, 1, -1},
    {"*", Builtin::kMul, 0, -1},         {"/", Builtin::kDiv, 1, -1},
    {"=", Builtin::kNumEq, 2, -1},       {"/=", Builtin::kNumNe, 2, 2},
    {"<", Builtin::kLt, 2, -1},          {"<=", Builtin::kLe, 2, -1},
    {">", Builtin::kGt, 2, -1},          {">=", Builtin::kGe, 2, -1},
    {"NOT", Builtin::kNot, 1, 1},        {"ABS", Builtin::kAbs, 1, 1},
    {"SQRT", Builtin::kSqrt, 1, 1},      {"MIN", Builtin::kMin, 1, -1},
    {"MAX", Builtin::kMax, 1, -1},       {"LIST", Builtin::kList, 0, -1},
    {"FIRST", Builtin::kFirst, 1, 1},    {"SECOND", Builtin::kSecond, 1, 1},
    {"THIRD", Builtin::kThird, 1, 1},    {"NTH", Builtin::kNth, 2, 2},
    {"LENGTH", Builtin::kLength, 1, 1},  {"DISTANCE", Builtin::kDistance, 2, 2},
    {"CONCAT", Builtin::kConcat, 0, -1}, {"EQUAL", Builtin::kEqual, 2, 2},
};

const char* const kDefinitionForms[] = {"DEFUN", "DEF-INTERRUPTIBLE-PROCEDURE", "DEFVAR",
                                        "DEF-FLUENT", "DEF-PULSE"};

const SpecialForm* FindSpecial(const std::string& name) {
  for (const auto& s : kSpecialForms) {
    if (name == s.name) return &s;
  }
  return nullptr;
}
const BuiltinSpec* FindBuiltin(const std::string& name) {
  for (const auto& b : kBuiltins) {
    if (name == b.name) return &b;
  }
  return nullptr;
}
bool IsDefinitionForm(const std::string& name) {
  for (const char* d : kDefinitionForms) {
    if (name == d) return true;
  }
  return false;
}

std::string ArgCount(int n) { return std::to_string(n) + (n == 1 ? " argument" : " arguments"); }

std::string ArityText(int min_args, int max_args) {
  if (max_args < 0) return "at least " + ArgCount(min_args);
  if (min_args == max_args) return ArgCount(min_args);
  return std::to_string(min_args) + " to " + ArgCount(max_args);
}

size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

Value DatumToValue(const Datum& d) {
  switch (d.kind) {
    case Datum::Kind::kNumber:
      return Value::Number(d.number);
    case Datum::Kind::kString:
      return Value::String(d.text);
    case Datum::Kind::kSymbol:
      return Value::Symbol(d.text);
    case Datum::Kind::kList: {
      std::vector<Value> items;
      for (const auto& item : d.items) items.push_back(DatumToValue(item));
      return Value::List(std::move(items));
    }
  }
  return Value();
}

class Compiler {
 public:
  Compiler(const Vocabulary& vocabulary, Plan* plan) : voc_(vocabulary), plan_(plan) {}

  std::vector<Diagnostic> Run() {
    plan_->num_vocabulary_fluents = static_cast<int>(voc_.fluents.size());
    std::vector<const Datum*> main_forms;
    CollectDefinitions(&main_forms);
    CompileDefinitions();
    // The top-level activities, in one frame of their own.
    BeginFrame();
    std::vector<const Form*> items;
    for (const Datum* d : main_forms) items.push_back(Compile(*d));
    if (main_forms.empty() && errors_ == 0) {
      Error(1, 1, "the plan has no top-level activity (only definitions)");
    }
    Form* main = New(FormKind::kSeq, main_forms.empty() ? 1 : main_forms[0]->line,
                     main_forms.empty() ? 1 : main_forms[0]->column, nullptr);
    main->args = std::move(items);
    plan_->main = main;
    plan_->main_frame_size = EndFrame();
    if (errors_ == 0) {
      ComputePurity();
      CheckConditions();
      ClassifyPlanFluents();
      CheckDerivedFluentCycles();
    }
    return std::move(diagnostics_);
  }

 private:
  // ---- diagnostics ---------------------------------------------------------------------------
  void Error(int line, int column, std::string message) {
    ++errors_;
    diagnostics_.push_back(
        {Diagnostic::Severity::kError, plan_->file, {line, column}, std::move(message)});
  }
  void Error(const Datum& d, std::string message) { Error(d.line, d.column, std::move(message)); }
  void Warning(const Datum& d, std::string message) {
    diagnostics_.push_back(
        {Diagnostic::Severity::kWarning, plan_->file, {d.line, d.column}, std::move(message)});
  }

  std::string Suggest(const std::string& name, const std::vector<std::string>& candidates) {
    std::string best;
    size_t best_distance = name.size() >= 5 ? 2 : 1;
    for (const auto& c : candidates) {
      const size_t dist = EditDistance(name, c);
      if (dist <= best_distance && c != name) {
        if (best.empty() || dist < best_distance) best = c;
        best_distance = dist;
      }
    }
    return best.empty() ? "" : " (did you mean " + best + "?)";
  }

  std::vector<std::string> OperatorNames() const {
    std::vector<std::string> names;
    for (const auto& s : kSpecialForms) names.push_back(s.name);
    for (const auto& b : kBuiltins) names.push_back(b.name);
    for (const auto& p : plan_->procedures) names.push_back(p.name);
    for (const auto& f : voc_.functions) names.push_back(f.name);
    for (const char* d : kDefinitionForms) names.push_back(d);
    return names;
  }
  std::vector<std::string> ValueNames() const {
    std::vector<std::string> names;
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
      for (const auto& v : *it) names.push_back(v.first);
    }
    for (const auto& g : plan_->globals) names.push_back(g.name);
    for (const auto& f : voc_.fluents) names.push_back(f.name);
    for (const auto& f : plan_->fluents) names.push_back(f.name);
    return names;
  }

  // ---- forms ---------------------------------------------------------------------------------
  Form* New(FormKind kind, int line, int column, const Datum* datum) {
    plan_->forms.emplace_back();
    Form* f = &plan_->forms.back();
    f->kind = kind;
    f->line = line;
    f->column = column;
    f->datum = datum;
    f->id = static_cast<int>(plan_->forms.size()) - 1;
    return f;
  }
  Form* New(FormKind kind, const Datum& d) { return New(kind, d.line, d.column, &d); }
  const Form* Constant(const Datum& d, Value v) {
    Form* f = New(FormKind::kConstant, d);
    f->constant = std::move(v);
    return f;
  }
  // A placeholder after an error, so that compilation goes on and finds more errors.
  const Form* Bad(const Datum& d) { return Constant(d, Value()); }

  // ---- frames and scopes ---------------------------------------------------------------------
  void BeginFrame() {
    scopes_.clear();
    scopes_.emplace_back();
    next_slot_ = 0;
    max_slot_ = 0;
  }
  int EndFrame() {
    scopes_.clear();
    return max_slot_;
  }
  int Declare(const std::string& name) {
    const int slot = next_slot_++;
    max_slot_ = std::max(max_slot_, next_slot_);
    scopes_.back().push_back({name, slot});
    return slot;
  }
  int FindLocal(const std::string& name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
      for (auto v = it->rbegin(); v != it->rend(); ++v) {
        if (v->first == name) return v->second;
      }
    }
    return -1;
  }
  int FindPlanFluent(const std::string& name) const {
    for (size_t i = 0; i < plan_->fluents.size(); ++i) {
      if (plan_->fluents[i].name == name) return static_cast<int>(i);
    }
    return -1;
  }
  int FindAnyFluent(const std::string& name) const {
    const int v = voc_.FindFluent(name);
    if (v >= 0) return v;
    const int p = FindPlanFluent(name);
    return p >= 0 ? plan_->num_vocabulary_fluents + p : -1;
  }

  // Why `name` cannot be defined or bound by the plan, or "" when it can.
  std::string Reserved(const std::string& name) const {
    if (name == "T" || name == "NIL") return name + " is a constant";
    if (!name.empty() && name[0] == ':') return name + " is a keyword (it stands for itself)";
    if (name == "UNTIL") return "UNTIL is part of LOOP";
    if (FindSpecial(name)) return name + " is a special form";
    if (IsDefinitionForm(name)) return name + " is a definition form";
    if (FindBuiltin(name)) return name + " is a builtin function";
    if (voc_.FindFunction(name) >= 0) return name + " is a function of the robot";
    if (voc_.FindModule(name) >= 0) return name + " is a behaviour module";
    if (voc_.FindValve(name) >= 0) return name + " is a valve";
    if (voc_.FindFluent(name) >= 0) return name + " is a fluent of the robot";
    return "";
  }

  // ---- pass 1: definitions -------------------------------------------------------------------
  void CollectDefinitions(std::vector<const Datum*>* main_forms) {
    std::map<std::string, std::pair<int, int>> defined;  // name -> where
    auto define = [&](const Datum& name_datum) -> bool {
      if (!name_datum.IsSymbol()) {
        Error(name_datum, "a definition needs a name (a symbol), not " + PrintDatum(name_datum));
        return false;
      }
      const std::string reserved = Reserved(name_datum.text);
      if (!reserved.empty()) {
        Error(name_datum, "cannot define " + name_datum.text + ": " + reserved);
        return false;
      }
      auto it = defined.find(name_datum.text);
      if (it != defined.end()) {
        Error(name_datum, name_datum.text + " is already defined at " + plan_->file + ":" +
                              std::to_string(it->second.first) + ":" +
                              std::to_string(it->second.second));
        return false;
      }
      defined[name_datum.text] = {name_datum.line, name_datum.column};
      return true;
    };
    for (const Datum& d : plan_->data) {
      const std::string& head = d.Head();
      if (head == "DEFUN" || head == "DEF-INTERRUPTIBLE-PROCEDURE") {
        if (d.items.size() < 4) {
          Error(d, "(" + head + " NAME (PARAMETERS...) BODY...) needs a name, a parameter list " +
                       "and at least one body form");
          continue;
        }
        if (!define(d.items[1])) continue;
        if (!d.items[2].IsList()) {
          Error(d.items[2], "the parameter list of " + d.items[1].text + " must be a list, e.g. " +
                                "(DEST) or ()");
          continue;
        }
        Procedure p;
        p.name = d.items[1].text;
        p.interruptible = head == "DEF-INTERRUPTIBLE-PROCEDURE";
        p.num_params = static_cast<int>(d.items[2].items.size());
        p.line = d.line;
        p.column = d.column;
        plan_->procedures.push_back(p);
        procedure_data_.push_back(&d);
      } else if (head == "DEFVAR") {
        if (d.items.size() != 3) {
          Error(d, "(DEFVAR NAME INITIAL-VALUE) takes a name and an initial value");
          continue;
        }
        if (!define(d.items[1])) continue;
        plan_->globals.push_back({d.items[1].text, nullptr, d.line, d.column});
        global_data_.push_back(&d);
      } else if (head == "DEF-FLUENT") {
        if (d.items.size() != 3) {
          Error(d,
                "(DEF-FLUENT NAME VALUE-OR-EXPRESSION) takes a name and an initial value or "
                "an expression over other fluents");
          continue;
        }
        if (!define(d.items[1])) continue;
        plan_->fluents.push_back(
            {d.items[1].text, PlanFluent::Kind::kValue, nullptr, d.line, d.column});
        fluent_data_.push_back(&d);
      } else if (head == "DEF-PULSE") {
        if (d.items.size() != 2 && d.items.size() != 3) {
          Error(d, "(DEF-PULSE NAME [CONDITION]) takes a name and an optional condition");
          continue;
        }
        if (!define(d.items[1])) continue;
        plan_->fluents.push_back(
            {d.items[1].text, PlanFluent::Kind::kPulse, nullptr, d.line, d.column});
        fluent_data_.push_back(&d);
      } else {
        main_forms->push_back(&d);
      }
    }
  }

  void CompileDefinitions() {
    for (size_t i = 0; i < plan_->procedures.size(); ++i) {
      const Datum& d = *procedure_data_[i];
      Procedure& p = plan_->procedures[i];
      BeginFrame();
      std::set<std::string> seen;
      for (const Datum& param : d.items[2].items) {
        if (!param.IsSymbol()) {
          Error(param, "a parameter must be a symbol, not " + PrintDatum(param));
          Declare("");
          continue;
        }
        const std::string reserved = Reserved(param.text);
        if (!reserved.empty()) {
          Error(param, "cannot use " + param.text + " as a parameter: " + reserved);
        } else if (FindPlanFluent(param.text) >= 0) {
          Error(param, "cannot use " + param.text + " as a parameter: it is a fluent of the plan");
        } else if (!seen.insert(param.text).second) {
          Error(param, "parameter " + param.text + " appears twice");
        }
        Declare(param.text);
      }
      p.body = CompileBody(d, 3);
      p.frame_size = EndFrame();
    }
    for (size_t i = 0; i < plan_->globals.size(); ++i) {
      BeginFrame();
      plan_->globals[i].init = Compile(global_data_[i]->items[2]);
      EndFrame();
    }
    for (size_t i = 0; i < plan_->fluents.size(); ++i) {
      const Datum& d = *fluent_data_[i];
      if (d.items.size() == 3) {
        BeginFrame();
        plan_->fluents[i].expr = Compile(d.items[2]);
        EndFrame();
      }
    }
  }

  // ---- pass 2: forms -------------------------------------------------------------------------
  // Items d.items[from..] as one form (a SEQ when more than one).
  const Form* CompileBody(const Datum& d, size_t from) {
    if (from >= d.items.size()) return Constant(d, Value());
    if (from + 1 == d.items.size()) return Compile(d.items[from]);
    Form* seq = New(FormKind::kSeq, d.items[from].line, d.items[from].column, nullptr);
    for (size_t i = from; i < d.items.size(); ++i) seq->args.push_back(Compile(d.items[i]));
    return seq;
  }

  bool CheckArity(const Datum& d, const std::string& what, int min_args, int max_args) {
    const int n = static_cast<int>(d.items.size()) - 1;
    if (n < min_args || (max_args >= 0 && n > max_args)) {
      Error(d, what + " takes " + ArityText(min_args, max_args) + ", got " + std::to_string(n));
      return false;
    }
    return true;
  }

  const Form* Compile(const Datum& d) {
    switch (d.kind) {
      case Datum::Kind::kNumber:
        return Constant(d, Value::Number(d.number));
      case Datum::Kind::kString:
        return Constant(d, Value::String(d.text));
      case Datum::Kind::kSymbol:
        return CompileSymbol(d);
      case Datum::Kind::kList:
        break;
    }
    if (d.items.empty()) return Constant(d, Value());
    const Datum& head = d.items[0];
    if (!head.IsSymbol()) {
      Error(head, "a form starts with the name of an operator, not " + PrintDatum(head));
      return Bad(d);
    }
    const std::string& op = head.text;
    if (const SpecialForm* special = FindSpecial(op)) return CompileSpecial(d, special->kind);
    if (const BuiltinSpec* b = FindBuiltin(op)) {
      if (!CheckArity(d, op, b->min_args, b->max_args)) return Bad(d);
      Form* f = New(FormKind::kBuiltin, d);
      f->index = static_cast<int>(b->op);
      for (size_t i = 1; i < d.items.size(); ++i) f->args.push_back(Compile(d.items[i]));
      return f;
    }
    const int procedure = plan_->FindProcedure(op);
    if (procedure >= 0) {
      const int n = plan_->procedures[procedure].num_params;
      if (!CheckArity(d, "procedure " + op, n, n)) return Bad(d);
      Form* f = New(FormKind::kCall, d);
      f->index = procedure;
      for (size_t i = 1; i < d.items.size(); ++i) f->args.push_back(Compile(d.items[i]));
      return f;
    }
    const int function = voc_.FindFunction(op);
    if (function >= 0) {
      const FunctionSpec& spec = voc_.functions[function];
      if (!CheckArity(d, "function " + op, spec.min_args, spec.max_args)) return Bad(d);
      Form* f = New(FormKind::kHostCall, d);
      f->index = function;
      for (size_t i = 1; i < d.items.size(); ++i) f->args.push_back(Compile(d.items[i]));
      return f;
    }
    if (voc_.FindModule(op) >= 0) {
      Error(head, op + " is a behaviour module: run it with (EXECUTE " + op +
                      " ...), start it with (ACTIVATE " + op + " ...), stop it with (DEACTIVATE " +
                      op + ")");
      return Bad(d);
    }
    if (IsDefinitionForm(op)) {
      Error(head, op + " is allowed only at the top level of a plan");
      return Bad(d);
    }
    if (op == "UNTIL") {
      Error(head, "UNTIL is allowed only directly inside LOOP: (LOOP body... UNTIL condition)");
      return Bad(d);
    }
    if (FindLocal(op) >= 0 || plan_->FindGlobal(op) >= 0 || FindAnyFluent(op) >= 0) {
      Error(head, op + " is a variable or fluent, not an operator");
      return Bad(d);
    }
    Error(head, "unknown operator " + op + Suggest(op, OperatorNames()));
    return Bad(d);
  }

  const Form* CompileSymbol(const Datum& d) {
    const std::string& name = d.text;
    if (name == "T") return Constant(d, Value::True());
    if (name == "NIL") return Constant(d, Value());
    if (name[0] == ':') return Constant(d, Value::Symbol(name));
    const int local = FindLocal(name);
    if (local >= 0) {
      Form* f = New(FormKind::kLocal, d);
      f->index = local;
      return f;
    }
    const int global = plan_->FindGlobal(name);
    if (global >= 0) {
      Form* f = New(FormKind::kGlobal, d);
      f->index = global;
      return f;
    }
    const int fluent = FindAnyFluent(name);
    if (fluent >= 0) {
      Form* f = New(FormKind::kFluent, d);
      f->index = fluent;
      return f;
    }
    if (plan_->FindProcedure(name) >= 0 || voc_.FindFunction(name) >= 0) {
      Error(d, name + " is a procedure: call it as (" + name + " ...)");
    } else if (voc_.FindModule(name) >= 0) {
      Error(d, name + " is a behaviour module: run it with (EXECUTE " + name + " ...)");
    } else if (FindSpecial(name) || FindBuiltin(name)) {
      Error(d, name + " is an operator: write (" + name + " ...)");
    } else {
      Error(d, "unknown name " + name + " (not a variable, a DEFVAR, a fluent or a constant)" +
                   Suggest(name, ValueNames()));
    }
    return Bad(d);
  }

  const Form* CompileSpecial(const Datum& d, FormKind kind) {
    const std::string& op = d.items[0].text;
    const size_t n = d.items.size() - 1;
    switch (kind) {
      case FormKind::kConstant:  // QUOTE
        if (!CheckArity(d, "QUOTE", 1, 1)) return Bad(d);
        return Constant(d, DatumToValue(d.items[1]));
      case FormKind::kIf: {
        if (!CheckArity(d, "IF", 2, 3)) return Bad(d);
        Form* f = New(kind, d);
        for (size_t i = 1; i < d.items.size(); ++i) f->args.push_back(Compile(d.items[i]));
        if (n == 2) f->args.push_back(Constant(d, Value()));
        return f;
      }
      case FormKind::kAnd:
      case FormKind::kOr:
      case FormKind::kSeq: {
        Form* f = New(kind, d);
        for (size_t i = 1; i < d.items.size(); ++i) f->args.push_back(Compile(d.items[i]));
        return f;
      }
      case FormKind::kPar:
      case FormKind::kTryAll:
      case FormKind::kTryInOrder: {
        if (!CheckArity(d, op, 1, -1)) return Bad(d);
        Form* f = New(kind, d);
        for (size_t i = 1; i < d.items.size(); ++i) f->args.push_back(Compile(d.items[i]));
        return f;
      }
      case FormKind::kLoop:
        return CompileLoop(d);
      case FormKind::kWhenever: {
        if (!CheckArity(d, "WHENEVER", 2, -1)) return Bad(d);
        Form* f = New(kind, d);
        f->args.push_back(Compile(d.items[1]));
        f->args.push_back(CompileBody(d, 2));
        conditions_.push_back({f->args[0], "WHENEVER"});
        return f;
      }
      case FormKind::kWaitFor: {
        if (!CheckArity(d, "WAIT-FOR", 1, 1)) return Bad(d);
        Form* f = New(kind, d);
        f->args.push_back(Compile(d.items[1]));
        conditions_.push_back({f->args[0], "WAIT-FOR"});
        return f;
      }
      case FormKind::kWaitTime:
      case FormKind::kVerifyCondition:
      case FormKind::kFail: {
        if (!CheckArity(d, op, 1, 1)) return Bad(d);
        Form* f = New(kind, d);
        f->args.push_back(Compile(d.items[1]));
        return f;
      }
      case FormKind::kWithPolicy: {
        if (!CheckArity(d, "WITH-POLICY", 2, -1)) return Bad(d);
        Form* f = New(kind, d);
        f->args.push_back(Compile(d.items[1]));
        f->args.push_back(CompileBody(d, 2));
        return f;
      }
      case FormKind::kWithValve: {
        if (!CheckArity(d, "WITH-VALVE", 2, -1)) return Bad(d);
        const Datum& valve = d.items[1];
        const int index = valve.IsSymbol() ? voc_.FindValve(valve.text) : -1;
        if (index < 0) {
          std::string known;
          for (const auto& v : voc_.valves) known += (known.empty() ? "" : ", ") + v;
          Error(valve,
                "unknown valve " + PrintDatum(valve) +
                    (known.empty() ? " (the robot has no valves)" : " (valves: " + known + ")"));
          return Bad(d);
        }
        Form* f = New(kind, d);
        f->index = index;
        f->args.push_back(CompileBody(d, 2));
        return f;
      }
      case FormKind::kEvapProtect: {
        if (!CheckArity(d, "EVAP-PROTECT", 2, 2)) return Bad(d);
        Form* f = New(kind, d);
        f->args.push_back(Compile(d.items[1]));
        f->args.push_back(Compile(d.items[2]));
        return f;
      }
      case FormKind::kProcess: {
        if (!CheckArity(d, "PROCESS", 2, -1)) return Bad(d);
        if (!d.items[1].IsSymbol()) {
          Error(d.items[1],
                "(PROCESS NAME BODY...) needs a name (a symbol), not " + PrintDatum(d.items[1]));
          return Bad(d);
        }
        Form* f = New(kind, d);
        f->constant = Value::Symbol(d.items[1].text);
        f->args.push_back(CompileBody(d, 2));
        return f;
      }
      case FormKind::kLet:
        return CompileLet(d);
      case FormKind::kSetfLocal:
        return CompileSetf(d);
      case FormKind::kExecute:
      case FormKind::kActivate:
      case FormKind::kDeactivate: {
        if (n < 1 || !d.items[1].IsSymbol()) {
          Error(d, "(" + op + " MODULE" + (kind == FormKind::kDeactivate ? "" : " ARGUMENTS...") +
                       ") needs the name of a behaviour module");
          return Bad(d);
        }
        const Datum& module = d.items[1];
        const int index = voc_.FindModule(module.text);
        if (index < 0) {
          std::vector<std::string> names;
          for (const auto& m : voc_.modules) names.push_back(m.name);
          Error(module, "unknown behaviour module " + module.text + Suggest(module.text, names));
          return Bad(d);
        }
        const ModuleSpec& spec = voc_.modules[index];
        if (kind == FormKind::kDeactivate) {
          if (!CheckArity(d, "DEACTIVATE", 1, 1)) return Bad(d);
        } else {
          const int args = static_cast<int>(n) - 1;
          if (args < spec.min_args || (spec.max_args >= 0 && args > spec.max_args)) {
            Error(d, "behaviour module " + spec.name + " takes " +
                         ArityText(spec.min_args, spec.max_args) + ", got " + std::to_string(args));
            return Bad(d);
          }
        }
        Form* f = New(kind, d);
        f->index = index;
        for (size_t i = 2; i < d.items.size(); ++i) f->args.push_back(Compile(d.items[i]));
        return f;
      }
      case FormKind::kPulse: {
        if (!CheckArity(d, "PULSE", 1, 1)) return Bad(d);
        const Datum& name = d.items[1];
        const int p = name.IsSymbol() ? FindPlanFluent(name.text) : -1;
        if (p < 0 || plan_->fluents[p].kind != PlanFluent::Kind::kPulse) {
          Error(name, PrintDatum(name) + " is not a pulsed fluent of the plan (define it with " +
                          "(DEF-PULSE NAME))");
          return Bad(d);
        }
        Form* f = New(kind, d);
        f->index = plan_->num_vocabulary_fluents + p;
        return f;
      }
      case FormKind::kWithFailureHandling:
        return CompileFailureHandling(d);
      default:
        break;
    }
    Error(d, "internal: unhandled special form " + op);
    return Bad(d);
  }

  const Form* CompileLoop(const Datum& d) {
    if (!CheckArity(d, "LOOP", 1, -1)) return Bad(d);
    Form* f = New(FormKind::kLoop, d);
    for (size_t i = 1; i < d.items.size(); ++i) {
      const Datum& item = d.items[i];
      if (item.IsSymbol("UNTIL")) {
        if (i + 1 >= d.items.size()) {
          Error(item, "UNTIL must be followed by a condition");
          return Bad(d);
        }
        Form* until = New(FormKind::kUntil, item);
        until->args.push_back(Compile(d.items[++i]));
        f->args.push_back(until);
      } else {
        f->args.push_back(Compile(item));
      }
    }
    return f;
  }

  const Form* CompileLet(const Datum& d) {
    if (!CheckArity(d, "LET", 2, -1)) return Bad(d);
    const Datum& bindings = d.items[1];
    if (!bindings.IsList()) {
      Error(bindings, "LET needs a list of bindings: (LET ((VAR VALUE) ...) BODY...)");
      return Bad(d);
    }
    Form* f = New(FormKind::kLet, d);
    // The initial values are evaluated outside the new scope (LET binds in parallel).
    std::vector<std::string> names;
    std::vector<int> slots;
    for (const Datum& b : bindings.items) {
      const Datum* name = nullptr;
      const Datum* init = nullptr;
      if (b.IsSymbol()) {
        name = &b;
      } else if (b.IsList() && (b.items.size() == 1 || b.items.size() == 2) &&
                 b.items[0].IsSymbol()) {
        name = &b.items[0];
        if (b.items.size() == 2) init = &b.items[1];
      } else {
        Error(b, "a LET binding is VAR or (VAR VALUE), not " + PrintDatum(b));
        continue;
      }
      const std::string reserved = Reserved(name->text);
      if (!reserved.empty()) {
        Error(*name, "cannot bind " + name->text + ": " + reserved);
        continue;
      }
      if (FindPlanFluent(name->text) >= 0) {
        Error(*name, "cannot bind " + name->text + ": it is a fluent of the plan");
        continue;
      }
      if (std::find(names.begin(), names.end(), name->text) != names.end()) {
        Error(*name, "variable " + name->text + " is bound twice in this LET");
        continue;
      }
      Form* binding = New(FormKind::kSetfLocal, b);
      binding->args.push_back(init ? Compile(*init) : Constant(b, Value()));
      f->args.push_back(binding);
      names.push_back(name->text);
    }
    scopes_.emplace_back();
    for (size_t i = 0; i < names.size(); ++i) {
      const_cast<Form*>(f->args[i])->index = Declare(names[i]);
    }
    f->args.push_back(CompileBody(d, 2));
    scopes_.pop_back();
    return f;
  }

  const Form* CompileSetf(const Datum& d) {
    if (!CheckArity(d, "SETF", 2, 2)) return Bad(d);
    const Datum& place = d.items[1];
    if (!place.IsSymbol()) {
      Error(place, "SETF sets a variable or a fluent of the plan, not " + PrintDatum(place));
      return Bad(d);
    }
    const int local = FindLocal(place.text);
    const int global = plan_->FindGlobal(place.text);
    const int plan_fluent = FindPlanFluent(place.text);
    Form* f = nullptr;
    if (local >= 0) {
      f = New(FormKind::kSetfLocal, d);
      f->index = local;
    } else if (global >= 0) {
      f = New(FormKind::kSetfGlobal, d);
      f->index = global;
    } else if (plan_fluent >= 0) {
      if (plan_->fluents[plan_fluent].kind == PlanFluent::Kind::kPulse) {
        Error(place, place.text + " is a pulsed fluent: use (PULSE " + place.text + ")");
        return Bad(d);
      }
      // Whether it is a value fluent is known once the definitions are classified.
      f = New(FormKind::kSetfFluent, d);
      f->index = plan_->num_vocabulary_fluents + plan_fluent;
      setf_fluents_.push_back(f);
    } else if (voc_.FindFluent(place.text) >= 0) {
      Error(place, place.text + " is set by the robot; plans only read it");
      return Bad(d);
    } else {
      Error(place, "SETF of unknown variable " + place.text + Suggest(place.text, ValueNames()));
      return Bad(d);
    }
    f->args.push_back(Compile(d.items[2]));
    return f;
  }

  const Form* CompileFailureHandling(const Datum& d) {
    if (!CheckArity(d, "WITH-FAILURE-HANDLING", 2, -1)) return Bad(d);
    Form* f = New(FormKind::kWithFailureHandling, d);
    f->args.push_back(Compile(d.items[1]));
    for (size_t i = 2; i < d.items.size(); ++i) {
      const Datum& c = d.items[i];
      if (!c.IsList() || c.items.size() < 3 || !c.items[0].IsSymbol() || !c.items[1].IsList() ||
          c.items[1].items.size() > 1) {
        Error(c, "a failure handler is (CLASS (VAR) HANDLER...) or (CLASS () HANDLER...), " +
                     std::string("e.g. (MODULE-FAILURE (CAUSE) (SETF LAST CAUSE))"));
        continue;
      }
      const std::string& cls = c.items[0].text;
      int index = -2;
      if (cls == "FAILURE") index = -1;  // any class
      for (FailureClass k :
           {FailureClass::kModuleFailure, FailureClass::kInterrupted, FailureClass::kPlanFailure,
            FailureClass::kRuntimeError, FailureClass::kAllFailed}) {
        if (cls == FailureClassName(k)) index = static_cast<int>(k);
      }
      if (index == -2) {
        Error(c.items[0], "unknown failure class " + cls +
                              Suggest(cls, {"FAILURE", "MODULE-FAILURE", "INTERRUPTED",
                                            "PLAN-FAILURE", "RUNTIME-ERROR", "ALL-FAILED"}) +
                              " (classes: FAILURE (any), MODULE-FAILURE, INTERRUPTED, " +
                              "PLAN-FAILURE, RUNTIME-ERROR, ALL-FAILED)");
        continue;
      }
      Form* clause = New(FormKind::kHandlerClause, c);
      clause->index = index;
      scopes_.emplace_back();
      int slot = -1;
      if (c.items[1].items.size() == 1) {
        const Datum& var = c.items[1].items[0];
        const std::string reserved = var.IsSymbol() ? Reserved(var.text) : "not a symbol";
        if (!reserved.empty() || FindPlanFluent(var.text) >= 0) {
          Error(var, "cannot bind " + PrintDatum(var) + " to the failure: " +
                         (reserved.empty() ? "it is a fluent of the plan" : reserved));
        } else {
          slot = Declare(var.text);
        }
      }
      clause->constant = Value::Number(slot);
      clause->args.push_back(CompileBody(c, 2));
      scopes_.pop_back();
      f->args.push_back(clause);
    }
    return f;
  }

  // ---- analyses ------------------------------------------------------------------------------
  // Purity is a greatest fixpoint: procedures whose body is one expression are assumed pure until
  // their body is shown to run something that may block.
  bool IsPure(const Form& f) const {
    switch (f.kind) {
      case FormKind::kConstant:
      case FormKind::kLocal:
      case FormKind::kGlobal:
      case FormKind::kFluent:
        return true;
      case FormKind::kBuiltin:
      case FormKind::kHostCall:
      case FormKind::kIf:
      case FormKind::kAnd:
      case FormKind::kOr:
        for (const Form* a : f.args) {
          if (!IsPure(*a)) return false;
        }
        return true;
      case FormKind::kCall:
        if (!plan_->procedures[f.index].pure) return false;
        for (const Form* a : f.args) {
          if (!IsPure(*a)) return false;
        }
        return true;
      default:
        return false;
    }
  }

  void ComputePurity() {
    for (auto& p : plan_->procedures) p.pure = p.body && IsExpressionKind(p.body->kind);
    bool changed = true;
    while (changed) {
      changed = false;
      for (auto& p : plan_->procedures) {
        if (p.pure && !IsPure(*p.body)) {
          p.pure = false;
          changed = true;
        }
      }
    }
    for (auto& f : plan_->forms) f.pure = IsPure(f);
  }
  static bool IsExpressionKind(FormKind k) {
    return k == FormKind::kConstant || k == FormKind::kLocal || k == FormKind::kGlobal ||
           k == FormKind::kFluent || k == FormKind::kBuiltin || k == FormKind::kHostCall ||
           k == FormKind::kCall || k == FormKind::kIf || k == FormKind::kAnd || k == FormKind::kOr;
  }

  // The fluents a pure form reads, through the pure procedures it calls.
  void CollectFluents(const Form& f, std::set<int>* fluents, std::set<int>* procedures,
                      bool* reads_locals, bool top) const {
    if (f.kind == FormKind::kFluent) fluents->insert(f.index);
    if (f.kind == FormKind::kLocal && top) *reads_locals = true;
    if (f.kind == FormKind::kCall && procedures->insert(f.index).second) {
      CollectFluents(*plan_->procedures[f.index].body, fluents, procedures, reads_locals, false);
    }
    for (const Form* a : f.args) CollectFluents(*a, fluents, procedures, reads_locals, top);
  }

  const Form* FirstImpure(const Form& f) const {
    if (f.pure) return nullptr;
    for (const Form* a : f.args) {
      if (const Form* bad = FirstImpure(*a)) return bad;
    }
    return &f;
  }

  void AnalyseCondition(const Form* f) {
    std::set<int> fluents, procedures;
    bool reads_locals = false;
    CollectFluents(*f, &fluents, &procedures, &reads_locals, true);
    Form* mutable_form = const_cast<Form*>(f);
    mutable_form->fluent_deps.assign(fluents.begin(), fluents.end());
    mutable_form->reads_locals = reads_locals;
  }

  void CheckConditions() {
    for (const auto& c : conditions_) {
      const Form* f = c.first;
      if (!f->pure) {
        const Form* bad = FirstImpure(*f);
        Error(bad->line, bad->column,
              "the condition of " + c.second + " must be a fluent expression (fluents, " +
                  "variables, constants, operators and procedures that are one such " +
                  "expression); " + Plan::Text(*bad) + " can block");
        continue;
      }
      AnalyseCondition(f);
      if (f->fluent_deps.empty() && f->datum) {
        Warning(*f->datum, "the condition of " + c.second + " reads no fluent: if it is false " +
                               "the thread waits forever");
      }
    }
  }

  void ClassifyPlanFluents() {
    for (size_t i = 0; i < plan_->fluents.size(); ++i) {
      PlanFluent& pf = plan_->fluents[i];
      if (!pf.expr) continue;
      const Datum& d = fluent_data_[i]->items[2];
      if (!pf.expr->pure) {
        const Form* bad = FirstImpure(*pf.expr);
        Error(bad->line, bad->column,
              "the value of " + pf.name + " must be an expression that does not block; " +
                  Plan::Text(*bad) + " can block");
        continue;
      }
      AnalyseCondition(pf.expr);
      if (pf.kind == PlanFluent::Kind::kValue && !pf.expr->fluent_deps.empty()) {
        pf.kind = PlanFluent::Kind::kDerived;
      }
      if (pf.kind == PlanFluent::Kind::kPulse && pf.expr->fluent_deps.empty()) {
        Error(d, "the condition of pulse " + pf.name + " reads no fluent, so it never pulses");
      }
    }
    for (const Form* f : setf_fluents_) {
      const PlanFluent& pf = plan_->fluents[f->index - plan_->num_vocabulary_fluents];
      if (pf.kind != PlanFluent::Kind::kValue) {
        Error(f->line, f->column,
              pf.name +
                  " is computed from other fluents; SETF sets only fluents defined with "
                  "an initial value");
      }
    }
    for (size_t i = 0; i < plan_->globals.size(); ++i) {
      const Form* init = plan_->globals[i].init;
      if (init && !init->pure) {
        const Form* bad = FirstImpure(*init);
        Error(bad->line, bad->column,
              "the initial value of " + plan_->globals[i].name +
                  " must be an expression that does not block; " + Plan::Text(*bad) + " can block");
      }
    }
  }

  // A derived fluent computed from itself (directly or through others) would never settle.
  void CheckDerivedFluentCycles() {
    const int base = plan_->num_vocabulary_fluents;
    const int n = static_cast<int>(plan_->fluents.size());
    auto deps = [&](int i) -> std::vector<int> {
      std::vector<int> out;
      const PlanFluent& pf = plan_->fluents[i];
      if (pf.expr && pf.kind != PlanFluent::Kind::kValue) {
        for (int dep : pf.expr->fluent_deps) {
          if (dep >= base) out.push_back(dep - base);
        }
      }
      return out;
    };
    for (int i = 0; i < n; ++i) {
      std::vector<int> stack = deps(i);
      std::vector<bool> seen(n, false);
      bool cycle = false;
      while (!stack.empty() && !cycle) {
        const int j = stack.back();
        stack.pop_back();
        if (j == i) cycle = true;
        if (seen[j]) continue;
        seen[j] = true;
        for (int k : deps(j)) stack.push_back(k);
      }
      if (cycle) {
        const PlanFluent& pf = plan_->fluents[i];
        Error(pf.line, pf.column, "fluent " + pf.name + " depends on itself");
      }
    }
  }

  const Vocabulary& voc_;
  Plan* plan_;
  std::vector<Diagnostic> diagnostics_;
  int errors_ = 0;
  std::vector<const Datum*> procedure_data_, global_data_, fluent_data_;
  std::vector<std::vector<std::pair<std::string, int>>> scopes_;
  int next_slot_ = 0;
  int max_slot_ = 0;
  std::vector<std::pair<const Form*, std::string>> conditions_;
  std::vector<const Form*> setf_fluents_;
};

}  // namespace

CompileResult CompilePlan(const std::string& text, const std::string& file,
                          const Vocabulary& vocabulary) {
  CompileResult result;
  ReadResult read = ReadPlanText(text, file);
  const bool read_ok = read.ok();
  result.diagnostics = std::move(read.diagnostics);
  if (!read_ok) return result;
  auto plan = std::make_shared<Plan>();
  plan->file = file;
  plan->data = std::move(read.forms);
  std::vector<Diagnostic> more = Compiler(vocabulary, plan.get()).Run();
  result.diagnostics.insert(result.diagnostics.end(), more.begin(), more.end());
  if (!HasErrors(result.diagnostics)) result.plan = std::move(plan);
  return result;
}

}  // namespace rpl
}  // namespace rpl_executive
