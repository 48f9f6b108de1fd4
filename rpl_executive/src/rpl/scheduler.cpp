// The scheduler of the task tree: cooperative threads of control in the caller's OS thread,
// run in priority order (a policy before its primary activity, section 3.2), FIFO among equals;
// completion of tasks, and their termination ("evaporation") with the EVAP-PROTECT cleanups it
// triggers.
#include <algorithm>

#include "runtime.h"

namespace rpl_executive {
namespace rpl {
namespace internal {

Task* Runtime::NewTask(Task* parent, const Form* form, FramePtr frame, int branch) {
  TaskIndex i;
  if (!free_tasks_.empty()) {
    i = free_tasks_.back();
    free_tasks_.pop_back();
  } else {
    i = static_cast<TaskIndex>(tasks_.size());
    tasks_.emplace_back();
  }
  Task* t = &tasks_[i];
  t->state = TaskState::kReady;
  t->queued = false;
  t->terminating = false;
  t->thread_root = false;
  t->cleanup = false;
  t->operand_pending = false;
  t->policy = parent ? parent->policy : false;
  t->phase = 0;
  t->priority_depth = parent ? parent->priority_depth : 0;
  t->branch = static_cast<std::uint16_t>(branch);
  t->pc = 0;
  t->live_children = 0;
  t->call_depth = parent ? parent->call_depth : 0;
  t->priority = parent ? parent->priority : 0;
  t->form = form;
  t->frame = std::move(frame);
  t->parent = parent ? IndexOf(parent) : kNoTask;
  t->first_child = t->next_sibling = t->prev_sibling = kNoTask;
  t->value = Value();
  t->failure.reset();
  t->args.clear();
  t->link = WaitLink();
  t->link.task = i;
  t->condition = nullptr;
  t->condition_owned = false;
  t->activation = 0;
  t->claim = nullptr;
  t->extra.reset();
  if (parent) {
    // Children in creation order: append after the last one (found from the first's prev).
    if (parent->first_child == kNoTask) {
      parent->first_child = i;
      t->prev_sibling = i;  // the first child's prev is the last child
    } else {
      Task* first = Get(parent->first_child);
      const TaskIndex last = first->prev_sibling;
      Get(last)->next_sibling = i;
      t->prev_sibling = last;
      first->prev_sibling = i;
    }
    ++parent->live_children;
  }
  ++live_tasks_;
  return t;
}

void Runtime::FreeTask(Task* t) {
  const TaskIndex i = IndexOf(t);
  if (t->parent != kNoTask) {
    Task* p = Get(t->parent);
    Task* first = Get(p->first_child);
    if (p->first_child == i) {
      p->first_child = t->next_sibling;
      if (t->next_sibling != kNoTask) Get(t->next_sibling)->prev_sibling = t->prev_sibling;
    } else {
      Get(t->prev_sibling)->next_sibling = t->next_sibling;
      if (t->next_sibling != kNoTask) {
        Get(t->next_sibling)->prev_sibling = t->prev_sibling;
      } else {
        first->prev_sibling = t->prev_sibling;  // t was the last child
      }
    }
    --p->live_children;
  }
  ++t->generation;
  t->state = TaskState::kFree;
  t->queued = false;
  t->frame.reset();
  t->value = Value();
  t->failure.reset();
  t->args.clear();
  t->extra.reset();
  free_tasks_.push_back(i);
  --live_tasks_;
}

void Runtime::Enqueue(Task* t) {
  if (t->queued || t->terminating || t->state == TaskState::kFree) return;
  t->state = TaskState::kReady;
  t->queued = true;
  ready_.push({t->priority, seq_++, IndexOf(t), t->generation});
}

Task* Runtime::ThreadRoot(Task* t) {
  while (!t->thread_root && t->parent != kNoTask) t = Get(t->parent);
  return t;
}

void Runtime::RunReady() {
  const int budget = params_.max_instructions_per_step;
  while (!ready_.empty() && instructions_ < budget) {
    const ReadyEntry e = ready_.top();
    ready_.pop();
    if (!Alive(e.task, e.generation)) continue;
    Task* t = Get(e.task);
    if (!t->queued) continue;
    t->queued = false;
    if (t->terminating || t->state != TaskState::kReady) continue;
    Task* current = t;
    while (current) {
      current->state = TaskState::kRunning;
      ++instructions_;
      Task* next = Resume(current);
      if (!next || next->queued) break;
      // A thread of higher priority became ready (a policy woken by what this one did): it runs
      // first, at this instruction boundary.
      if (instructions_ >= budget || (!ready_.empty() && ready_.top().priority > next->priority)) {
        Enqueue(next);
        break;
      }
      current = next;
    }
  }
}

void Runtime::FireTimers() {
  while (!timers_.empty() && timers_.top().due_s <= now_s_) {
    const TimerEntry e = timers_.top();
    timers_.pop();
    if (!Alive(e.task, e.generation)) continue;
    Task* t = Get(e.task);
    if (t->state == TaskState::kWaitTime) Enqueue(t);
  }
}

void Runtime::ProcessReports() {
  std::vector<ModuleReport> reports;
  reports.swap(inbox_);
  for (ModuleReport& r : reports) {
    auto it = activations_.find(r.id);
    if (it == activations_.end()) continue;  // deactivated meanwhile: ignored
    Activation a = std::move(it->second);
    activations_.erase(it);
    if (module_activation_[a.module] == r.id) module_activation_[a.module] = 0;
    for (Claim* c : a.under_claims) {
      c->activations.erase(std::remove(c->activations.begin(), c->activations.end(), r.id),
                           c->activations.end());
    }
    for (Claim* c : a.own_claims) {
      c->activations.erase(std::remove(c->activations.begin(), c->activations.end(), r.id),
                           c->activations.end());
    }
    const std::string& name = vocabulary_.modules[a.module].name;
    Log(r.success ? Event::Kind::kModuleSucceeded : Event::Kind::kModuleFailed, name,
        r.success ? r.value.ToString() : r.cause);
    for (Claim* c : a.own_claims) Release(c);
    if (Alive(a.waiter, a.waiter_generation)) {
      Task* w = Get(a.waiter);
      if (w->state == TaskState::kWaitModule && w->activation == r.id && !w->terminating) {
        w->activation = 0;
        if (r.success) {
          w->value = std::move(r.value);
        } else {
          w->failure =
              MakeFailure(w, FailureClass::kModuleFailure, w->form, name + " failed: " + r.cause);
        }
        Enqueue(w);
      }
      continue;
    }
    // Activated without waiting (ACTIVATE): a failure fails the thread that activated it.
    if (!r.success && Alive(a.owner, a.owner_generation)) {
      Task* owner = Get(a.owner);
      if (!owner->terminating) {
        Log(Event::Kind::kThreadFailed, Path(owner), name + " failed: " + r.cause);
        auto failure = std::make_unique<Failure>();
        failure->failure_class = FailureClass::kModuleFailure;
        failure->message = name + " (activated at " +
                           (a.label.empty() ? std::string("?") : a.label) + ") failed: " + r.cause;
        failure->where = plan_->Where(*owner->form);
        failure->task_path = Path(owner);
        Terminate(owner, std::move(failure));
      }
    }
  }
}

Task* Runtime::Complete(Task* t, bool ok, Value value, std::unique_ptr<Failure> failure) {
  ReleaseResources(t);
  if (t->thread_root && Logging()) {
    Log(Event::Kind::kThreadEnded, Path(t),
        ok ? "done" : "failed: " + (failure ? failure->message : std::string("?")));
  }
  if (t->parent == kNoTask) {
    FreeTask(t);
    root_ = kNoTask;
    FinishPlan(ok, std::move(value), std::move(failure), false);
    return nullptr;
  }
  Task* parent = Get(t->parent);
  const int branch = t->branch;
  const bool was_cleanup = t->cleanup;
  FreeTask(t);
  if (parent->terminating) {
    if (!ok && was_cleanup && failure) {
      Log(Event::Kind::kCleanup, Path(parent), "cleanup failed: " + failure->ToString());
    }
    if (parent->live_children == 0) EndTerminated(parent);
    return nullptr;
  }
  parent->value = std::move(value);
  if (!ok) parent->failure = std::move(failure);
  return ChildDone(parent, branch, ok);
}

Task* Runtime::ChildDone(Task* parent, int branch, bool ok) {
  const FormKind kind = parent->form->kind;
  auto evaporate_others = [&]() -> Task* {
    parent->state = TaskState::kWaitEvaporation;
    std::vector<Task*> others;
    for (TaskIndex c = parent->first_child; c != kNoTask; c = Get(c)->next_sibling) {
      others.push_back(Get(c));
    }
    for (Task* c : others) {
      if (Alive(IndexOf(c), c->generation)) Terminate(c, nullptr);
    }
    if (parent->live_children == 0 && !parent->queued) return parent;
    return nullptr;
  };
  switch (kind) {
    case FormKind::kPar:
      if (!ok) {
        parent->phase = 2;
        parent->Extra().saved = std::move(parent->failure);
        return evaporate_others();
      }
      return parent->live_children == 0 ? parent : nullptr;
    case FormKind::kTryAll:
      if (ok) {
        parent->phase = 2;
        return evaporate_others();
      }
      parent->Extra().failures.push_back(std::move(*parent->failure));
      parent->failure.reset();
      if (parent->live_children == 0) {
        parent->phase = 3;
        return parent;
      }
      return nullptr;
    case FormKind::kWithPolicy:
      if (branch == 0 && ok) return nullptr;  // the policy ended; the primary activity goes on
      parent->phase = 2;
      if (!ok) parent->Extra().saved = std::move(parent->failure);
      return evaporate_others();
    default:
      return parent;  // sequential constructs resume at once
  }
}

void Runtime::StopWaiting(Task* t) {
  t->link.Unlink();
  if (t->condition) {
    Unuse(t->condition);
    if (t->condition_owned) delete t->condition;
    t->condition = nullptr;
    t->condition_owned = false;
  }
  if (t->activation) {
    const ActivationId id = t->activation;
    t->activation = 0;
    Deactivate(id, /*deliver=*/false, FailureClass::kInterrupted,
               "deactivated: " + Path(t) + " evaporated");
  }
  if (t->extra && !t->extra->own_claims.empty()) {
    std::vector<Claim*> claims;
    claims.swap(t->extra->own_claims);
    for (Claim* c : claims) Release(c);
  }
  if (t->thread_root) DeactivateOwnedBy(t);
}

void Runtime::ReleaseResources(Task* t) {
  StopWaiting(t);
  if (t->claim) {
    Claim* c = t->claim;
    t->claim = nullptr;
    Release(c);
  }
}

void Runtime::Terminate(Task* root, std::unique_ptr<Failure> failure) {
  if (root->terminating) return;
  // 1. Mark the subtree (cleanups of EVAP-PROTECTs are protected and go on) and stop every wait:
  //    activations end now, so the robot stops doing what the evaporated threads asked for.
  std::vector<std::pair<TaskIndex, std::uint32_t>> order;
  std::vector<Task*> stack{root};
  while (!stack.empty()) {
    Task* n = stack.back();
    stack.pop_back();
    n->terminating = true;
    n->queued = false;
    order.push_back({IndexOf(n), n->generation});
    StopWaiting(n);
    for (TaskIndex c = n->first_child; c != kNoTask; c = Get(c)->next_sibling) {
      Task* child = Get(c);
      if (!child->cleanup && !child->terminating) stack.push_back(child);
    }
  }
  if (failure) root->Extra().term_failure = std::move(failure);
  // 2. Tasks without live children are gone now, children before parents; an EVAP-PROTECT
  //    whose body is gone runs its cleanup first (EndTerminated).
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    if (!Alive(it->first, it->second)) continue;
    Task* n = Get(it->first);
    if (n->terminating && n->live_children == 0) EndTerminated(n);
  }
}

void Runtime::EndTerminated(Task* t) {
  while (true) {
    // "EVAP-PROTECT A B secures the execution of the code piece B in the case that A is
    // deactivated in the midst of its execution" (section 3.2): B starts once A and everything
    // below it (inner cleanups included) is gone, so cleanups run innermost first.
    if (t->form->kind == FormKind::kEvapProtect && t->phase == 1) {
      t->phase = 2;
      Log(Event::Kind::kCleanup, Path(t),
          "body deactivated: cleanup " + Plan::Text(*t->form->args[1]));
      Task* c = NewTask(t, t->form->args[1], t->frame, 1);
      c->cleanup = true;
      c->thread_root = true;
      Enqueue(c);
      return;
    }
    if (t->extra && t->extra->term_failure) {
      std::unique_ptr<Failure> f = std::move(t->extra->term_failure);
      t->terminating = false;
      if (Task* next = Complete(t, false, Value(), std::move(f))) Enqueue(next);
      return;
    }
    ReleaseResources(t);
    if (t->thread_root && Logging()) Log(Event::Kind::kThreadEnded, Path(t), "evaporated");
    const TaskIndex parent_index = t->parent;
    FreeTask(t);
    if (parent_index == kNoTask) {
      root_ = kNoTask;
      FinishPlan(false, Value(), nullptr, /*aborted=*/true);
      return;
    }
    Task* parent = Get(parent_index);
    if (parent->live_children > 0) return;
    if (parent->terminating) {
      t = parent;
      continue;
    }
    if (parent->state == TaskState::kWaitEvaporation) Enqueue(parent);
    return;
  }
}

void Runtime::FinishPlan(bool ok, Value value, std::unique_ptr<Failure> failure, bool aborted) {
  if (aborted) {
    state_ = PlanState::kAborted;
    Log(Event::Kind::kPlanFinished, plan_->file, "aborted");
    return;
  }
  state_ = ok ? PlanState::kSucceeded : PlanState::kFailed;
  result_ = ok ? std::move(value) : Value();
  failure_ = std::move(failure);
  Log(Event::Kind::kPlanFinished, plan_->file,
      ok ? "succeeded: " + result_.ToString() : "failed: " + failure_->ToString());
}

}  // namespace internal
}  // namespace rpl
}  // namespace rpl_executive
