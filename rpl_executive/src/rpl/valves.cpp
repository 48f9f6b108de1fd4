// Valves and behaviour-module activations (Beetz et al. section 3.2). A valve is a semaphore:
// "any process ... that asks the robot to move around requests the valve WHEELS, moves the robot
// only after it has received WHEELS, and releases WHEELS after it is done". A request from a
// thread of strictly higher priority pre-empts the holder ("in this case, the valves are simply
// pre-empted"): the modules running under the holder's claim are deactivated at once (a
// NAVIGATION module deletes its target points, so NR-OF-NAV-GOALS* drops to zero and the
// interrupted routine notices it), and the holder gets the valve back when the higher-priority
// thread releases it. Requests of equal priority wait, first come first served.
#include <algorithm>
#include <stdexcept>

#include "runtime.h"

namespace rpl_executive {
namespace rpl {
namespace internal {

namespace {
bool Outranks(const Claim* a, const Claim* b) {
  if (a->external != b->external) return a->external;
  return a->priority > b->priority;
}
bool BetterCandidate(const Claim* a, const Claim* b) {
  if (a->external != b->external) return a->external;
  if (a->priority != b->priority) return a->priority > b->priority;
  return a->seq < b->seq;
}
void Erase(std::vector<ActivationId>* ids, ActivationId id) {
  ids->erase(std::remove(ids->begin(), ids->end(), id), ids->end());
}
}  // namespace

Claim* Runtime::NewClaim(int valve, Task* t, std::string label) {
  auto c = std::make_unique<Claim>();
  c->valve = valve;
  if (t) {
    c->task = IndexOf(t);
    c->task_generation = t->generation;
    c->priority = t->priority;
  }
  c->seq = seq_++;
  c->label = std::move(label);
  Claim* raw = c.get();
  valves_[valve]->claims.push_back(std::move(c));
  return raw;
}

bool Runtime::Request(Claim* c) {
  Valve* v = valves_[c->valve].get();
  Claim* holder = v->holder;
  if (!holder) {
    Grant(v, c, /*wake=*/false);
    return true;
  }
  if (holder == c) return true;
  if (!Outranks(c, holder)) return false;
  holder->holding = false;
  Grant(v, c, /*wake=*/false);
  Preempt(holder, c);
  return true;
}

void Runtime::Grant(Valve* v, Claim* c, bool wake) {
  v->holder = c;
  c->holding = true;
  Log(Event::Kind::kValveGranted, v->name, c->label);
  if (wake) {
    if (!c->granted_once) {
      if (c->task != kNoTask && Alive(c->task, c->task_generation)) {
        Task* t = Get(c->task);
        if (t->state == TaskState::kWaitValve) Enqueue(t);
      }
    } else {
      for (const auto& b : c->blocked) {
        if (!Alive(b.first, b.second)) continue;
        Task* t = Get(b.first);
        if (t->state == TaskState::kWaitValve) Enqueue(t);
      }
    }
    c->blocked.clear();
  }
  c->granted_once = true;
}

void Runtime::Preempt(Claim* victim, const Claim* by) {
  const Valve* v = valves_[victim->valve].get();
  const std::string why = "valve " + v->name + " pre-empted by " + by->label;
  Log(Event::Kind::kValvePreempted, v->name, victim->label + " lost it to " + by->label);
  // The victim may be released while its activations end (an ACTIVATE's own claim): copy first.
  const std::vector<ActivationId> ids = victim->activations;
  for (ActivationId id : ids) Deactivate(id, /*deliver=*/true, FailureClass::kInterrupted, why);
}

void Runtime::Release(Claim* c) {
  Valve* v = valves_[c->valve].get();
  // Modules still running under the claim stop with it.
  const std::vector<ActivationId> ids = c->activations;
  c->activations.clear();
  for (ActivationId id : ids) {
    Deactivate(id, /*deliver=*/true, FailureClass::kInterrupted,
               "stopped: valve " + v->name + " released by " + c->label);
  }
  const bool was_holder = v->holder == c;
  const std::string label = c->label;
  auto it = std::find_if(v->claims.begin(), v->claims.end(),
                         [c](const std::unique_ptr<Claim>& p) { return p.get() == c; });
  if (it != v->claims.end()) v->claims.erase(it);
  if (was_holder) {
    v->holder = nullptr;
    Log(Event::Kind::kValveReleased, v->name, label);
    GrantNext(v);
  }
}

void Runtime::GrantNext(Valve* v) {
  Claim* best = nullptr;
  for (const auto& c : v->claims) {
    if (!best || BetterCandidate(c.get(), best)) best = c.get();
  }
  if (best) Grant(v, best, /*wake=*/true);
}

Claim* Runtime::EnclosingClaim(Task* t, int valve) {
  if (t->extra) {
    for (Claim* c : t->extra->own_claims) {
      if (c->valve == valve) return c;
    }
  }
  for (TaskIndex i = t->parent; i != kNoTask; i = Get(i)->parent) {
    Task* a = Get(i);
    if (a->form->kind == FormKind::kWithValve && a->form->index == valve && a->claim) {
      return a->claim;
    }
  }
  return nullptr;
}

void Runtime::Deactivate(ActivationId id, bool deliver, FailureClass c, const std::string& why) {
  auto it = activations_.find(id);
  if (it == activations_.end()) return;
  Activation a = std::move(it->second);
  activations_.erase(it);
  if (module_activation_[a.module] == id) module_activation_[a.module] = 0;
  for (Claim* claim : a.under_claims) Erase(&claim->activations, id);
  for (Claim* claim : a.own_claims) Erase(&claim->activations, id);
  const std::string& name = vocabulary_.modules[a.module].name;
  Log(Event::Kind::kModuleDeactivated, name, why);
  ++in_callback_;
  modules_[a.module]->Deactivate(id, now_s_);
  --in_callback_;
  for (Claim* claim : a.own_claims) Release(claim);
  if (deliver && Alive(a.waiter, a.waiter_generation)) {
    Task* w = Get(a.waiter);
    if (w->state == TaskState::kWaitModule && w->activation == id && !w->terminating) {
      w->activation = 0;
      w->failure = MakeFailure(w, c, w->form, name + " " + why);
      Enqueue(w);
    }
  }
}

void Runtime::DeactivateOwnedBy(Task* root) {
  if (activations_.empty()) return;
  const TaskIndex index = IndexOf(root);
  std::vector<ActivationId> ids;
  for (const auto& entry : activations_) {
    if (entry.second.owner == index && entry.second.owner_generation == root->generation) {
      ids.push_back(entry.first);
    }
  }
  if (ids.empty()) return;
  const std::string why = "deactivated: its thread of control " + Path(root) + " ended";
  for (ActivationId id : ids) Deactivate(id, /*deliver=*/false, FailureClass::kInterrupted, why);
}

void Runtime::SeizeValve(const std::string& valve, const std::string& who, double now_s) {
  CheckNotInCallback("SeizeValve");
  const int index = vocabulary_.FindValve(valve);
  if (index < 0) throw std::invalid_argument("rpl: SeizeValve: unknown valve " + valve);
  now_s_ = std::max(now_s_, now_s);
  Claim* c = NewClaim(index, nullptr, who);
  c->external = true;
  Request(c);
}

void Runtime::ReturnValve(const std::string& valve, double now_s) {
  CheckNotInCallback("ReturnValve");
  const int index = vocabulary_.FindValve(valve);
  if (index < 0) throw std::invalid_argument("rpl: ReturnValve: unknown valve " + valve);
  now_s_ = std::max(now_s_, now_s);
  Valve* v = valves_[index].get();
  std::vector<Claim*> external;
  for (const auto& c : v->claims) {
    if (c->external) external.push_back(c.get());
  }
  for (Claim* c : external) Release(c);
}

std::string Runtime::ValveHolder(const std::string& valve) const {
  const int index = vocabulary_.FindValve(valve);
  if (index < 0) return "";
  const Claim* h = valves_[index]->holder;
  return h ? h->label : "";
}

}  // namespace internal
}  // namespace rpl
}  // namespace rpl_executive
