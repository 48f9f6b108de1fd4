#include "spott_tr_plus/ast.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "spott_text/lexemes.h"
#include "spott_tr_plus/value.h"

namespace spott_tr_plus {

const char* ToString(Semantics s) { return s == Semantics::kEnergized ? "energized" : "ballistic"; }

int ConditionDecl::NumInputs() const {
  int n = 0;
  for (const auto& p : params) n += p.is_output ? 0 : 1;
  return n;
}

int ConditionDecl::NumOutputs() const { return static_cast<int>(params.size()) - NumInputs(); }

bool OutputsOmitted(const CondExpr& atom, const ConditionDecl& decl) {
  return decl.NumOutputs() > 0 && static_cast<int>(atom.args.size()) == decl.NumInputs();
}

const Arg* ArgForParam(const CondExpr& atom, const ConditionDecl& decl, size_t k) {
  if (k >= decl.params.size()) return nullptr;
  if (!OutputsOmitted(atom, decl)) return k < atom.args.size() ? &atom.args[k] : nullptr;
  if (decl.params[k].is_output) return nullptr;
  size_t input = 0;  // the k-th parameter is the input-th input
  for (size_t j = 0; j < k; ++j) input += decl.params[j].is_output ? 0 : 1;
  return input < atom.args.size() ? &atom.args[input] : nullptr;
}

namespace {

// The shortest of 15 and 17 significant digits that reads back as the same double: 0.1 stays
// "0.1", and a condition's value published as text (TRProgramState) is the value itself.
std::string FormatNumber(double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.15g", v);
  if (std::isfinite(v) && std::strtod(buf, nullptr) != v)
    std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

}  // namespace

std::string ValueToString(const Value& value) {
  struct Visitor {
    std::string operator()(std::monostate) const { return "nil"; }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(double d) const { return FormatNumber(d); }
    std::string operator()(const std::string& s) const { return spott_text::QuoteString(s); }
    std::string operator()(const std::vector<double>& v) const {
      std::string s = "[";
      for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + FormatNumber(v[i]);
      return s + "]";
    }
  };
  return std::visit(Visitor{}, value);
}

std::string Arg::ToString() const {
  switch (kind) {
    case Kind::kNumber:
      return FormatNumber(number);
    case Kind::kString:
      return spott_text::QuoteString(text);
    case Kind::kVariable:
      return text;
  }
  return text;
}

const ConditionDecl* ProgramFile::FindCondition(const std::string& name) const {
  for (const auto& c : conditions) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

const ActionDecl* ProgramFile::FindAction(const std::string& name) const {
  for (const auto& a : actions) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

const Program* ProgramFile::FindProgram(const std::string& name) const {
  const int i = ProgramIndex(name);
  return i < 0 ? nullptr : &programs[i];
}

int ProgramFile::ProgramIndex(const std::string& name) const {
  for (size_t i = 0; i < programs.size(); ++i) {
    if (programs[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

const Program* ProgramFile::Main() const {
  for (const auto& p : programs) {
    if (p.is_main) return &p;
  }
  return nullptr;
}

namespace {

void ResolveAction(const ProgramFile& file, ActExpr& a) {
  if (a.op == ActOp::kInvoke) a.is_call = file.FindProgram(a.name) != nullptr;
  for (auto& c : a.children) ResolveAction(file, c);
}

int Precedence(CondOp op) {
  switch (op) {
    case CondOp::kSeqOr:
    case CondOp::kParOr:
      return 1;
    case CondOp::kXor:
      return 2;
    case CondOp::kSeqAnd:
    case CondOp::kParAnd:
      return 3;
    case CondOp::kNot:
      return 4;
    default:
      return 5;
  }
}

const char* OpSymbol(CondOp op) {
  switch (op) {
    case CondOp::kSeqAnd:
      return "and";
    case CondOp::kSeqOr:
      return "or";
    case CondOp::kParAnd:
      return "&";
    case CondOp::kParOr:
      return "|";
    case CondOp::kXor:
      return "^";
    default:
      return "?";
  }
}

std::string ArgsText(const std::vector<Arg>& args) {
  std::string s = "(";
  for (size_t i = 0; i < args.size(); ++i) s += (i ? ", " : "") + args[i].ToString();
  return s + ")";
}

void CondText(const CondExpr& c, std::string& out) {
  switch (c.op) {
    case CondOp::kTrue:
      out += "true";
      return;
    case CondOp::kFalse:
      out += "false";
      return;
    case CondOp::kAtom:
      out += c.name;
      if (!c.args.empty()) out += ArgsText(c.args);
      return;
    case CondOp::kNot: {
      out += "not ";
      const bool paren = Precedence(c.children[0].op) < Precedence(CondOp::kNot);
      if (paren) out += '(';
      CondText(c.children[0], out);
      if (paren) out += ')';
      return;
    }
    default:
      break;
  }
  const int p = Precedence(c.op);
  const bool lp = Precedence(c.children[0].op) < p;
  const bool rp = Precedence(c.children[1].op) <= p;
  if (lp) out += '(';
  CondText(c.children[0], out);
  if (lp) out += ')';
  out += ' ';
  out += OpSymbol(c.op);
  if (c.IsTimed()) out += "[" + FormatNumber(c.timeout_s) + "s]";
  out += ' ';
  if (rp) out += '(';
  CondText(c.children[1], out);
  if (rp) out += ')';
}

void ActText(const ActExpr& a, std::string& out) {
  switch (a.op) {
    case ActOp::kNil:
      out += "nil";
      return;
    case ActOp::kInvoke:
      out += a.name;
      if (!a.args.empty() || a.is_call) out += ArgsText(a.args);
      return;
    case ActOp::kParallel:
    case ActOp::kSequence: {
      const char* sym = a.op == ActOp::kParallel ? " || " : " > ";
      for (size_t i = 0; i < a.children.size(); ++i) {
        if (i) out += sym;
        const ActExpr& ch = a.children[i];
        // `||` binds tighter than `>`; parenthesize a child of the same or looser binding.
        const bool paren = ch.op == ActOp::kSequence || (ch.op == a.op);
        if (paren) out += '(';
        ActText(ch, out);
        if (paren) out += ')';
      }
      return;
    }
  }
}

}  // namespace

void ResolveCalls(ProgramFile& file) {
  for (auto& p : file.programs) {
    for (auto& r : p.rules) ResolveAction(file, r.action);
  }
}

Semantics ActionSemantics(const ProgramFile& file, const Rule& rule) {
  if (rule.semantics) return *rule.semantics;
  if (rule.action.op == ActOp::kInvoke && !rule.action.is_call) {
    if (const ActionDecl* d = file.FindAction(rule.action.name)) return d->semantics;
  }
  return Semantics::kEnergized;
}

std::string ToText(const CondExpr& c) {
  std::string s;
  CondText(c, s);
  return s;
}

std::string ToText(const ActExpr& a) {
  std::string s;
  ActText(a, s);
  return s;
}

std::string ToText(const Rule& r) {
  std::string s = ToText(r.condition) + " -> ";
  if (r.semantics) s += std::string(ToString(*r.semantics)) + " ";
  s += ToText(r.action);
  if (r.has_effects) {
    s += " effects {";
    for (size_t i = 0; i < r.effects.size(); ++i) {
      const auto& e = r.effects[i];
      s += (i ? ", " : " ") + std::string(e.positive ? "" : "not ") + e.name;
      if (!e.args.empty()) s += ArgsText(e.args);
    }
    s += " }";
  }
  return s;
}

std::string ToText(const ProgramFile& file) {
  std::ostringstream out;
  for (const auto& c : file.conditions) {
    out << "condition " << c.name;
    if (!c.params.empty()) {
      out << '(';
      for (size_t i = 0; i < c.params.size(); ++i) {
        out << (i ? ", " : "") << (c.params[i].is_output ? "out " : "") << c.params[i].name;
      }
      out << ')';
    }
    out << ' ' << ToString(c.semantics);
    if (c.frequency_hz > 0) out << " at " << FormatNumber(c.frequency_hz) << " hz";
    out << ";\n";
  }
  for (const auto& a : file.actions) {
    out << "action " << a.name;
    if (!a.params.empty()) {
      out << '(';
      for (size_t i = 0; i < a.params.size(); ++i) out << (i ? ", " : "") << a.params[i];
      out << ')';
    }
    out << ' ' << ToString(a.semantics) << ";\n";
  }
  for (const auto& p : file.programs) {
    out << '\n' << (p.is_main ? "main " : "sub ") << p.name;
    if (!p.params.empty() || !p.is_main) {
      out << '(';
      for (size_t i = 0; i < p.params.size(); ++i) out << (i ? ", " : "") << p.params[i];
      out << ')';
    }
    out << " {\n";
    for (const auto& r : p.rules) out << "  " << ToText(r) << ";\n";
    out << "}\n";
  }
  return out.str();
}

}  // namespace spott_tr_plus
