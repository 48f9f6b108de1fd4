// A structured reactive plan (Beetz et al. section 3) read, checked and compiled: every name is
// resolved (variables to frame slots, fluents, modules, valves and procedures to indices) and
// every form's arity checked before anything runs. The grammar is in the package README
// ("RPL structured reactive plans").
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "rpl_executive/rpl/reader.h"
#include "rpl_executive/rpl/source.h"
#include "rpl_executive/rpl/value.h"
#include "rpl_executive/rpl/vocabulary.h"

namespace rpl_executive {
namespace rpl {

enum class FormKind {
  // Expressions (pure when their parts are: evaluated at once, never block).
  kConstant,  // a literal, a quoted datum, T, NIL, a keyword
  kLocal,     // a variable of the current frame (procedure parameter, LET, handler variable)
  kGlobal,    // a DEFVAR variable
  kFluent,    // a fluent's current value
  kBuiltin,   // + - * / = /= < <= > >= NOT ABS SQRT MIN MAX LIST FIRST ... DISTANCE CONCAT
  kHostCall,  // a host function
  kCall,      // a plan procedure (DEFUN / DEF-INTERRUPTIBLE-PROCEDURE)
  kIf,
  kAnd,
  kOr,
  // Statements (run as tasks of a thread of control; may block).
  kSeq,
  kPar,
  kTryAll,
  kTryInOrder,
  kLoop,
  kUntil,  // an UNTIL clause inside LOOP: args[0] the condition
  kWhenever,
  kWaitFor,
  kWaitTime,
  kWithPolicy,
  kWithValve,
  kEvapProtect,
  kProcess,
  kLet,
  kSetfLocal,
  kSetfGlobal,
  kSetfFluent,
  kExecute,
  kActivate,
  kDeactivate,
  kVerifyCondition,
  kFail,
  kPulse,
  kWithFailureHandling,
  kHandlerClause,  // (CLASS (VAR) handler...) of WITH-FAILURE-HANDLING
};

/// The builtin functions (pure).
enum class Builtin {
  kAdd,
  kSub,
  kMul,
  kDiv,
  kNumEq,
  kNumNe,
  kLt,
  kLe,
  kGt,
  kGe,
  kNot,
  kAbs,
  kSqrt,
  kMin,
  kMax,
  kList,
  kFirst,
  kSecond,
  kThird,
  kNth,
  kLength,
  kDistance,
  kConcat,
  kEqual,
};

/// The classes of failure (section 3: "locally recovering from execution failures"); a failure
/// keeps its class, message, the form that failed and the path of tasks it came through.
enum class FailureClass {
  kModuleFailure,  // a behaviour module signalled failure ("unable to reach its destination")
  kInterrupted,    // an activation ended by another thread (DEACTIVATE, a pre-empted valve)
  kPlanFailure,    // (FAIL message)
  kRuntimeError,   // a type error, a host function's error, a limit exceeded
  kAllFailed,      // every subtask of a TRY-ALL / TRY-IN-ORDER failed
};
const char* FailureClassName(FailureClass c);  // "MODULE-FAILURE", ...

struct Form {
  FormKind kind = FormKind::kConstant;
  bool pure = false;  // evaluated inline, without a task
  int line = 0;
  int column = 0;
  int id = 0;      // dense index of the form in its plan
  int index = -1;  // slot / global / fluent / procedure / function / module / valve / builtin /
                   // failure class, by kind
  Value constant;  // kConstant; the name of kProcess
  std::vector<const Form*> args;
  const Datum* datum = nullptr;  // the source
  /// Conditions (WAIT-FOR, WHENEVER, UNTIL, derived fluents): the fluents they read, through pure
  /// procedures too. A waiting thread is woken only by a change of one of these.
  std::vector<int> fluent_deps;
  bool reads_locals = false;  // reads variables of its frame (a wait on it is per thread)
};

struct Procedure {
  std::string name;
  bool interruptible = false;  // DEF-INTERRUPTIBLE-PROCEDURE
  int num_params = 0;
  int frame_size = 0;  // parameters + LET and handler variables
  const Form* body = nullptr;
  bool pure = false;  // body is one pure expression: callable inside conditions
  int line = 0;
  int column = 0;
};

struct GlobalVariable {
  std::string name;
  const Form* init = nullptr;  // evaluated at Start, in order (may read earlier globals)
  int line = 0;
  int column = 0;
};

/// A fluent the plan defines. Fluent indices: the vocabulary's first, then these in order.
struct PlanFluent {
  enum class Kind {
    kValue,    // (DEF-FLUENT NAME initial): set by SETF
    kDerived,  // (DEF-FLUENT NAME expr-over-fluents): recomputed when its inputs change
    kPulse,    // (DEF-PULSE NAME [condition]): pulsed by PULSE or when the condition becomes true
  };
  std::string name;
  Kind kind = Kind::kValue;
  const Form* expr = nullptr;  // initial value, expression or condition (may be null: a pulse)
  int line = 0;
  int column = 0;
};

struct Plan {
  std::string file;
  std::vector<Datum> data;  // the source (forms point into it)
  std::deque<Form> forms;   // every compiled form
  std::vector<Procedure> procedures;
  std::vector<GlobalVariable> globals;
  std::vector<PlanFluent> fluents;
  const Form* main = nullptr;  // SEQ of the top-level activities
  int main_frame_size = 0;
  int num_vocabulary_fluents = 0;  // the vocabulary's fluents come first

  int FindProcedure(const std::string& name) const;
  int FindGlobal(const std::string& name) const;
  SourceLocation Where(const Form& f) const { return {file, f.line, f.column}; }
  /// The form as text ("(<= POS-CERTAINTY* 0.8)").
  static std::string Text(const Form& f);
};

struct CompileResult {
  std::shared_ptr<const Plan> plan;  // null when there are errors
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return plan != nullptr; }
};

/// Reads and checks `text` (named `file` in diagnostics) against `vocabulary`: syntax, unknown
/// names (with the closest known name), arity, definitions only at top level, conditions that
/// must be fluent expressions. All errors are reported, not only the first.
CompileResult CompilePlan(const std::string& text, const std::string& file,
                          const Vocabulary& vocabulary);

}  // namespace rpl
}  // namespace rpl_executive
