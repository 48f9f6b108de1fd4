// The TR+ program as data (SPOTT III.C): condition and action declarations, a main program and
// subroutines, each an ordered list of rules `condition -> action`. Produced by the parser
// (parser.h), read by the checker, the interpreter and the DOT export. The text format is
// documented in spott_tr_plus/README.md ("The TR+ language").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spott_tr_plus/diagnostic.h"

namespace spott_tr_plus {

/// SPOTT III.C.2. A condition is energized when it holds its last value while it recomputes and
/// ballistic when it is FALSE while it recomputes. An action is energized when it is sustained
/// while its rule stays the highest true one and ballistic when it starts on its condition's
/// FALSE-to-TRUE transition and runs to completion.
enum class Semantics { kEnergized, kBallistic };

const char* ToString(Semantics s);

/// A parameter of a condition process: an input (read from the caller's variables) or an output
/// variable the process binds for the rule's action.
struct ConditionParam {
  std::string name;
  bool is_output = false;
};

/// `condition NAME(in A, out B) ballistic at 2 hz;`
struct ConditionDecl {
  std::string name;
  std::vector<ConditionParam> params;
  Semantics semantics = Semantics::kEnergized;
  /// Computation frequency (Hz); 0 = computed on every scan (or pushed from outside).
  double frequency_hz = 0.0;
  Location where;

  int NumInputs() const;
  int NumOutputs() const;
};

/// `action NAME(A, B) ballistic;`
struct ActionDecl {
  std::string name;
  std::vector<std::string> params;
  Semantics semantics = Semantics::kEnergized;
  Location where;
};

/// An argument: a number, a quoted string, or a variable (subroutine parameter or a condition's
/// output variable).
struct Arg {
  enum class Kind { kNumber, kString, kVariable };
  Kind kind = Kind::kVariable;
  double number = 0.0;
  std::string text;  ///< String value or variable name.
  Location where;
  std::string ToString() const;
};

/// Condition operators. Sequential AND/OR evaluate left to right and stop when the value is known
/// (the later operands are not even computed); concurrent AND/OR and XOR compute every operand.
/// Any binary operator may carry a timeout: the expression is FALSE when an operand it consults
/// has not produced a value within the timeout, whatever they compute (the paper's AND_t, OR_t,
/// XOR_t).
enum class CondOp { kTrue, kFalse, kAtom, kNot, kSeqAnd, kSeqOr, kParAnd, kParOr, kXor };

struct CondExpr {
  CondOp op = CondOp::kTrue;
  std::string name;                ///< kAtom: the condition's name.
  std::vector<Arg> args;           ///< kAtom: inputs and output variables, as declared.
  std::vector<CondExpr> children;  ///< kNot: 1; binary operators: 2.
  double timeout_s = -1.0;         ///< Binary operators: < 0 untimed, else the timeout (s).
  Location where;

  bool IsBinary() const { return op >= CondOp::kSeqAnd; }
  bool IsTimed() const { return timeout_s >= 0.0; }
};

/// Action operators: `a || b` runs both concurrently, `a > b` runs a then b (SPOTT III.C.2).
enum class ActOp { kNil, kInvoke, kParallel, kSequence };

struct ActExpr {
  ActOp op = ActOp::kNil;
  std::string name;               ///< kInvoke: a primitive action or a subroutine.
  std::vector<Arg> args;          ///< kInvoke.
  std::vector<ActExpr> children;  ///< kParallel / kSequence: 2 or more.
  bool is_call = false;           ///< kInvoke: set by Resolve() when `name` is a subroutine.
  Location where;
};

/// A literal of a rule's declared effects: `effects { door_open, not bumper_contact }`.
struct EffectLiteral {
  std::string name;
  std::vector<Arg> args;  ///< Inputs only.
  bool positive = true;
  Location where;
};

struct Rule {
  CondExpr condition;
  ActExpr action;
  /// `-> ballistic a` / `-> energized a`; otherwise the action declaration's, else energized.
  std::optional<Semantics> semantics;
  bool has_effects = false;
  std::vector<EffectLiteral> effects;
  Location where;
};

struct Program {
  std::string name;
  bool is_main = false;
  std::vector<std::string> params;
  std::vector<Rule> rules;
  Location where;
  Location end;  ///< The closing brace.
};

struct ProgramFile {
  std::string file;
  std::vector<ConditionDecl> conditions;
  std::vector<ActionDecl> actions;
  std::vector<Program> programs;

  const ConditionDecl* FindCondition(const std::string& name) const;
  const ActionDecl* FindAction(const std::string& name) const;
  const Program* FindProgram(const std::string& name) const;
  int ProgramIndex(const std::string& name) const;  ///< -1 if none.
  /// The program declared `main`, or null.
  const Program* Main() const;
};

/// An atom names a condition either with one argument per declared parameter (inputs and output
/// variables, in order) or with its inputs only, its outputs left unbound: `not bumper_contact`
/// for `condition bumper_contact(out where)` (outputs cannot be bound under `not`). True for the
/// second form (only when the condition has outputs).
bool OutputsOmitted(const CondExpr& atom, const ConditionDecl& decl);

/// The argument an atom gives for parameter `k` of its declaration; null when the atom omits its
/// outputs and `k` is an output, or when the atom has too few arguments.
const Arg* ArgForParam(const CondExpr& atom, const ConditionDecl& decl, size_t k);

/// Marks every invocation of a subroutine as a call (ActExpr::is_call).
void ResolveCalls(ProgramFile& file);

/// The semantics a rule's action runs with.
Semantics ActionSemantics(const ProgramFile& file, const Rule& rule);

/// Text of a condition or action as it would be written (used in DOT labels and live states).
std::string ToText(const CondExpr& c);
std::string ToText(const ActExpr& a);
std::string ToText(const Rule& r);

/// The whole file back as TR+ text (parsing it again gives the same program).
std::string ToText(const ProgramFile& file);

}  // namespace spott_tr_plus
