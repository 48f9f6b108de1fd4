// The public face of the RPL runtime, and the parts of the runtime that are neither the
// interpreter, the scheduler, the fluent network nor the valves: vocabulary, plan start-up,
// Step, introspection.
#include "rpl_executive/rpl/executive.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <stdexcept>

#include "runtime.h"

namespace rpl_executive {
namespace rpl {

// ---- small public types -----------------------------------------------------------------------

std::vector<std::string> ValidateParameters(const ExecutiveParameters& p) {
  std::vector<std::string> errors;
  auto check = [&errors](const char* name, long long value, long long lo, long long hi) {
    if (value < lo || value > hi) {
      errors.push_back(std::string(name) + ": must be in [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "], got " + std::to_string(value));
    }
  };
  check("max_instructions_per_step", p.max_instructions_per_step, 1, 1000000000);
  check("max_call_depth", p.max_call_depth, 1, 100000);
  check("event_log_capacity", p.event_log_capacity, 0, 10000000);
  check("max_live_tasks", p.max_live_tasks, 1, 100000000);
  return errors;
}

std::string Failure::ToString() const {
  std::string s = where.ToString() + ": " + FailureClassName(failure_class) + ": " + message;
  if (!task_path.empty()) s += " (in " + task_path + ")";
  for (const Failure& c : causes) {
    std::string text = c.ToString();
    size_t start = 0;
    while (start <= text.size()) {
      const size_t end = text.find('\n', start);
      s += "\n  " + text.substr(start, end == std::string::npos ? std::string::npos : end - start);
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }
  return s;
}

const char* Event::KindName(Kind kind) {
  switch (kind) {
    case Kind::kPlanStarted:
      return "PLAN-STARTED";
    case Kind::kPlanFinished:
      return "PLAN-FINISHED";
    case Kind::kModuleActivated:
      return "MODULE-ACTIVATED";
    case Kind::kModuleSucceeded:
      return "MODULE-SUCCEEDED";
    case Kind::kModuleFailed:
      return "MODULE-FAILED";
    case Kind::kModuleDeactivated:
      return "MODULE-DEACTIVATED";
    case Kind::kValveGranted:
      return "VALVE-GRANTED";
    case Kind::kValvePreempted:
      return "VALVE-PREEMPTED";
    case Kind::kValveReleased:
      return "VALVE-RELEASED";
    case Kind::kPulse:
      return "PULSE";
    case Kind::kCleanup:
      return "CLEANUP";
    case Kind::kThreadFailed:
      return "THREAD-FAILED";
    case Kind::kFailureHandled:
      return "FAILURE-HANDLED";
    case Kind::kThreadEnded:
      return "THREAD-ENDED";
  }
  return "?";
}

std::string Event::ToString() const {
  char time[32];
  std::snprintf(time, sizeof time, "%.3f", time_s);
  return std::string(time) + " " + KindName(kind) + " " + subject +
         (detail.empty() ? "" : ": " + detail);
}

const char* TaskInfo::StateName(State state) {
  switch (state) {
    case State::kActive:
      return "active";
    case State::kWaitBlocked:
      return "wait-blocked";
    case State::kEvaporating:
      return "evaporating";
  }
  return "?";
}

const char* PlanStateName(PlanState state) {
  switch (state) {
    case PlanState::kNoPlan:
      return "no plan";
    case PlanState::kLoaded:
      return "loaded";
    case PlanState::kRunning:
      return "running";
    case PlanState::kSucceeded:
      return "succeeded";
    case PlanState::kFailed:
      return "failed";
    case PlanState::kAborted:
      return "aborted";
  }
  return "?";
}

namespace internal {

namespace {
struct Counter {
  explicit Counter(int* c) : c_(c) { ++*c_; }
  ~Counter() { --*c_; }
  int* c_;
};

void CheckName(const std::string& name, const char* what) {
  bool ok = !name.empty() && name[0] != ':';
  for (char c : name) {
    ok = ok && !std::islower(static_cast<unsigned char>(c)) && c > ' ' && c != '(' && c != ')' &&
         c != '"' && c != ';' && c != '\'';
  }
  if (!ok) {
    throw std::invalid_argument(std::string("rpl: ") + what + " name '" + name +
                                "' must be an upper-case symbol as plans write it");
  }
}
}  // namespace

Runtime::Runtime(const ExecutiveParameters& parameters) : params_(parameters) {
  const std::vector<std::string> errors = ValidateParameters(parameters);
  if (!errors.empty()) {
    std::string all;
    for (const auto& e : errors) all += (all.empty() ? "" : "; ") + e;
    throw std::invalid_argument("rpl: invalid ExecutiveParameters: " + all);
  }
}

Runtime::~Runtime() {
  // The control processes still running stop; no cleanup runs (the executive is going away).
  std::vector<std::pair<ActivationId, int>> active;
  for (const auto& a : activations_) active.push_back({a.first, a.second.module});
  activations_.clear();
  ++in_callback_;
  for (const auto& a : active) modules_[a.second]->Deactivate(a.first, now_s_);
  --in_callback_;
  for (Task& t : tasks_) {
    if (t.state != TaskState::kFree && t.condition_owned) {
      t.link.Unlink();
      delete t.condition;
      t.condition = nullptr;
    }
  }
}

void Runtime::CheckNotInCallback(const char* what) const {
  if (in_callback_ > 0 || in_step_ > 0) {
    throw std::logic_error(std::string("rpl: ") + what +
                           " called from inside the executive (a module or host function)");
  }
}

void Runtime::Log(Event::Kind kind, std::string subject, std::string detail) {
  if (params_.event_log_capacity == 0 && !event_callback_) return;
  Event e{now_s_, kind, std::move(subject), std::move(detail)};
  if (event_callback_) event_callback_(e);
  if (params_.event_log_capacity > 0) {
    events_.push_back(std::move(e));
    while (events_.size() > static_cast<size_t>(params_.event_log_capacity)) events_.pop_front();
  }
}

// ---- vocabulary -------------------------------------------------------------------------------

void Runtime::DeclareFluent(const FluentSpec& spec) {
  CheckNotInCallback("DeclareFluent");
  CheckName(spec.name, "fluent");
  if (plan_) throw std::logic_error("rpl: declare fluents before a plan is loaded");
  if (vocabulary_.FindFluent(spec.name) >= 0 || vocabulary_.FindModule(spec.name) >= 0 ||
      vocabulary_.FindFunction(spec.name) >= 0 || vocabulary_.FindValve(spec.name) >= 0) {
    throw std::invalid_argument("rpl: " + spec.name + " is declared twice");
  }
  vocabulary_.fluents.push_back(spec);
  host_nodes_.push_back(std::make_unique<FluentNode>());
  FluentNode* n = host_nodes_.back().get();
  n->name = spec.name;
  n->value = spec.initial;
  nodes_.push_back(n);  // no plan is loaded: nodes_ holds only the vocabulary's fluents
}

void Runtime::AddModule(std::shared_ptr<BehaviourModule> module) {
  CheckNotInCallback("AddModule");
  if (!module) throw std::invalid_argument("rpl: AddModule: null module");
  if (plan_) throw std::logic_error("rpl: add modules before a plan is loaded");
  ModuleSpec spec = module->Spec();
  CheckName(spec.name, "module");
  if (vocabulary_.FindFluent(spec.name) >= 0 || vocabulary_.FindModule(spec.name) >= 0 ||
      vocabulary_.FindFunction(spec.name) >= 0 || vocabulary_.FindValve(spec.name) >= 0) {
    throw std::invalid_argument("rpl: " + spec.name + " is declared twice");
  }
  if (spec.min_args < 0 || (spec.max_args >= 0 && spec.max_args < spec.min_args)) {
    throw std::invalid_argument("rpl: module " + spec.name + ": bad arity");
  }
  for (const auto& v : spec.valves) AddValve(v);
  vocabulary_.modules.push_back(spec);
  modules_.push_back(std::move(module));
  module_activation_.push_back(0);
}

void Runtime::AddFunction(const FunctionSpec& spec, HostFunction function) {
  CheckNotInCallback("AddFunction");
  CheckName(spec.name, "function");
  if (!function) throw std::invalid_argument("rpl: AddFunction: null function");
  if (plan_) throw std::logic_error("rpl: add functions before a plan is loaded");
  if (vocabulary_.FindFluent(spec.name) >= 0 || vocabulary_.FindModule(spec.name) >= 0 ||
      vocabulary_.FindFunction(spec.name) >= 0 || vocabulary_.FindValve(spec.name) >= 0) {
    throw std::invalid_argument("rpl: " + spec.name + " is declared twice");
  }
  vocabulary_.functions.push_back(spec);
  functions_.push_back(std::move(function));
}

int Runtime::AddValve(const std::string& name) {
  CheckName(name, "valve");
  const int existing = vocabulary_.FindValve(name);
  if (existing >= 0) return existing;
  if (plan_) throw std::logic_error("rpl: add valves before a plan is loaded");
  if (vocabulary_.FindFluent(name) >= 0 || vocabulary_.FindModule(name) >= 0 ||
      vocabulary_.FindFunction(name) >= 0) {
    throw std::invalid_argument("rpl: " + name + " is declared twice");
  }
  vocabulary_.valves.push_back(name);
  valves_.push_back(std::make_unique<Valve>());
  valves_.back()->name = name;
  return static_cast<int>(valves_.size()) - 1;
}

// ---- plans ------------------------------------------------------------------------------------

std::vector<Diagnostic> Runtime::Load(const std::string& text, const std::string& file) {
  CheckNotInCallback("Load");
  if (state_ == PlanState::kRunning) {
    return {{Diagnostic::Severity::kError,
             file,
             {1, 1},
             "a plan is running: abort it (and let its cleanups end) before loading another"}};
  }
  CompileResult r = CompilePlan(text, file, vocabulary_);
  if (!r.ok()) return r.diagnostics;
  DestroyPlanFluents();
  plan_ = std::move(r.plan);
  state_ = PlanState::kLoaded;
  result_ = Value();
  failure_.reset();
  return r.diagnostics;
}

std::string Runtime::Start(double now_s,
                           const std::vector<std::pair<std::string, Value>>& overrides) {
  CheckNotInCallback("Start");
  if (!plan_) return "no plan is loaded";
  if (state_ == PlanState::kRunning) return "a plan is running";
  for (const auto& o : overrides) {
    if (plan_->FindGlobal(o.first) < 0) {
      return "the plan has no DEFVAR " + o.first + " to set";
    }
  }
  now_s_ = std::max(now_s_, now_s);
  DestroyPlanFluents();
  ready_ = {};
  timers_ = {};
  inbox_.clear();
  result_ = Value();
  failure_.reset();
  auto fail = [this](const EvalResult& r) {
    DestroyPlanFluents();
    return plan_->Where(*r.where).ToString() + ": " + r.error;
  };
  // DEFVARs, in order (an override replaces the initial value).
  globals_.assign(plan_->globals.size(), Value());
  for (size_t i = 0; i < plan_->globals.size(); ++i) {
    const GlobalVariable& g = plan_->globals[i];
    auto o =
        std::find_if(overrides.begin(), overrides.end(),
                     [&g](const std::pair<std::string, Value>& p) { return p.first == g.name; });
    if (o != overrides.end()) {
      globals_[i] = o->second;
      continue;
    }
    EvalResult r = Eval(g.init, nullptr, 0);
    if (!r.ok()) return fail(r);
    globals_[i] = std::move(r.value);
  }
  // The plan's fluents: nodes first (definitions may refer to later ones), then values.
  std::vector<FluentNode*> triggers(plan_->fluents.size(), nullptr);
  for (size_t i = 0; i < plan_->fluents.size(); ++i) {
    const PlanFluent& pf = plan_->fluents[i];
    const auto kind = pf.kind == PlanFluent::Kind::kDerived ? FluentNode::Kind::kDerived
                      : pf.kind == PlanFluent::Kind::kPulse ? FluentNode::Kind::kPulse
                                                            : FluentNode::Kind::kBase;
    nodes_.push_back(NewPlanNode(pf.name, kind));
    if (pf.kind == PlanFluent::Kind::kPulse && pf.expr) {
      triggers[i] = NewPlanNode("", FluentNode::Kind::kDerived);
    }
  }
  for (size_t i = 0; i < plan_->fluents.size(); ++i) {
    const PlanFluent& pf = plan_->fluents[i];
    FluentNode* node = nodes_[plan_->num_vocabulary_fluents + i];
    if (pf.kind == PlanFluent::Kind::kValue) {
      if (pf.expr) {
        EvalResult r = Eval(pf.expr, nullptr, 0);
        if (!r.ok()) return fail(r);
        node->value = std::move(r.value);
      }
      continue;
    }
    FluentNode* derived = pf.kind == PlanFluent::Kind::kDerived ? node : triggers[i];
    if (!derived) continue;  // a pulse without a condition: pulsed by (PULSE NAME)
    derived->expr = pf.expr;
    for (int dep : pf.expr->fluent_deps) derived->inputs.push_back(nodes_[dep]);
    if (pf.kind == PlanFluent::Kind::kPulse) derived->pulse_target = node;
  }
  for (size_t i = 0; i < plan_->fluents.size(); ++i) {
    const PlanFluent& pf = plan_->fluents[i];
    if (pf.kind == PlanFluent::Kind::kDerived) Use(nodes_[plan_->num_vocabulary_fluents + i]);
    if (triggers[i]) Use(triggers[i]);
  }
  Task* root = NewTask(nullptr, plan_->main, std::make_shared<Frame>(plan_->main_frame_size), 0);
  root->thread_root = true;
  root_ = IndexOf(root);
  state_ = PlanState::kRunning;
  Log(Event::Kind::kPlanStarted, plan_->file, "");
  Enqueue(root);
  return "";
}

StepResult Runtime::Step(double now_s) {
  CheckNotInCallback("Step");
  Counter in_step(&in_step_);
  now_s_ = std::max(now_s_, now_s);
  instructions_ = 0;
  FireTimers();
  do {
    ProcessReports();
    RunReady();
  } while ((!inbox_.empty() || !ready_.empty()) &&
           instructions_ < params_.max_instructions_per_step);
  return {instructions_, state_};
}

void Runtime::Abort(double now_s) {
  CheckNotInCallback("Abort");
  if (state_ != PlanState::kRunning || root_ == kNoTask) return;
  now_s_ = std::max(now_s_, now_s);
  Task* root = Get(root_);
  if (root->terminating) return;
  Counter in_step(&in_step_);
  Terminate(root, nullptr);
}

bool Runtime::Report(ActivationId id, bool success, const Value& value, const std::string& cause) {
  if (activations_.find(id) == activations_.end()) return false;
  inbox_.push_back({id, success, value, cause});
  return true;
}

// ---- introspection ----------------------------------------------------------------------------

std::vector<TaskInfo> Runtime::TaskTree() const {
  std::vector<TaskInfo> out;
  if (root_ == kNoTask) return out;
  std::vector<std::pair<TaskIndex, int>> stack{{root_, 0}};
  while (!stack.empty()) {
    const auto [index, depth] = stack.back();
    stack.pop_back();
    const Task* t = Get(index);
    TaskInfo info;
    info.id = static_cast<int>(index);
    info.parent = t->parent == kNoTask ? -1 : static_cast<int>(t->parent);
    info.depth = depth;
    info.label = Label(t);
    info.where = plan_->Where(*t->form);
    info.policy = t->policy;
    if (t->terminating) {
      info.state = TaskInfo::State::kEvaporating;
    } else {
      switch (t->state) {
        case TaskState::kWaitCondition:
          info.state = TaskInfo::State::kWaitBlocked;
          info.waiting_for = Plan::Text(*t->form->args[0]);
          break;
        case TaskState::kWaitTime:
          info.state = TaskInfo::State::kWaitBlocked;
          info.waiting_for = "time";
          break;
        case TaskState::kWaitValve:
          info.state = TaskInfo::State::kWaitBlocked;
          if (t->form->kind == FormKind::kWithValve) {
            info.waiting_for = "valve " + vocabulary_.valves[t->form->index];
          } else {  // EXECUTE / ACTIVATE: the valves of its module
            info.waiting_for = "valve";
            for (const auto& v : vocabulary_.modules[t->form->index].valves) {
              info.waiting_for += " " + v;
            }
          }
          break;
        case TaskState::kWaitModule:
          info.state = TaskInfo::State::kWaitBlocked;
          info.waiting_for = vocabulary_.modules[t->form->index].name;
          break;
        default:
          info.state = TaskInfo::State::kActive;
          break;
      }
    }
    out.push_back(std::move(info));
    std::vector<TaskIndex> children;
    for (TaskIndex c = t->first_child; c != kNoTask; c = Get(c)->next_sibling)
      children.push_back(c);
    for (auto it = children.rbegin(); it != children.rend(); ++it)
      stack.push_back({*it, depth + 1});
  }
  return out;
}

std::optional<double> Runtime::NextWakeUp() const {
  if (timers_.empty()) return std::nullopt;
  return timers_.top().due_s;
}

}  // namespace internal

// ---- Executive --------------------------------------------------------------------------------

Executive::Executive(const ExecutiveParameters& parameters)
    : runtime_(std::make_unique<internal::Runtime>(parameters)) {}
Executive::~Executive() = default;

void Executive::Shutdown() { runtime_.reset(); }

void Executive::DeclareFluent(const FluentSpec& spec) { runtime_->DeclareFluent(spec); }
void Executive::AddModule(std::shared_ptr<BehaviourModule> module) {
  runtime_->AddModule(std::move(module));
}
void Executive::AddFunction(const FunctionSpec& spec, HostFunction function) {
  runtime_->AddFunction(spec, std::move(function));
}
void Executive::AddValve(const std::string& name) { runtime_->AddValve(name); }
const Vocabulary& Executive::vocabulary() const { return runtime_->vocabulary(); }

std::vector<Diagnostic> Executive::Load(const std::string& text, const std::string& file) {
  return runtime_->Load(text, file);
}
std::string Executive::Start(double now_s,
                             const std::vector<std::pair<std::string, Value>>& globals) {
  return runtime_->Start(now_s, globals);
}
StepResult Executive::Step(double now_s) { return runtime_->Step(now_s); }
void Executive::Abort(double now_s) { runtime_->Abort(now_s); }
PlanState Executive::state() const { return runtime_->state(); }
const Value& Executive::result() const { return runtime_->result(); }
const Failure* Executive::failure() const { return runtime_->failure(); }

int Executive::FluentIndex(const std::string& name) const { return runtime_->FluentIndex(name); }
void Executive::SetFluent(const std::string& name, const Value& value, double now_s) {
  const int index = runtime_->vocabulary().FindFluent(name);
  if (index < 0) throw std::invalid_argument("rpl: SetFluent: unknown fluent " + name);
  runtime_->SetHostFluent(index, value, now_s);
}
void Executive::SetFluent(int index, const Value& value, double now_s) {
  runtime_->SetHostFluent(index, value, now_s);
}
Value Executive::GetFluent(const std::string& name) const {
  return runtime_->GetFluent(runtime_->FluentIndex(name));
}
std::vector<FluentState> Executive::Fluents() const { return runtime_->Fluents(); }

bool Executive::ReportSuccess(ActivationId id, const Value& value) {
  return runtime_->Report(id, true, value, "");
}
bool Executive::ReportFailure(ActivationId id, const std::string& cause) {
  return runtime_->Report(id, false, Value(), cause);
}

void Executive::SeizeValve(const std::string& valve, const std::string& who, double now_s) {
  runtime_->SeizeValve(valve, who, now_s);
}
void Executive::ReturnValve(const std::string& valve, double now_s) {
  runtime_->ReturnValve(valve, now_s);
}
std::string Executive::ValveHolder(const std::string& valve) const {
  return runtime_->ValveHolder(valve);
}

std::vector<TaskInfo> Executive::TaskTree() const { return runtime_->TaskTree(); }
std::size_t Executive::NumLiveTasks() const { return runtime_->NumLiveTasks(); }
const std::deque<Event>& Executive::events() const { return runtime_->events(); }
void Executive::SetEventCallback(std::function<void(const Event&)> callback) {
  runtime_->SetEventCallback(std::move(callback));
}
std::optional<double> Executive::NextWakeUp() const { return runtime_->NextWakeUp(); }

}  // namespace rpl
}  // namespace rpl_executive
