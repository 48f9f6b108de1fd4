// Internals of the RPL runtime (not installed): tasks, the fluent network, valves, activations.
//
// Design. A plan runs as a tree of tasks (RPL's task tree). Each task interprets one form with an
// explicit state machine (phase/pc) and is resumed by the scheduler, so every thread of control
// is a cooperative thread inside the caller's OS thread: no stacks, no locks, deterministic
// order (priority, then FIFO). A task that waits is linked into the waiter list of one fluent
// node (or a valve claim, a module activation, a timer) and is not looked at again until that
// changes: a wait costs memory only.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <queue>
#include <string>
#include <unordered_map>
#include <vector>

#include "rpl_executive/rpl/executive.h"

namespace rpl_executive {
namespace rpl {
namespace internal {

using TaskIndex = std::uint32_t;
constexpr TaskIndex kNoTask = 0xFFFFFFFFu;

/// The variables of one procedure invocation (or of the top level).
struct Frame {
  explicit Frame(int size) : slots(static_cast<size_t>(size)) {}
  std::vector<Value> slots;
};
using FramePtr = std::shared_ptr<Frame>;

/// A node of an intrusive doubly linked list of waiting tasks.
struct WaitLink {
  WaitLink* prev = nullptr;
  WaitLink* next = nullptr;
  TaskIndex task = kNoTask;
  bool linked() const { return prev != nullptr; }
  void Unlink() {
    if (!prev) return;
    prev->next = next;
    next->prev = prev;
    prev = next = nullptr;
  }
};
struct WaitList {
  WaitLink head;
  WaitList() { head.prev = head.next = &head; }
  WaitList(const WaitList&) = delete;
  bool empty() const { return head.next == &head; }
  void PushBack(WaitLink* link) {
    link->prev = head.prev;
    link->next = &head;
    head.prev->next = link;
    head.prev = link;
  }
};

/// A fluent: a base value set from outside (or by SETF / PULSE), or a condition computed from
/// other fluents. Derived nodes are subscribed to their inputs only while someone needs them
/// (a waiting thread, a dependent, or a named definition of the plan).
struct FluentNode {
  enum class Kind { kBase, kDerived, kPulse };
  std::string name;  // "" for the anonymous condition of a WAIT-FOR / WHENEVER
  Kind kind = Kind::kBase;
  Value value;
  double stamp_s = 0.0;
  int rank = 0;  // 0 for base and pulse nodes; 1 + the highest input rank for derived ones
  std::vector<FluentNode*> dependents;  // subscribed derived nodes
  // Derived nodes:
  const Form* expr = nullptr;
  FramePtr frame;  // the variables the condition reads (per-thread conditions only)
  std::vector<FluentNode*> inputs;
  int users = 0;  // waiting tasks + subscribed dependents + 1 if named (permanent)
  FluentNode* pulse_target = nullptr;  // DEF-PULSE: pulse that node when this becomes true
  std::string error;                   // why the last evaluation failed ("" = fine)
  bool queued = false;                 // in the propagation worklist
  WaitList waiters;
};

/// One request for a valve (section 3.2: "semaphores or valves, which can be requested and
/// released").
struct Claim {
  int valve = 0;
  TaskIndex task = kNoTask;  // the WITH-VALVE, EXECUTE or ACTIVATE task that asked
  std::uint32_t task_generation = 0;
  ActivationId activation = 0;  // an ACTIVATE's claim belongs to its activation once started
  bool external = false;        // SeizeValve: above every thread
  std::uint64_t priority = 0;
  std::uint64_t seq = 0;
  bool holding = false;
  bool granted_once = false;
  std::string label;                                         // who, for events and ValveHolder
  std::vector<std::pair<TaskIndex, std::uint32_t>> blocked;  // tasks waiting to regain it
  std::vector<ActivationId> activations;                     // modules running under it
};

struct Valve {
  std::string name;
  std::vector<std::unique_ptr<Claim>> claims;
  Claim* holder = nullptr;
};

struct Activation {
  ActivationId id = 0;
  int module = 0;
  TaskIndex waiter = kNoTask;  // the EXECUTE waiting for the outcome
  std::uint32_t waiter_generation = 0;
  TaskIndex owner = kNoTask;  // the thread of control it lasts for
  std::uint32_t owner_generation = 0;
  std::vector<Claim*> own_claims;    // claims taken for it (released when it ends)
  std::vector<Claim*> under_claims;  // WITH-VALVE claims it runs under
  std::string label;                 // path of the activating task
};

enum class TaskState : std::uint8_t {
  kFree,
  kReady,
  kRunning,
  kWaitChildren,
  kWaitCondition,
  kWaitTime,
  kWaitValve,
  kWaitModule,
  kWaitEvaporation,
};

/// Rare per-task data, allocated on demand.
struct TaskExtra {
  std::vector<Failure> failures;          // TRY-ALL / TRY-IN-ORDER
  std::vector<Claim*> own_claims;         // EXECUTE / ACTIVATE: claims of valves it had to request
  std::unique_ptr<Failure> saved;         // EVAP-PROTECT: the body's failure while cleanup runs
  std::unique_ptr<Failure> term_failure;  // the failure a terminated task completes with
};

struct Task {
  std::uint32_t generation = 0;
  TaskState state = TaskState::kFree;
  bool queued = false;
  bool terminating = false;
  bool thread_root = false;
  bool cleanup = false;          // an EVAP-PROTECT cleanup (not evaporated by its ancestors)
  bool operand_pending = false;  // a child evaluates operand `pc`
  bool policy = false;           // in a policy of a WITH-POLICY
  std::uint8_t phase = 0;
  std::uint8_t priority_depth = 0;
  std::uint16_t branch = 0;
  std::int32_t pc = 0;
  std::int32_t live_children = 0;
  std::int32_t call_depth = 0;
  std::uint64_t priority = 0;  // WITH-POLICY nesting as a binary fraction: higher runs first
  const Form* form = nullptr;
  FramePtr frame;
  TaskIndex parent = kNoTask;
  TaskIndex first_child = kNoTask;
  TaskIndex next_sibling = kNoTask;
  TaskIndex prev_sibling = kNoTask;
  Value value;                       // the last child's value, or the task's own result
  std::unique_ptr<Failure> failure;  // a child's failure, or one delivered to the task
  std::vector<Value> args;           // evaluated operands
  WaitLink link;                     // in a fluent node's waiter list
  FluentNode* condition = nullptr;   // the condition node the task uses (WAIT-FOR, WHENEVER)
  bool condition_owned = false;      // a per-thread node, freed with the task
  ActivationId activation = 0;       // EXECUTE: the activation it waits for
  Claim* claim = nullptr;            // WITH-VALVE: its claim
  std::unique_ptr<TaskExtra> extra;

  TaskExtra& Extra() {
    if (!extra) extra = std::make_unique<TaskExtra>();
    return *extra;
  }
};

struct ReadyEntry {
  std::uint64_t priority;
  std::uint64_t seq;
  TaskIndex task;
  std::uint32_t generation;
  bool operator<(const ReadyEntry& o) const {  // std::priority_queue pops the largest
    if (priority != o.priority) return priority < o.priority;
    return seq > o.seq;
  }
};

struct TimerEntry {
  double due_s;
  std::uint64_t seq;
  TaskIndex task;
  std::uint32_t generation;
  bool operator<(const TimerEntry& o) const {
    if (due_s != o.due_s) return due_s > o.due_s;
    return seq > o.seq;
  }
};

struct ModuleReport {
  ActivationId id;
  bool success;
  Value value;
  std::string cause;
};

struct EvalResult {
  Value value;
  std::string error;  // "" = ok
  const Form* where = nullptr;
  bool ok() const { return error.empty(); }
};

class Runtime {
 public:
  explicit Runtime(const ExecutiveParameters& parameters);
  ~Runtime();

  // Vocabulary.
  void DeclareFluent(const FluentSpec& spec);
  void AddModule(std::shared_ptr<BehaviourModule> module);
  void AddFunction(const FunctionSpec& spec, HostFunction function);
  int AddValve(const std::string& name);
  const Vocabulary& vocabulary() const { return vocabulary_; }

  // Plans.
  std::vector<Diagnostic> Load(const std::string& text, const std::string& file);
  std::string Start(double now_s, const std::vector<std::pair<std::string, Value>>& globals);
  StepResult Step(double now_s);
  void Abort(double now_s);
  PlanState state() const { return state_; }
  const Value& result() const { return result_; }
  const Failure* failure() const { return failure_.get(); }

  // Fluents.
  int FluentIndex(const std::string& name) const;
  void SetHostFluent(int index, const Value& value, double now_s);
  Value GetFluent(int index) const;
  std::vector<FluentState> Fluents() const;

  // Reports and outside valves.
  bool Report(ActivationId id, bool success, const Value& value, const std::string& cause);
  void SeizeValve(const std::string& valve, const std::string& who, double now_s);
  void ReturnValve(const std::string& valve, double now_s);
  std::string ValveHolder(const std::string& valve) const;

  // Introspection.
  std::vector<TaskInfo> TaskTree() const;
  std::size_t NumLiveTasks() const { return live_tasks_; }
  const std::deque<Event>& events() const { return events_; }
  void SetEventCallback(std::function<void(const Event&)> callback) {
    event_callback_ = std::move(callback);
  }
  std::optional<double> NextWakeUp() const;

 private:
  // ---- evaluator.cpp ----
  EvalResult Eval(const Form* f, Frame* frame, int depth);
  EvalResult ApplyBuiltin(const Form* f, Value* args, size_t n);
  EvalResult CallHost(const Form* f, const std::vector<Value>& args);

  // ---- fluents.cpp ----
  FluentNode* NewPlanNode(std::string name, FluentNode::Kind kind);
  FluentNode* ConditionNode(const Form* f, const FramePtr& frame, bool* owned);
  void Use(FluentNode* node);
  void Unuse(FluentNode* node);
  void Recompute(FluentNode* node);
  void SetBase(FluentNode* node, const Value& value);
  void Propagate(FluentNode* source);
  void FirePulse(FluentNode* node);
  void WakeWaiters(FluentNode* node);
  void DestroyPlanFluents();

  // ---- scheduler.cpp ----
  Task* Get(TaskIndex i) { return &tasks_[i]; }
  const Task* Get(TaskIndex i) const { return &tasks_[i]; }
  TaskIndex IndexOf(const Task* t) const { return t->link.task; }
  bool Alive(TaskIndex i, std::uint32_t generation) const {
    return i < tasks_.size() && tasks_[i].generation == generation &&
           tasks_[i].state != TaskState::kFree;
  }
  Task* NewTask(Task* parent, const Form* form, FramePtr frame, int branch);
  void FreeTask(Task* t);
  void Enqueue(Task* t);
  void RunReady();
  void ProcessReports();
  void FireTimers();
  Task* Complete(Task* t, bool ok, Value value, std::unique_ptr<Failure> failure);
  Task* ChildDone(Task* parent, int branch, bool ok);
  void Terminate(Task* root, std::unique_ptr<Failure> failure);
  void StopWaiting(Task* t);
  void ReleaseResources(Task* t);
  void EndTerminated(Task* t);
  void FinishPlan(bool ok, Value value, std::unique_ptr<Failure> failure, bool aborted);
  Task* ThreadRoot(Task* t);

  // ---- interpreter.cpp ----
  Task* Resume(Task* t);
  Task* Finish(Task* t, Value value);
  Task* Fail(Task* t, FailureClass c, const Form* where, std::string message);
  Task* FailWith(Task* t, std::unique_ptr<Failure> failure);
  Task* FailEval(Task* t, const EvalResult& r);
  Task* Spawn(Task* parent, const Form* f, int branch);
  std::string TooManyTasks(size_t more) const;  // "" when `more` new tasks fit
  // Evaluates operands form->args[first..] into t->args; false with *next set when the task must
  // wait for a child or failed.
  bool Operands(Task* t, size_t first, Task** next);
  Task* ResumeWait(Task* t, bool whenever);
  Task* ResumeModule(Task* t);
  Task* ResumeLoop(Task* t);
  Task* ResumeConcurrent(Task* t);
  std::string Label(const Task* t) const;
  std::string Path(const Task* t) const;
  std::unique_ptr<Failure> MakeFailure(const Task* t, FailureClass c, const Form* where,
                                       std::string message) const;

  // ---- valves.cpp ----
  Claim* NewClaim(int valve, Task* t, std::string label);
  bool Request(Claim* c);  // true when granted now
  void Release(Claim* c);
  void GrantNext(Valve* v);
  void Grant(Valve* v, Claim* c, bool wake);
  void Preempt(Claim* victim, const Claim* by);
  Claim* EnclosingClaim(Task* t, int valve);
  void Deactivate(ActivationId id, bool deliver, FailureClass c, const std::string& why);
  void DeactivateOwnedBy(Task* root);

  void Log(Event::Kind kind, std::string subject, std::string detail);
  bool Logging() const { return params_.event_log_capacity > 0 || event_callback_ != nullptr; }
  void CheckNotInCallback(const char* what) const;

  ExecutiveParameters params_;
  Vocabulary vocabulary_;
  std::vector<std::shared_ptr<BehaviourModule>> modules_;
  std::vector<HostFunction> functions_;
  std::vector<std::unique_ptr<Valve>> valves_;
  std::vector<std::unique_ptr<FluentNode>> host_nodes_;
  std::vector<std::unique_ptr<FluentNode>> plan_nodes_;  // named plan fluents and pulse triggers
  std::vector<FluentNode*> nodes_;                       // by fluent index
  std::vector<std::unique_ptr<FluentNode>> cached_conditions_;  // by form id
  std::vector<std::vector<FluentNode*>> buckets_;               // propagation worklist, by rank
  std::vector<FluentNode*> changed_;
  std::vector<FluentNode*> pending_pulses_;
  bool propagating_ = false;

  std::shared_ptr<const Plan> plan_;
  std::vector<Value> globals_;
  PlanState state_ = PlanState::kNoPlan;
  Value result_;
  std::unique_ptr<Failure> failure_;

  std::deque<Task> tasks_;
  std::vector<TaskIndex> free_tasks_;
  std::size_t live_tasks_ = 0;
  TaskIndex root_ = kNoTask;
  std::priority_queue<ReadyEntry> ready_;
  std::priority_queue<TimerEntry> timers_;
  std::uint64_t seq_ = 0;
  std::vector<ModuleReport> inbox_;
  std::map<ActivationId, Activation> activations_;
  std::vector<ActivationId> module_activation_;  // per module: its active activation or 0
  ActivationId next_activation_ = 1;

  double now_s_ = 0.0;
  int instructions_ = 0;
  int in_step_ = 0;
  int in_callback_ = 0;
  std::deque<Event> events_;
  std::function<void(const Event&)> event_callback_;
};

}  // namespace internal
}  // namespace rpl
}  // namespace rpl_executive
