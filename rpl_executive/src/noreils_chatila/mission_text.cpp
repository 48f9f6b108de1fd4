// Canonical text of the mission tree (mission.h). Parsing the text gives the same tree.
#include <string>

#include "rpl_executive/noreils_chatila/mission.h"

namespace rpl_executive::noreils_chatila {

namespace {

std::string Join(const std::vector<Statement>& statements) {
  std::string out;
  for (size_t i = 0; i < statements.size(); ++i) {
    if (i > 0) out += ' ';
    out += statements[i].ToText();
  }
  return out;
}

// A body in ( ): each statement in its own parentheses inside one more pair, so that one
// statement reads back as a list of one: ((a)), ((a) (b)), ().
std::string Body(const std::vector<Statement>& statements) { return "(" + Join(statements) + ")"; }

std::string Monitors(const std::vector<Monitor>& monitors) {
  std::string out;
  for (const Monitor& m : monitors) out += " " + m.ToText();
  return out;
}

}  // namespace

std::string ValueExpr::ToText() const {
  switch (kind) {
    case Kind::kLiteral:
      return literal.ToText();
    case Kind::kName:
      return name;
    case Kind::kDeref:
      return "$" + name;
  }
  return "NIL";
}

std::string ConditionNode::ToText() const {
  std::string out = "(";
  switch (kind) {
    case Kind::kAtom:
      out += name;
      for (const Sexpr& a : args) out += " " + a.ToText();
      break;
    case Kind::kAnd:
    case Kind::kOr:
    case Kind::kNot:
      out += kind == Kind::kAnd ? "AND" : kind == Kind::kOr ? "OR" : "NOT";
      for (const ConditionNode& c : children) out += " " + c.ToText();
      break;
  }
  return out + ")";
}

std::string Test::ToText() const {
  switch (kind) {
    case Kind::kEq:
      return "(eq " + lhs.ToText() + " " + rhs.ToText() + ")";
    case Kind::kNot:
    case Kind::kAnd:
    case Kind::kOr: {
      std::string out = kind == Kind::kNot ? "(not" : kind == Kind::kAnd ? "(and" : "(or";
      for (const Test& c : children) out += " " + c.ToText();
      return out + ")";
    }
    case Kind::kVariable:
      return "(" + variable + ")";
    case Kind::kSensor:
      return sensor.empty() ? "()" : sensor[0].ToText();
  }
  return "()";
}

std::string Monitor::ToText() const {
  std::string out = is_static ? "MNTR STATIC " : "MNTR ";
  out += condition.ToText() + " => " + Body(reflex);
  switch (control_form) {
    case ControlForm::kNone:
      break;
    case ControlForm::kBraces:
      out += " {" + Join(control) + "}";
      break;
    case ControlForm::kParens:
      out += " " + Body(control);
      break;
  }
  return out;
}

std::string Statement::ToText() const {
  switch (kind) {
    case Kind::kCommand: {
      std::string out = "(" + op;
      for (const Sexpr& a : args) out += " " + a.ToText();
      return out + Monitors(monitors) + ")";
    }
    case Kind::kRun: {
      std::string out = "(RUN (" + op;
      for (const Sexpr& a : args) out += " " + a.ToText();
      return out + ")" + Monitors(monitors) + ")";
    }
    case Kind::kSet:
      return "(set " + target + " " + value.ToText() + ")";
    case Kind::kIf:
      return "(IF " + test.ToText() + " " + Body(then_body) +
             (has_else ? " " + Body(else_body) : std::string()) + ")";
    case Kind::kWhile: {
      std::string out = "(WHILE " + test.ToText();
      if (!then_body.empty()) out += " " + Join(then_body);
      return out + ")";
    }
    case Kind::kNext:
      return "(NEXT)";
    case Kind::kFail:
      return "(FAIL)";
    case Kind::kMonitor:
      return "(" + (monitor ? monitor->ToText() : std::string("MNTR")) + ")";
    case Kind::kMission:
      return mission ? mission->ToText() : std::string("(MISSION)");
  }
  return "()";
}

std::string Mission::ToText() const {
  std::string out = "(MISSION " + name;
  if (has_pre) {
    out += " (PRE:";
    for (const Test& t : pre) out += " " + t.ToText();
    out += ")";
  }
  if (has_env) out += " (ENV:" + (env.empty() ? std::string() : " " + Join(env)) + ")";
  if (has_lsurv) out += " (LSURV:" + Monitors(lsurv) + ")";
  out += " (MAIN:" + (main.empty() ? std::string() : " " + Join(main)) + "))";
  return out;
}

std::string Definition::ToText() const {
  return "(define " + type + (size >= 0 ? "[" + std::to_string(size) + "]" : std::string()) + " " +
         name + " " + value.ToText() + ")";
}

std::string MissionFile::ToText() const {
  std::string out;
  for (const Definition& d : definitions) out += d.ToText() + "\n";
  for (const Mission& m : missions) out += m.ToText() + "\n";
  if (!o_surveillances.empty()) out += "(OSURV:" + Monitors(o_surveillances) + ")\n";
  return out;
}

}  // namespace rpl_executive::noreils_chatila
