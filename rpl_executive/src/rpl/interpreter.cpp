// The interpreter: one explicit state machine per construct. Resume(t) runs one step of task t
// and returns the task to run next in the same thread of control (a child it spawned, itself, or
// its parent when it completed), or null when the thread blocks or ends.
#include <cmath>

#include "runtime.h"

namespace rpl_executive {
namespace rpl {
namespace internal {

std::string Runtime::Label(const Task* t) const {
  const Form* f = t->form;
  if (t->parent == kNoTask && f == plan_->main) return "PLAN";
  switch (f->kind) {
    case FormKind::kCall:
      return plan_->procedures[f->index].name;
    case FormKind::kProcess:
      return "PROCESS " + f->constant.text();
    case FormKind::kExecute:
      return "EXECUTE " + vocabulary_.modules[f->index].name;
    case FormKind::kActivate:
      return "ACTIVATE " + vocabulary_.modules[f->index].name;
    default:
      break;
  }
  if (!f->datum) return f->kind == FormKind::kSeq ? "SEQ" : "?";
  if (f->datum->IsList() && !f->datum->items.empty()) return PrintDatum(f->datum->items[0]);
  return PrintDatum(*f->datum);
}

std::string Runtime::Path(const Task* t) const {
  std::vector<std::string> parts;
  const Task* own = t;
  for (; t; t = t->parent == kNoTask ? nullptr : Get(t->parent)) {
    const FormKind k = t->form->kind;
    if (k == FormKind::kCall || k == FormKind::kExecute || k == FormKind::kActivate) {
      parts.push_back(Label(t));
    } else if (k == FormKind::kProcess) {
      parts.push_back(t->form->constant.text());
    } else if (t == own) {
      parts.push_back(Label(t));
    }
    if (t->parent != kNoTask && Get(t->parent)->form->kind == FormKind::kWithPolicy &&
        t->branch == 0) {
      parts.push_back("WITH-POLICY policy");
    }
  }
  std::string out;
  for (auto it = parts.rbegin(); it != parts.rend(); ++it) {
    if (!out.empty()) out += " > ";
    out += *it;
  }
  return out;
}

std::unique_ptr<Failure> Runtime::MakeFailure(const Task* t, FailureClass c, const Form* where,
                                              std::string message) const {
  auto f = std::make_unique<Failure>();
  f->failure_class = c;
  f->message = std::move(message);
  f->where = plan_->Where(*where);
  f->task_path = Path(t);
  return f;
}

Task* Runtime::Finish(Task* t, Value value) { return Complete(t, true, std::move(value), nullptr); }

Task* Runtime::FailWith(Task* t, std::unique_ptr<Failure> failure) {
  return Complete(t, false, Value(), std::move(failure));
}

Task* Runtime::Fail(Task* t, FailureClass c, const Form* where, std::string message) {
  return FailWith(t, MakeFailure(t, c, where, std::move(message)));
}

Task* Runtime::FailEval(Task* t, const EvalResult& r) {
  return Fail(t, FailureClass::kRuntimeError, r.where ? r.where : t->form, r.error);
}

std::string Runtime::TooManyTasks(size_t more) const {
  if (live_tasks_ + more <= static_cast<size_t>(params_.max_live_tasks)) return "";
  return "more than max_live_tasks (" + std::to_string(params_.max_live_tasks) +
         ") tasks would be live (a plan that forks without end?)";
}

Task* Runtime::Spawn(Task* parent, const Form* f, int branch) {
  const std::string too_many = TooManyTasks(1);
  if (!too_many.empty()) return Fail(parent, FailureClass::kRuntimeError, parent->form, too_many);
  Task* c = NewTask(parent, f, parent->frame, branch);
  parent->state = TaskState::kWaitChildren;
  return c;
}

bool Runtime::Operands(Task* t, size_t first, Task** next) {
  const auto& a = t->form->args;
  if (t->operand_pending) {
    t->operand_pending = false;
    t->args.push_back(std::move(t->value));
    ++t->pc;
  }
  while (first + static_cast<size_t>(t->pc) < a.size()) {
    const Form* f = a[first + t->pc];
    if (f->pure) {
      EvalResult r = Eval(f, t->frame.get(), 0);
      if (!r.ok()) {
        *next = FailEval(t, r);
        return false;
      }
      t->args.push_back(std::move(r.value));
      ++t->pc;
      continue;
    }
    t->operand_pending = true;
    *next = Spawn(t, f, t->pc);
    return false;
  }
  return true;
}

Task* Runtime::Resume(Task* t) {
  const Form* f = t->form;
  // A failure of a child (or one delivered to a waiting task) propagates with its cause, except
  // in the constructs that handle failures.
  if (t->failure && f->kind != FormKind::kTryInOrder && f->kind != FormKind::kWithFailureHandling &&
      f->kind != FormKind::kEvapProtect) {
    return FailWith(t, std::move(t->failure));
  }
  if (f->pure) {
    EvalResult r = Eval(f, t->frame.get(), 0);
    return r.ok() ? Finish(t, std::move(r.value)) : FailEval(t, r);
  }
  Task* next = nullptr;
  switch (f->kind) {
    case FormKind::kBuiltin:
    case FormKind::kHostCall: {
      if (!Operands(t, 0, &next)) return next;
      EvalResult r = f->kind == FormKind::kBuiltin ? ApplyBuiltin(f, t->args.data(), t->args.size())
                                                   : CallHost(f, t->args);
      return r.ok() ? Finish(t, std::move(r.value)) : FailEval(t, r);
    }
    case FormKind::kCall: {
      if (t->phase == 1) return Finish(t, std::move(t->value));
      if (!Operands(t, 0, &next)) return next;
      if (t->call_depth >= params_.max_call_depth) {
        return Fail(t, FailureClass::kRuntimeError, f,
                    "procedure calls nested deeper than max_call_depth (" +
                        std::to_string(params_.max_call_depth) + ")");
      }
      const std::string too_many = TooManyTasks(1);
      if (!too_many.empty()) return Fail(t, FailureClass::kRuntimeError, f, too_many);
      const Procedure& p = plan_->procedures[f->index];
      auto frame = std::make_shared<Frame>(p.frame_size);
      for (int i = 0; i < p.num_params; ++i) frame->slots[i] = std::move(t->args[i]);
      t->args.clear();
      t->phase = 1;
      t->state = TaskState::kWaitChildren;
      Task* body = NewTask(t, p.body, std::move(frame), 0);
      body->call_depth = t->call_depth + 1;
      return body;
    }
    case FormKind::kIf: {
      if (t->phase == 2) return Finish(t, std::move(t->value));
      if (t->phase == 0) {
        const Form* c = f->args[0];
        if (!c->pure) {
          t->phase = 1;
          return Spawn(t, c, 0);
        }
        EvalResult r = Eval(c, t->frame.get(), 0);
        if (!r.ok()) return FailEval(t, r);
        t->value = std::move(r.value);
      }
      const Form* branch = f->args[t->value.Truthy() ? 1 : 2];
      if (branch->pure) {
        EvalResult r = Eval(branch, t->frame.get(), 0);
        return r.ok() ? Finish(t, std::move(r.value)) : FailEval(t, r);
      }
      t->phase = 2;
      return Spawn(t, branch, 1);
    }
    case FormKind::kAnd:
    case FormKind::kOr: {
      const bool is_and = f->kind == FormKind::kAnd;
      if (t->phase == 1) {
        t->phase = 0;
        if (is_and != t->value.Truthy()) return Finish(t, is_and ? Value() : std::move(t->value));
        ++t->pc;
      } else if (t->pc == 0) {
        t->value = is_and ? Value::True() : Value();
      }
      while (t->pc < static_cast<int>(f->args.size())) {
        const Form* a = f->args[t->pc];
        if (!a->pure) {
          t->phase = 1;
          return Spawn(t, a, t->pc);
        }
        EvalResult r = Eval(a, t->frame.get(), 0);
        if (!r.ok()) return FailEval(t, r);
        if (is_and != r.value.Truthy()) return Finish(t, is_and ? Value() : std::move(r.value));
        t->value = std::move(r.value);
        ++t->pc;
      }
      return Finish(t, is_and ? std::move(t->value) : Value());
    }
    case FormKind::kSeq:
      while (t->pc < static_cast<int>(f->args.size())) {
        const Form* a = f->args[t->pc++];
        if (!a->pure) return Spawn(t, a, t->pc - 1);
        EvalResult r = Eval(a, t->frame.get(), 0);
        if (!r.ok()) return FailEval(t, r);
        t->value = std::move(r.value);
      }
      return Finish(t, std::move(t->value));
    case FormKind::kPar:
    case FormKind::kTryAll:
    case FormKind::kWithPolicy:
      return ResumeConcurrent(t);
    case FormKind::kTryInOrder: {
      if (t->phase == 1) {
        t->phase = 0;
        if (!t->failure) return Finish(t, std::move(t->value));
        t->Extra().failures.push_back(std::move(*t->failure));
        t->failure.reset();
        ++t->pc;
      }
      while (t->pc < static_cast<int>(f->args.size())) {
        const Form* a = f->args[t->pc];
        if (!a->pure) {
          t->phase = 1;
          return Spawn(t, a, t->pc);
        }
        EvalResult r = Eval(a, t->frame.get(), 0);
        if (r.ok()) return Finish(t, std::move(r.value));
        t->Extra().failures.push_back(
            *MakeFailure(t, FailureClass::kRuntimeError, r.where ? r.where : a, r.error));
        ++t->pc;
      }
      auto failure = MakeFailure(
          t, FailureClass::kAllFailed, f,
          "all " + std::to_string(f->args.size()) + " alternatives of TRY-IN-ORDER failed");
      failure->causes = std::move(t->Extra().failures);
      return FailWith(t, std::move(failure));
    }
    case FormKind::kLoop:
      return ResumeLoop(t);
    case FormKind::kWhenever:
      return ResumeWait(t, true);
    case FormKind::kWaitFor:
      return ResumeWait(t, false);
    case FormKind::kWaitTime: {
      if (t->phase == 1) return Finish(t, Value::True());
      if (!Operands(t, 0, &next)) return next;
      if (!t->args[0].IsNumber() || std::isnan(t->args[0].number())) {
        return Fail(t, FailureClass::kRuntimeError, f,
                    "WAIT-TIME takes a duration in seconds, not " + t->args[0].ToString());
      }
      const double seconds = t->args[0].number();
      if (seconds <= 0) return Finish(t, Value::True());
      t->phase = 1;
      t->state = TaskState::kWaitTime;
      timers_.push({now_s_ + seconds, seq_++, IndexOf(t), t->generation});
      return nullptr;
    }
    case FormKind::kWithValve: {
      if (t->phase == 2) return Finish(t, std::move(t->value));
      if (t->phase == 0) {
        t->claim = NewClaim(f->index, t, Path(t));
        if (!Request(t->claim)) {
          t->phase = 1;
          t->state = TaskState::kWaitValve;
          return nullptr;
        }
      }
      t->phase = 2;
      return Spawn(t, f->args[0], 0);
    }
    case FormKind::kEvapProtect: {
      if (t->phase == 0) {
        t->phase = 1;
        return Spawn(t, f->args[0], 0);
      }
      if (t->phase == 1) {  // the body ended (succeeded or failed): the cleanup runs in any case
        if (t->failure) t->Extra().saved = std::move(t->failure);
        t->args.assign(1, std::move(t->value));
        t->phase = 2;
        t->state = TaskState::kWaitChildren;
        Task* c = NewTask(t, f->args[1], t->frame, 1);
        c->cleanup = true;
        c->thread_root = true;
        return c;
      }
      if (t->failure) return FailWith(t, std::move(t->failure));  // the cleanup failed
      if (t->extra && t->extra->saved) return FailWith(t, std::move(t->extra->saved));
      return Finish(t, t->args.empty() ? Value() : std::move(t->args[0]));
    }
    case FormKind::kProcess:
      if (t->phase == 1) return Finish(t, std::move(t->value));
      t->thread_root = true;
      t->phase = 1;
      return Spawn(t, f->args[0], 0);
    case FormKind::kLet: {
      const int bindings = static_cast<int>(f->args.size()) - 1;
      if (t->phase == 2) return Finish(t, std::move(t->value));
      if (t->operand_pending) {
        t->operand_pending = false;
        t->args.push_back(std::move(t->value));
        ++t->pc;
      }
      while (t->pc < bindings) {
        const Form* init = f->args[t->pc]->args[0];
        if (!init->pure) {
          t->operand_pending = true;
          return Spawn(t, init, t->pc);
        }
        EvalResult r = Eval(init, t->frame.get(), 0);
        if (!r.ok()) return FailEval(t, r);
        t->args.push_back(std::move(r.value));
        ++t->pc;
      }
      for (int i = 0; i < bindings; ++i) {
        t->frame->slots[f->args[i]->index] = std::move(t->args[i]);
      }
      t->args.clear();
      t->phase = 2;
      return Spawn(t, f->args[bindings], bindings);
    }
    case FormKind::kSetfLocal:
    case FormKind::kSetfGlobal:
    case FormKind::kSetfFluent: {
      if (!Operands(t, 0, &next)) return next;
      const Value& v = t->args[0];
      if (f->kind == FormKind::kSetfLocal) {
        t->frame->slots[f->index] = v;
      } else if (f->kind == FormKind::kSetfGlobal) {
        globals_[f->index] = v;
      } else {
        SetBase(nodes_[f->index], v);
      }
      return Finish(t, v);
    }
    case FormKind::kExecute:
    case FormKind::kActivate:
      return ResumeModule(t);
    case FormKind::kDeactivate: {
      const ActivationId id = module_activation_[f->index];
      if (id) {
        Deactivate(id, /*deliver=*/true, FailureClass::kInterrupted,
                   "deactivated by (DEACTIVATE " + vocabulary_.modules[f->index].name + ") at " +
                       plan_->Where(*f).ToString() + " in " + Path(t));
      }
      return Finish(t, Value::Boolean(id != 0));
    }
    case FormKind::kVerifyCondition:
      if (!Operands(t, 0, &next)) return next;
      return Finish(t, std::move(t->args[0]));
    case FormKind::kFail: {
      if (!Operands(t, 0, &next)) return next;
      const Value& m = t->args[0];
      return Fail(t, FailureClass::kPlanFailure, f, m.IsString() ? m.text() : m.ToString());
    }
    case FormKind::kPulse:
      FirePulse(nodes_[f->index]);
      return Finish(t, Value::True());
    case FormKind::kWithFailureHandling: {
      if (t->phase == 2) {  // the handler ended
        if (t->failure) return FailWith(t, std::move(t->failure));
        return Finish(t, std::move(t->value));
      }
      if (t->phase == 0) {
        t->phase = 1;
        return Spawn(t, f->args[0], 0);
      }
      if (!t->failure) return Finish(t, std::move(t->value));
      for (size_t i = 1; i < f->args.size(); ++i) {
        const Form* clause = f->args[i];
        if (clause->index >= 0 && clause->index != static_cast<int>(t->failure->failure_class)) {
          continue;
        }
        Log(Event::Kind::kFailureHandled, Path(t), t->failure->ToString());
        const int slot = static_cast<int>(clause->constant.number());
        if (slot >= 0) t->frame->slots[slot] = Value::String(t->failure->message);
        t->failure.reset();
        t->phase = 2;
        return Spawn(t, clause->args[0], static_cast<int>(i));
      }
      return FailWith(t, std::move(t->failure));
    }
    default:
      break;
  }
  return Fail(t, FailureClass::kRuntimeError, f, "internal: cannot run " + Plan::Text(*f));
}

Task* Runtime::ResumeConcurrent(Task* t) {
  const Form* f = t->form;
  if (t->phase == 0) {
    const std::string too_many = TooManyTasks(f->args.size());
    if (!too_many.empty()) return Fail(t, FailureClass::kRuntimeError, f, too_many);
    if (f->kind == FormKind::kWithPolicy) {
      if (t->priority_depth >= 64) {
        return Fail(t, FailureClass::kRuntimeError, f, "WITH-POLICY nested deeper than 64");
      }
      Task* policy = NewTask(t, f->args[0], t->frame, 0);
      policy->thread_root = true;
      policy->policy = true;
      policy->priority |= std::uint64_t{1} << (63 - t->priority_depth);
      policy->priority_depth = static_cast<std::uint8_t>(t->priority_depth + 1);
      Task* primary = NewTask(t, f->args[1], t->frame, 1);
      primary->thread_root = true;
      primary->priority_depth = static_cast<std::uint8_t>(t->priority_depth + 1);
      Enqueue(policy);
      Enqueue(primary);
    } else {
      std::vector<Task*> children;
      for (size_t i = 0; i < f->args.size(); ++i) {
        Task* c = NewTask(t, f->args[i], t->frame, static_cast<int>(i));
        c->thread_root = true;
        children.push_back(c);
      }
      for (Task* c : children) Enqueue(c);
    }
    t->phase = 1;
    t->state = TaskState::kWaitChildren;
    return nullptr;
  }
  switch (f->kind) {
    case FormKind::kPar:  // all succeeded (phase 1), or one failed and the others evaporated
      if (t->phase == 2) return FailWith(t, std::move(t->Extra().saved));
      return Finish(t, Value::True());
    case FormKind::kTryAll:
      if (t->phase == 2) return Finish(t, std::move(t->value));  // the first success
      {
        auto failure =
            MakeFailure(t, FailureClass::kAllFailed, f,
                        "all " + std::to_string(f->args.size()) + " subtasks of TRY-ALL failed");
        failure->causes = std::move(t->Extra().failures);
        return FailWith(t, std::move(failure));
      }
    default:  // WITH-POLICY: the primary activity ended (or the policy failed)
      if (t->extra && t->extra->saved) return FailWith(t, std::move(t->extra->saved));
      return Finish(t, std::move(t->value));
  }
}

Task* Runtime::ResumeLoop(Task* t) {
  const Form* f = t->form;
  const int n = static_cast<int>(f->args.size());
  if (t->phase == 2 && t->value.Truthy()) return Finish(t, Value::True());  // UNTIL held
  if (t->phase != 0) ++t->pc;
  t->phase = 0;
  while (true) {
    if (t->pc >= n) {
      t->pc = 0;
      return t;  // one iteration per step: a LOOP that never waits cannot hang the caller
    }
    const Form* item = f->args[t->pc];
    if (item->kind == FormKind::kUntil) {
      const Form* c = item->args[0];
      if (!c->pure) {
        t->phase = 2;
        return Spawn(t, c, t->pc);
      }
      EvalResult r = Eval(c, t->frame.get(), 0);
      if (!r.ok()) return FailEval(t, r);
      if (r.value.Truthy()) return Finish(t, Value::True());
      ++t->pc;
      continue;
    }
    if (!item->pure) {
      t->phase = 1;
      return Spawn(t, item, t->pc);
    }
    EvalResult r = Eval(item, t->frame.get(), 0);
    if (!r.ok()) return FailEval(t, r);
    ++t->pc;
  }
}

Task* Runtime::ResumeWait(Task* t, bool whenever) {
  const Form* f = t->form;
  if (whenever && t->phase == 2) t->phase = 0;  // the body ended: wait for the condition again
  if (t->phase == 0) {
    if (!t->condition) {
      bool owned = false;
      t->condition = ConditionNode(f->args[0], t->frame, &owned);
      t->condition_owned = owned;
      Use(t->condition);
    }
    FluentNode* c = t->condition;
    if (!c->error.empty()) return Fail(t, FailureClass::kRuntimeError, f, c->error);
    if (!c->value.Truthy()) {  // wait-blocked until the condition becomes true
      c->waiters.PushBack(&t->link);
      t->phase = 1;
      t->state = TaskState::kWaitCondition;
      return nullptr;
    }
  }
  // The condition is (or became) true.
  if (!whenever) return Finish(t, Value::True());
  t->phase = 2;
  return Spawn(t, f->args[1], 1);
}

Task* Runtime::ResumeModule(Task* t) {
  const Form* f = t->form;
  Task* next = nullptr;
  if (t->phase == 2) return Finish(t, std::move(t->value));  // EXECUTE: the module succeeded
  if (t->phase == 0) {
    if (!Operands(t, 0, &next)) return next;
    t->phase = 1;
  }
  const int m = f->index;
  const ModuleSpec& spec = vocabulary_.modules[m];
  // The valves the module needs: the enclosing WITH-VALVE's, or requested for this activation.
  std::vector<Claim*> claims;
  std::vector<bool> own;
  for (const std::string& valve_name : spec.valves) {
    const int valve = vocabulary_.FindValve(valve_name);
    Claim* c = EnclosingClaim(t, valve);
    bool is_own = false;
    if (!c) {
      c = NewClaim(valve, t, Path(t));
      t->Extra().own_claims.push_back(c);
      is_own = true;
      if (!Request(c)) {
        t->state = TaskState::kWaitValve;  // woken when granted
        return nullptr;
      }
    } else {
      for (Claim* o : t->extra ? t->extra->own_claims : std::vector<Claim*>()) is_own |= o == c;
      if (!c->holding) {
        if (!is_own) c->blocked.push_back({IndexOf(t), t->generation});  // pre-empted: wait
        t->state = TaskState::kWaitValve;
        return nullptr;
      }
    }
    claims.push_back(c);
    own.push_back(is_own);
  }
  if (module_activation_[m]) {
    Deactivate(module_activation_[m], /*deliver=*/true, FailureClass::kInterrupted,
               "superseded: activated again by " + Path(t));
  }
  Activation a;
  a.id = next_activation_++;
  a.module = m;
  a.label = Path(t);
  for (size_t i = 0; i < claims.size(); ++i) {
    claims[i]->activations.push_back(a.id);
    if (own[i] && f->kind == FormKind::kActivate) {
      a.own_claims.push_back(claims[i]);  // the activation keeps the valve until it ends
      claims[i]->activation = a.id;
      claims[i]->task = kNoTask;
    } else {
      a.under_claims.push_back(claims[i]);
    }
  }
  if (f->kind == FormKind::kActivate && t->extra) t->extra->own_claims.clear();
  if (f->kind == FormKind::kExecute) {
    a.waiter = IndexOf(t);
    a.waiter_generation = t->generation;
    t->activation = a.id;
  } else {
    Task* root = ThreadRoot(t);
    a.owner = IndexOf(root);
    a.owner_generation = root->generation;
  }
  const ActivationId id = a.id;
  activations_[id] = std::move(a);
  module_activation_[m] = id;
  std::string args;
  for (const Value& v : t->args) args += " " + v.ToString();
  Log(Event::Kind::kModuleActivated, spec.name, "(" + spec.name + args + ") by " + Path(t));
  ++in_callback_;
  modules_[m]->Activate(id, t->args, now_s_);
  --in_callback_;
  if (f->kind == FormKind::kActivate) return Finish(t, Value::True());
  t->phase = 2;
  t->state = TaskState::kWaitModule;
  return nullptr;
}

}  // namespace internal
}  // namespace rpl
}  // namespace rpl_executive
