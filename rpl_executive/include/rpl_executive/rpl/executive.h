// The RPL runtime system (Beetz et al. section 3, Fig. 11): interprets a structured reactive
// plan as a tree of tasks, the threads of control of which are cooperative and run in the
// caller's thread inside Step(now). Fluents wake the threads waiting on them (no polling), policies
// run concurrently with and take priority over their primary activities, valves are semaphores
// that higher-priority threads pre-empt, EVAP-PROTECT cleanups run when their body is deactivated,
// TRY-ALL succeeds with its first successful subtask and evaporates the others.
//
// Time is an input: the caller passes now (s, any monotonic clock) to Start, Step and the
// setters; nothing here reads a clock or starts a thread. The executive is not thread-safe: call
// it from one thread (a ROS node calls it from its single spinner thread).
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rpl_executive/rpl/behaviour_module.h"
#include "rpl_executive/rpl/plan.h"
#include "rpl_executive/rpl/source.h"
#include "rpl_executive/rpl/value.h"
#include "rpl_executive/rpl/vocabulary.h"

namespace rpl_executive {
namespace rpl {

struct ExecutiveParameters {
  /// Instructions (task steps) one Step may run before it returns; a plan that loops without
  /// waiting is cut off here and resumed by the next Step. [1, 1e9]
  int max_instructions_per_step = 100000;
  /// Nested procedure calls (and expression evaluation depth / 16) before the calling thread
  /// fails with RUNTIME-ERROR. [1, 100000]
  int max_call_depth = 250;
  /// Events kept by events() (the oldest are dropped). [0, 1e7]
  int event_log_capacity = 10000;
  /// Live tasks (about two per thread of control) before a construct that would create more
  /// fails with RUNTIME-ERROR: a plan that forks without end cannot exhaust memory. EVAP-PROTECT
  /// cleanups are exempt. [1, 1e8]
  int max_live_tasks = 1000000;
};

/// Every violation, by parameter name ("max_call_depth: must be in [1, 100000], got 0").
std::vector<std::string> ValidateParameters(const ExecutiveParameters& parameters);

/// Why a thread of control failed: its class, a message, the form that failed, the task path
/// ("GO-TO > NAVIGATION-PROC > EXECUTE NAVIGATION") and, for TRY-ALL / TRY-IN-ORDER, the failure
/// of every subtask.
struct Failure {
  FailureClass failure_class = FailureClass::kRuntimeError;
  std::string message;
  SourceLocation where;
  std::string task_path;
  std::vector<Failure> causes;
  /// "plan.rpl:12:9: MODULE-FAILURE: NAVIGATION failed: unreachable (in GO-TO > ...)", with the
  /// causes indented below.
  std::string ToString() const;
};

/// Something the runtime did that a user or a test wants to see, in order.
struct Event {
  enum class Kind {
    kPlanStarted,
    kPlanFinished,     // detail: succeeded / failed: cause / aborted
    kModuleActivated,  // subject: module; detail: arguments and who
    kModuleSucceeded,
    kModuleFailed,
    kModuleDeactivated,  // detail: why (DEACTIVATE by whom, valve pre-empted, thread ended)
    kValveGranted,       // subject: valve; detail: holder
    kValvePreempted,     // detail: who lost it to whom
    kValveReleased,      // detail: who released it
    kPulse,              // subject: the pulsed fluent
    kCleanup,            // an EVAP-PROTECT body was deactivated: its cleanup starts
    kThreadFailed,       // a thread failed because a module it activated (not awaited) failed
    kFailureHandled,     // WITH-FAILURE-HANDLING caught a failure
    kThreadEnded,        // subject: a thread of control's path; detail: done / failed: ... /
                         // evaporated (for the node's task-tree feedback)
  };
  double time_s = 0.0;
  Kind kind = Kind::kPlanStarted;
  std::string subject;
  std::string detail;
  std::string ToString() const;  // "12.300 MODULE-DEACTIVATED NAVIGATION: ..."
  static const char* KindName(Kind kind);
};

/// One live task of the task tree (for the node's feedback and for tests).
struct TaskInfo {
  enum class State { kActive, kWaitBlocked, kEvaporating };
  int id = 0;
  int parent = -1;
  int depth = 0;
  std::string label;  // "WITH-POLICY", "PROCESS NAVIGATION-PROC", "EXECUTE NAVIGATION"
  State state = State::kActive;
  std::string waiting_for;  // wait-blocked on: "(<= POS-CERTAINTY* 0.8)", "valve WHEELS", ...
  SourceLocation where;
  bool policy = false;                        // the task is (inside) a policy of a WITH-POLICY
  static const char* StateName(State state);  // "active", "wait-blocked", "evaporating"
};

struct FluentState {
  std::string name;
  Value value;
  double stamp_s = 0.0;  // when the value last changed (the caller's clock)
  bool pulsed = false;   // a pulsed fluent (true only at the instant of a pulse)
};

enum class PlanState { kNoPlan, kLoaded, kRunning, kSucceeded, kFailed, kAborted };
const char* PlanStateName(PlanState state);

struct StepResult {
  int instructions = 0;  // task steps run by this Step (0 when nothing changed)
  PlanState state = PlanState::kNoPlan;
};

namespace internal {
class Runtime;
}

class Executive {
 public:
  /// Throws std::invalid_argument when ValidateParameters finds a violation.
  explicit Executive(const ExecutiveParameters& parameters = ExecutiveParameters());
  ~Executive();  // deactivates the modules still active (no cleanups run)
  /// Deactivates the modules still active and drops the plan and the modules now, as the
  /// destructor would: an owner whose members the modules call (its Navigate client) calls it
  /// first in its own destructor. Nothing but destruction may follow.
  void Shutdown();
  Executive(const Executive&) = delete;
  Executive& operator=(const Executive&) = delete;

  // ---- Vocabulary (before Load). A name declared twice throws std::invalid_argument. ----
  void DeclareFluent(const FluentSpec& spec);
  /// Adds a behaviour module and the valves it needs.
  void AddModule(std::shared_ptr<BehaviourModule> module);
  void AddFunction(const FunctionSpec& spec, HostFunction function);
  void AddValve(const std::string& name);
  const Vocabulary& vocabulary() const;

  // ---- Plans ----
  /// Reads and checks a plan (CompilePlan). With errors the loaded plan and the state stay as
  /// they were. Refused (an error) while a plan runs.
  std::vector<Diagnostic> Load(const std::string& text, const std::string& file);
  /// Starts the loaded plan; `globals` override DEFVAR initial values by name. Returns "" or why
  /// it did not start (no plan, running, unknown DEFVAR, an initial value failed).
  std::string Start(double now_s, const std::vector<std::pair<std::string, Value>>& globals = {});
  /// Runs every thread of control that can run now: due WAIT-TIMEs, module reports, threads woken
  /// by fluents; returns when all are blocked or the instruction budget is spent.
  StepResult Step(double now_s);
  /// Evaporates the whole plan; EVAP-PROTECT cleanups run (in this and later Steps). The state
  /// becomes kAborted when the last cleanup has ended.
  void Abort(double now_s);
  PlanState state() const;
  /// The plan's value once it succeeded.
  const Value& result() const;
  /// Why it failed (state kFailed), else null.
  const Failure* failure() const;

  // ---- Fluents ----
  /// Index of a fluent (the vocabulary's, or the running plan's), -1 if unknown.
  int FluentIndex(const std::string& name) const;
  /// Sets a fluent of the vocabulary; threads waiting on a condition that becomes true are woken
  /// (they run in the next Step). Setting the same value does nothing. Throws
  /// std::invalid_argument for an unknown name or index.
  void SetFluent(const std::string& name, const Value& value, double now_s);
  void SetFluent(int index, const Value& value, double now_s);
  Value GetFluent(const std::string& name) const;
  std::vector<FluentState> Fluents() const;

  // ---- Behaviour modules report (any time; processed in the next Step) ----
  /// False when `id` is not an active activation (the report is ignored).
  bool ReportSuccess(ActivationId id, const Value& value = Value::True());
  bool ReportFailure(ActivationId id, const std::string& cause);

  // ---- Valves taken from outside the plan (e.g. the wheels arbiter's bumper reflex) ----
  /// Takes the valve with a priority above every thread: its holder is pre-empted.
  void SeizeValve(const std::string& valve, const std::string& who, double now_s);
  void ReturnValve(const std::string& valve, double now_s);
  /// Who holds the valve ("" = free): the holder's task path or the outside agent's name.
  std::string ValveHolder(const std::string& valve) const;

  // ---- Introspection ----
  std::vector<TaskInfo> TaskTree() const;
  std::size_t NumLiveTasks() const;
  const std::deque<Event>& events() const;
  /// Called with every event as it happens (e.g. the node takes the arbiter's wheels on
  /// kValveGranted of WHEELS). Must not call back into the executive except SetFluent/Report*.
  void SetEventCallback(std::function<void(const Event&)> callback);
  /// When the next WAIT-TIME falls due (the node arms a timer for it), if any.
  std::optional<double> NextWakeUp() const;

 private:
  std::unique_ptr<internal::Runtime> runtime_;
};

}  // namespace rpl
}  // namespace rpl_executive
