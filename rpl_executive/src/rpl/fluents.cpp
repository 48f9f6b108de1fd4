// The fluent network (Beetz et al. section 3.2: "To enable RPL control threads to react to
// asynchronous events ... we use fluents"). A change of a fluent recomputes, once each and in
// rank order (glitch-free), the conditions that read it, and moves the threads waiting on a
// condition that became true to the ready queue. Nothing is polled: a condition nobody waits on
// is not even subscribed to its inputs.
#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "runtime.h"

namespace rpl_executive {
namespace rpl {
namespace internal {

FluentNode* Runtime::NewPlanNode(std::string name, FluentNode::Kind kind) {
  plan_nodes_.push_back(std::make_unique<FluentNode>());
  FluentNode* n = plan_nodes_.back().get();
  n->name = std::move(name);
  n->kind = kind;
  n->stamp_s = now_s_;
  return n;
}

FluentNode* Runtime::ConditionNode(const Form* f, const FramePtr& frame, bool* owned) {
  *owned = false;
  if (f->kind == FormKind::kFluent) return nodes_[f->index];  // a named fluent itself
  FluentNode* node = nullptr;
  if (!f->reads_locals) {  // the same for every thread: one node per form
    if (cached_conditions_.size() <= static_cast<size_t>(f->id)) {
      cached_conditions_.resize(plan_->forms.size());
    }
    auto& slot = cached_conditions_[f->id];
    if (!slot) slot = std::make_unique<FluentNode>();
    node = slot.get();
  } else {  // reads the thread's variables: a node of its own
    node = new FluentNode();
    node->frame = frame;
    *owned = true;
  }
  if (node->inputs.empty() && node->expr == nullptr) {
    node->kind = FluentNode::Kind::kDerived;
    node->expr = f;
    for (int dep : f->fluent_deps) node->inputs.push_back(nodes_[dep]);
  }
  return node;
}

void Runtime::Use(FluentNode* node) {
  if (node->users++ > 0 || node->kind != FluentNode::Kind::kDerived) return;
  int rank = 0;
  for (FluentNode* input : node->inputs) {
    Use(input);
    input->dependents.push_back(node);
    rank = std::max(rank, input->rank);
  }
  node->rank = rank + 1;
  Recompute(node);
}

void Runtime::Unuse(FluentNode* node) {
  if (--node->users > 0 || node->kind != FluentNode::Kind::kDerived) return;
  for (FluentNode* input : node->inputs) {
    auto& d = input->dependents;
    auto it = std::find(d.begin(), d.end(), node);
    if (it != d.end()) {
      *it = d.back();
      d.pop_back();
    }
    Unuse(input);
  }
}

void Runtime::Recompute(FluentNode* node) {
  EvalResult r = Eval(node->expr, node->frame.get(), 0);
  if (r.ok()) {
    node->value = std::move(r.value);
    node->error.clear();
  } else {
    node->value = Value();
    node->error = plan_->Where(*r.where).ToString() + ": " + r.error;
  }
}

void Runtime::SetBase(FluentNode* node, const Value& value) {
  if (node->value == value) return;
  if (propagating_) {
    throw std::logic_error(
        "rpl: a fluent was set while conditions were being evaluated (a host "
        "function must not call SetFluent)");
  }
  node->value = value;
  node->stamp_s = now_s_;
  propagating_ = true;
  Propagate(node);
  propagating_ = false;
  if (!pending_pulses_.empty()) {
    std::vector<FluentNode*> pulses;
    pulses.swap(pending_pulses_);
    for (FluentNode* p : pulses) FirePulse(p);
  }
}

void Runtime::Propagate(FluentNode* source) {
  // Rank order: a node is recomputed after all its inputs (ranks rise along every edge), once.
  changed_.clear();
  changed_.push_back(source);
  size_t lowest = SIZE_MAX, highest = 0;
  auto push = [&](FluentNode* n) {
    if (n->queued) return;
    n->queued = true;
    const size_t r = static_cast<size_t>(n->rank);
    if (buckets_.size() <= r) buckets_.resize(r + 1);
    buckets_[r].push_back(n);
    lowest = std::min(lowest, r);
    highest = std::max(highest, r);
  };
  for (FluentNode* d : source->dependents) push(d);
  for (size_t r = lowest; r <= highest && r < buckets_.size(); ++r) {
    for (size_t i = 0; i < buckets_[r].size(); ++i) {  // the bucket does not grow: ranks rise
      FluentNode* n = buckets_[r][i];
      n->queued = false;
      const bool was_true = n->value.Truthy();
      const bool had_error = !n->error.empty();
      Value old = std::move(n->value);
      Recompute(n);
      if (n->value == old && had_error == !n->error.empty()) continue;
      changed_.push_back(n);
      if (n->pulse_target && !was_true && n->value.Truthy()) {
        pending_pulses_.push_back(n->pulse_target);
      }
      for (FluentNode* d : n->dependents) push(d);
    }
    buckets_[r].clear();
  }
  for (FluentNode* n : changed_) {
    if (!n->waiters.empty() && (n->value.Truthy() || !n->error.empty())) WakeWaiters(n);
  }
}

void Runtime::FirePulse(FluentNode* node) {
  Log(Event::Kind::kPulse, node->name, "");
  SetBase(node, Value::True());  // the threads waiting at this instant see it ...
  SetBase(node, Value());        // ... and only they: a pulse is over at once
}

void Runtime::WakeWaiters(FluentNode* node) {
  while (!node->waiters.empty()) {
    WaitLink* link = node->waiters.head.next;
    link->Unlink();
    Task* t = Get(link->task);
    if (!node->error.empty()) {
      t->failure = std::make_unique<Failure>();
      t->failure->failure_class = FailureClass::kRuntimeError;
      t->failure->message = node->error;
      t->failure->where = plan_->Where(*t->form);
      t->failure->task_path = Path(t);
    }
    Enqueue(t);
  }
}

void Runtime::DestroyPlanFluents() {
  for (auto& host : host_nodes_) {
    host->dependents.clear();
    host->users = 0;
  }
  cached_conditions_.clear();
  plan_nodes_.clear();
  nodes_.resize(host_nodes_.size());
  for (auto& b : buckets_) b.clear();
  changed_.clear();
  pending_pulses_.clear();
}

int Runtime::FluentIndex(const std::string& name) const {
  for (size_t i = 0; i < nodes_.size(); ++i) {
    if (nodes_[i]->name == name) return static_cast<int>(i);
  }
  return -1;
}

void Runtime::SetHostFluent(int index, const Value& value, double now_s) {
  if (index < 0 || index >= static_cast<int>(host_nodes_.size())) {
    throw std::invalid_argument("rpl: SetFluent: " + std::to_string(index) +
                                " is not a fluent of the vocabulary");
  }
  now_s_ = std::max(now_s_, now_s);
  SetBase(host_nodes_[index].get(), value);
}

Value Runtime::GetFluent(int index) const {
  if (index < 0 || index >= static_cast<int>(nodes_.size())) return Value();
  return nodes_[index]->value;
}

std::vector<FluentState> Runtime::Fluents() const {
  std::vector<FluentState> out;
  for (const FluentNode* n : nodes_) {
    out.push_back({n->name, n->value, n->stamp_s, n->kind == FluentNode::Kind::kPulse});
  }
  return out;
}

}  // namespace internal
}  // namespace rpl
}  // namespace rpl_executive
