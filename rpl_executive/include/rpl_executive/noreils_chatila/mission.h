// The mission formalism of Noreils and Chatila (section 5) as a syntax tree:
//
//   <mission> ::= (MISSION <name> [(PRE: <test>*)] [(ENV: <statement>*)]
//                   [(LSURV: <surv>*)] (MAIN: <statement>*))
//   <cmd>     ::= (<operator> <arg>* <surv>*)  |  (RUN (<process> <param>*) <surv>*)
//   <surv>    ::= MNTR [STATIC] <condition> => <reflex-action> [<control-action>]
//   <reflex-action>  ::= ( <operator call>* )              e.g. ((stop))
//   <control-action> ::= { <statement>* } | ( <statement>* )   Example 2 / Example 1 ((NEXT))
//   <statement> ::= <cmd> | (set <var> <value>) | (IF <test> <then> [<else>])
//                 | (WHILE <test> <statement>*) | (NEXT) | (FAIL)
//                 | (MNTR [STATIC] <condition> => ...)    a nested monitor (control actions)
//                 | <mission>                             a sub-plan in MAIN
//   <condition> ::= (S_<name> <arg>*) | (AND <condition>+) | (OR <condition>+) | (NOT <condition>)
//   <test>      ::= (eq <value> <value>) | (not <test>) | (and <test>+) | (or <test>+)
//                 | (<variable>) | <condition>
// plus, before the mission, (define <type> <name> <value>) of typed variables. See the README
// "Mission files" for every rule and the paper's typography that the shipped files normalize.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/diagnostic.h"
#include "rpl_executive/noreils_chatila/sexpr.h"
#include "rpl_executive/noreils_chatila/value.h"

namespace rpl_executive::noreils_chatila {

/// A value written in a mission: a literal (number, NIL, list), a name (a bare symbol: the
/// variable's value if such a variable exists, else the symbol itself, as ON and T) or an explicit
/// dereference $name (Example 2's $ZONE109: the variable must exist).
struct ValueExpr {
  enum class Kind { kLiteral, kName, kDeref };
  Kind kind = Kind::kLiteral;
  Value literal;
  std::string name;
  Location where;
  std::string ToText() const;
};

/// The left-hand side of a surveillance monitor: atomic sensor conditions (S_zone, ...)
/// combined by AND, OR, NOT (section 4.1.2's (AND (sensor_i, S_i)(sensor_j, S_j))).
struct ConditionNode {
  enum class Kind { kAtom, kAnd, kOr, kNot };
  Kind kind = Kind::kAtom;
  std::string name;         ///< kAtom: S_zone, S_us-threshold, ...
  std::vector<Sexpr> args;  ///< kAtom: raw arguments, decoded by the vocabulary
  std::vector<ConditionNode> children;
  Location where;
  std::string ToText() const;
};

/// Tests of PRE:, IF and WHILE.
struct Test {
  enum class Kind { kEq, kNot, kAnd, kOr, kVariable, kSensor };
  Kind kind = Kind::kVariable;
  std::vector<Test> children;         ///< kNot (one), kAnd, kOr
  ValueExpr lhs, rhs;                 ///< kEq
  std::string variable;               ///< kVariable: (LOA) is true when LOA is not NIL
  std::vector<ConditionNode> sensor;  ///< kSensor: exactly one condition
  Location where;
  std::string ToText() const;
};

struct Statement;

/// MNTR [STATIC] <condition> => <reflex-action> <control-action>.
struct Monitor {
  enum class ControlForm { kNone, kBraces, kParens };
  bool is_static = false;
  ConditionNode condition;
  std::vector<Statement> reflex;   ///< operator calls only (checked)
  std::vector<Statement> control;  ///< any statements
  ControlForm control_form = ControlForm::kNone;
  Location where;  ///< the MNTR keyword
  std::string ToText() const;
};

struct Mission;

struct Statement {
  enum class Kind { kCommand, kRun, kSet, kIf, kWhile, kNext, kFail, kMonitor, kMission };
  Kind kind = Kind::kCommand;
  Location where;
  /// kCommand: the execution operator; kRun: the process.
  std::string op;
  Location op_where;
  std::vector<Sexpr> args;           ///< kCommand, kRun: raw arguments
  std::vector<Monitor> monitors;     ///< kCommand, kRun
  std::string target;                ///< kSet
  ValueExpr value;                   ///< kSet
  Test test;                         ///< kIf, kWhile
  std::vector<Statement> then_body;  ///< kIf (then), kWhile (body)
  std::vector<Statement> else_body;  ///< kIf
  bool has_else = false;
  std::shared_ptr<Monitor> monitor;  ///< kMonitor
  std::shared_ptr<Mission> mission;  ///< kMission
  std::string ToText() const;
};

struct Mission {
  std::string name;
  Location where;
  bool has_pre = false, has_env = false, has_lsurv = false;
  std::vector<Test> pre;
  std::vector<Statement> env;
  std::vector<Monitor> lsurv;
  std::vector<Statement> main;
  std::string ToText() const;
};

/// (define <type> <name> <value>): Tclist[n] (n coordinate tuples), Tpath (points, the last
/// optionally with a heading), Tnum (a number), Tsym (a symbol or NIL).
struct Definition {
  std::string type;  ///< Tclist, Tpath, Tnum, Tsym
  int size = -1;     ///< Tclist[4] -> 4; -1 when not given
  std::string name;
  Value value;
  Location where;
  Location value_where;
  std::string ToText() const;
};

/// A parsed file: definitions, at most one mission and the O-surveillances of
/// (OSURV: <surv>*) (robot operation monitors, section 4.1.1; usually in their own file).
struct MissionFile {
  std::string file;
  std::vector<Definition> definitions;
  std::vector<Mission> missions;  ///< zero or one
  std::vector<Monitor> o_surveillances;
  /// Canonical text; parsing it gives the same tree (the fuzzer checks this).
  std::string ToText() const;
};

}  // namespace rpl_executive::noreils_chatila
