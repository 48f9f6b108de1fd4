// The TR+ interpreter (SPOTT III.C): event-driven, single-threaded, driven by its caller's
// clock (a node calls it from one thread).
//
// Semantics (README "Interpreter semantics" has the full statement):
// - Active programs are the main program and the subroutines called by the actions running in
//   active programs (the paper's "currently called set of subroutines"). Only their conditions
//   are evaluated; a condition process whose program is deactivated stops computing and forgets
//   its value (external, pushed conditions keep theirs).
// - A scan evaluates every rule of every active program from the top; the highest true rule
//   fires. A scan runs at once when anything changes: a condition value pushed or computed, an
//   action completing, a condition falling due at its frequency, a timed operator's deadline.
//   There is no fixed tick: NextWakeTime() says when the next timer falls due.
// - Sequential AND/OR compute their right operand only when the left does not decide; the
//   right operand's process is not even demanded. Concurrent AND/OR and XOR demand both.
// - A timed operator is FALSE when an operand it consults has not produced a value within its
//   timeout (now - last value > timeout), whatever the operands compute.
// - A ballistic condition reads FALSE while it computes; an energized one holds its last value.
// - Energized action: started when its rule becomes the highest true rule of its program,
//   sustained while it stays so (restarted at a later scan if it finishes), cancelled (primitive
//   actions stopped, called subroutines deactivated) as soon as it does not. While its rule
//   stays highest, a new value of an output variable it reads restarts it with that value.
// - When the action of a program is replaced (another rule fires, or the same rule with new
//   output values), the subroutines the new action calls at once with the same arguments as
//   the old one are handed over, not restarted: they stay in the "currently called set of
//   subroutines" (SPOTT III.C.1, footnote 11), their actions go on and their conditions keep
//   their values. So are primitive actions both start at once with the same arguments.
// - Ballistic action: started when its rule is the highest true rule after a FALSE-to-TRUE
//   transition of its condition that has not started it yet, and run to completion. It is not
//   restarted while its condition stays TRUE. When a higher rule fires meanwhile the ballistic
//   action is not cancelled: it completes alongside the higher rule's action. Only deactivating
//   its program (or Stop()) cancels it.
// - `a || b` starts both and completes when both have; `a > b` starts b when a completes. A
//   subroutine call completes when the subroutine's first rule fires with a nil action (its
//   goal holds); a call whose subroutine has no such goal runs until cancelled. A call that
//   completes inside a sustained (energized) action, not inside a `>` sequence, keeps its
//   subroutine active (monitoring) while the calling rule stays highest; in a sequence or a
//   ballistic action the subroutine is deactivated. A sustained action is restarted after it
//   completes only when none of its subroutines is still active.
// - The highest true rule is acted on as soon as the scan reaches it; the rules below it are
//   evaluated afterwards in the same scan (all active conditions are monitored).
// - Output variables of a rule's conditions are bound into its action's arguments when the
//   action starts. Across a sequential AND an output also feeds the inputs of the conditions
//   to its right (SPOTT Fig. 13: "find a new room", then "in that room"): their process is the
//   one for the values the output holds when they are evaluated.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "spott_tr_plus/ast.h"
#include "spott_tr_plus/diagnostic.h"
#include "spott_tr_plus/registry.h"

namespace spott_tr_plus {

/// The live state of one active program.
struct FrameState {
  std::string program;
  std::vector<std::string> args;  ///< Bound parameters, as text.
  int depth = 0;                  ///< 0 for main.
  int caller = -1;                ///< Index of the calling frame, -1 for main.
  std::vector<bool> rule_values;  ///< Value of each rule's condition at the last scan.
  int firing_rule = -1;           ///< Highest true rule, -1 if none.
  bool action_running = false;    ///< The firing rule's action is executing.
  int ballistic_running = 0;      ///< Ballistic actions of this program still running.
};

/// The live state of one condition process.
struct ProcessState {
  std::string name;  ///< "name" or "name(input, ...)".
  bool value = false;
  bool active = false;
  bool computing = false;
  Semantics semantics = Semantics::kEnergized;
  double frequency_hz = 0.0;
  double last_update = -std::numeric_limits<double>::infinity();
  std::vector<std::pair<std::string, std::string>> outputs;  ///< (parameter, value text)
};

struct InterpreterState {
  std::string main;
  double now = 0.0;
  uint64_t scans = 0;
  std::vector<FrameState> frames;  ///< Main first, then called subroutines in call order.
  std::vector<ProcessState> processes;
};

struct InterpreterOptions {
  int max_call_depth = 32;             ///< Deeper calls are refused (recursion guard).
  int max_events_per_advance = 10000;  ///< Bounds the scan passes of one event.
  /// Subroutines switched off: a call of one does nothing and is done at once, as `nil`. The
  /// same program then runs on a robot without the sensors they serve (SPOTT ran its program
  /// on the B-12 with the bumper, infrared and QUADRIS subroutines off). Create refuses a name
  /// that is not a subroutine of the file, or the main program.
  std::vector<std::string> off_subroutines;
};

class Interpreter {
 public:
  using Options = InterpreterOptions;

  /// Checks the program (checker.h), binds it to the registry and prepares to run `main_name`
  /// (empty: the file's main program). On any error returns null and the diagnostics.
  static std::unique_ptr<Interpreter> Create(const ProgramFile& file, const Registry& registry,
                                             std::vector<Diagnostic>* diagnostics,
                                             const std::string& main_name = "",
                                             Options options = Options());
  /// Stops every running primitive action through its binding's stop function: whatever those
  /// functions use must outlive the interpreter.
  ~Interpreter();
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  /// Activates the main program and scans.
  void Start(double now);
  /// Cancels every running action and deactivates every program.
  void Stop(double now);
  /// Scans if a timer has fallen due (a condition's period, a timeout). Call at NextWakeTime().
  void Advance(double now);
  /// Scans now, due or not.
  void Scan(double now);
  /// When the next timer falls due (+inf: nothing until an event).
  double NextWakeTime() const;

  /// Pushes the value of an external condition (Registry::ExternalCondition) and scans.
  /// `inputs` select the process of a condition with inputs. Unknown names return false.
  bool SetCondition(const std::string& name, bool value, double now,
                    std::vector<Value> outputs = {}, std::vector<Value> inputs = {});
  /// Reports an asynchronous condition's result. Stale tickets are ignored (false).
  bool CompleteCondition(Ticket ticket, bool value, double now, std::vector<Value> outputs = {});
  /// Reports that a primitive action finished. Stale tickets are ignored (false).
  bool CompleteAction(Ticket ticket, bool success, double now);

  InterpreterState State() const;
  /// Scans performed so far.
  uint64_t scans() const;
  const ProgramFile& program() const;
  const std::string& main_name() const;

 private:
  Interpreter();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace spott_tr_plus
