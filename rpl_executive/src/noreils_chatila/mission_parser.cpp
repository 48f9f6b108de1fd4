#include "rpl_executive/noreils_chatila/mission_parser.h"

#include <sstream>

#include "spott_text/file_reading.h"

namespace rpl_executive::noreils_chatila {

namespace {

const char* KindName(const Sexpr& s) {
  switch (s.kind) {
    case Sexpr::Kind::kSymbol:
      return "symbol";
    case Sexpr::Kind::kNumber:
      return "number";
    case Sexpr::Kind::kParen:
      return "list";
    case Sexpr::Kind::kBrace:
      return "{...} block";
    case Sexpr::Kind::kBracket:
      return "[...] size";
  }
  return "form";
}

std::string Shown(const Sexpr& s) {
  std::string text = s.ToText();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return "'" + text + "'";
}

bool IsTestKeyword(const Sexpr& s) {
  return s.IsKeyword("eq") || s.IsKeyword("not") || s.IsKeyword("and") || s.IsKeyword("or");
}

bool StartsWithS(const std::string& name) {
  return name.size() > 2 && (name[0] == 'S' || name[0] == 's') && name[1] == '_';
}

class Parser {
 public:
  explicit Parser(const std::string& file) : file_(file) {}

  void Error(Location where, std::string message) {
    Diagnostic d;
    d.file = file_;
    d.where = where;
    d.message = std::move(message);
    diagnostics_.push_back(std::move(d));
  }

  std::vector<Diagnostic> TakeDiagnostics() { return std::move(diagnostics_); }

  void TopLevel(const Sexpr& form, MissionFile* out) {
    if (!form.IsList() || form.items.empty() || !form.items[0].IsSymbol()) {
      Error(form.where,
            "expected (define ...), (MISSION ...) or (OSURV: ...), found " + Shown(form));
      return;
    }
    const Sexpr& head = form.items[0];
    if (head.IsKeyword("define")) {
      Definition d;
      if (ParseDefinition(form, &d)) out->definitions.push_back(std::move(d));
    } else if (head.IsKeyword("MISSION")) {
      Mission m;
      if (ParseMission(form, &m)) {
        if (!out->missions.empty()) {
          Error(form.where, "a file holds one mission; '" + out->missions[0].name +
                                "' is already defined at line " +
                                std::to_string(out->missions[0].where.line));
        } else {
          out->missions.push_back(std::move(m));
        }
      }
    } else if (head.IsKeyword("OSURV:")) {
      ParseMonitorSequence(form.items, 1, &out->o_surveillances, "OSURV:");
    } else {
      Error(head.where,
            "expected (define ...), (MISSION ...) or (OSURV: ...), found '" + head.text + "'");
    }
  }

 private:
  // --- values -------------------------------------------------------------------------------
  bool ToValue(const Sexpr& s, Value* out) {
    switch (s.kind) {
      case Sexpr::Kind::kNumber:
        *out = Value::Number(s.number);
        return true;
      case Sexpr::Kind::kSymbol:
        *out = Value::Symbol(s.text);
        return true;
      case Sexpr::Kind::kParen: {
        std::vector<Value> items;
        for (const Sexpr& item : s.items) {
          Value v;
          if (!ToValue(item, &v)) return false;
          items.push_back(std::move(v));
        }
        *out = Value::List(std::move(items));
        return true;
      }
      default:
        Error(s.where, std::string("a value cannot be a ") + KindName(s));
        return false;
    }
  }

  bool ParseValueExpr(const Sexpr& s, ValueExpr* out) {
    out->where = s.where;
    if (s.kind == Sexpr::Kind::kSymbol) {
      if (s.text.size() > 1 && s.text[0] == '$') {
        out->kind = ValueExpr::Kind::kDeref;
        out->name = s.text.substr(1);
        return true;
      }
      if (s.text == "$") {
        Error(s.where, "'$' must be followed by a variable name ($ZONE109)");
        return false;
      }
      Value v = Value::Symbol(s.text);
      if (v.IsNil()) {
        out->kind = ValueExpr::Kind::kLiteral;
        out->literal = v;
      } else {
        out->kind = ValueExpr::Kind::kName;
        out->name = s.text;
      }
      return true;
    }
    out->kind = ValueExpr::Kind::kLiteral;
    return ToValue(s, &out->literal);
  }

  // --- definitions --------------------------------------------------------------------------
  bool CheckPoint(const Value& p, size_t max_numbers, const Location& where,
                  const std::string& what) {
    if (!p.IsList() || p.list().size() < 2 || p.list().size() > max_numbers) {
      Error(where, what + " must be a list of " +
                       (max_numbers == 2 ? std::string("2 numbers") : "2 or 3 numbers") +
                       ", found " + p.ToText());
      return false;
    }
    for (const Value& n : p.list()) {
      if (!n.IsNumber()) {
        Error(where, what + " must hold numbers, found " + p.ToText());
        return false;
      }
    }
    return true;
  }

  bool ParseDefinition(const Sexpr& form, Definition* d) {
    d->where = form.where;
    const auto& items = form.items;
    size_t i = 1;
    if (i >= items.size() || !items[i].IsSymbol()) {
      Error(i < items.size() ? items[i].where : form.where,
            "define: expected a type (Tclist[n], Tpath, Tnum, Tsym) after 'define'");
      return false;
    }
    d->type = items[i].text;
    const Location type_where = items[i].where;
    ++i;
    if (i < items.size() && items[i].kind == Sexpr::Kind::kBracket) {
      const Sexpr& b = items[i];
      if (b.items.size() != 1 || b.items[0].kind != Sexpr::Kind::kNumber || b.items[0].number < 1 ||
          b.items[0].number > 100000 || b.items[0].number != static_cast<int>(b.items[0].number)) {
        Error(b.where, "define: the size in [ ] must be a whole number from 1 (Tclist[4])");
        return false;
      }
      d->size = static_cast<int>(b.items[0].number);
      ++i;
    }
    if (d->type != "Tclist" && d->type != "Tpath" && d->type != "Tnum" && d->type != "Tsym") {
      Error(type_where,
            "define: unknown type '" + d->type + "' (known: Tclist[n], Tpath, Tnum, Tsym)");
      return false;
    }
    if (d->size >= 0 && d->type != "Tclist") {
      Error(type_where, "define: only Tclist takes a size in [ ]");
      return false;
    }
    if (i >= items.size() || !items[i].IsSymbol() || items[i].text[0] == '$') {
      Error(i < items.size() ? items[i].where : form.where,
            "define: expected the variable's name after the type");
      return false;
    }
    d->name = items[i].text;
    if (Value::Symbol(d->name).IsNil()) {
      Error(items[i].where, "define: NIL cannot be a variable's name");
      return false;
    }
    ++i;
    if (i >= items.size()) {
      Error(form.where, "define: '" + d->name + "' has no value");
      return false;
    }
    if (i + 1 < items.size()) {
      Error(items[i + 1].where, "define: '" + d->name + "' takes one value, found more");
      return false;
    }
    d->value_where = items[i].where;
    if (!ToValue(items[i], &d->value)) return false;
    const Value& v = d->value;
    const Location w = d->value_where;
    if (d->type == "Tnum") {
      if (!v.IsNumber()) {
        Error(w, "define: Tnum '" + d->name + "' must be a number, found " + v.ToText());
        return false;
      }
    } else if (d->type == "Tsym") {
      if (!v.IsNil() && !v.IsSymbol()) {
        Error(w, "define: Tsym '" + d->name + "' must be a symbol, found " + v.ToText());
        return false;
      }
    } else {
      if (!v.IsList()) {
        Error(w, "define: " + d->type + " '" + d->name + "' must be a list, found " + v.ToText());
        return false;
      }
      const auto& points = v.list();
      if (d->type == "Tclist") {
        if (d->size >= 0 && static_cast<int>(points.size()) != d->size) {
          Error(w, "define: Tclist[" + std::to_string(d->size) + "] '" + d->name + "' needs " +
                       std::to_string(d->size) + " tuples, found " + std::to_string(points.size()));
          return false;
        }
        for (const Value& p : points) {
          if (!CheckPoint(p, 2, w, "each tuple of '" + d->name + "'")) return false;
        }
      } else {  // Tpath
        for (size_t k = 0; k < points.size(); ++k) {
          if (!CheckPoint(points[k], 3, w, "each point of '" + d->name + "'")) {
            return false;
          }
          if (points[k].list().size() == 3 && k + 1 != points.size()) {
            Error(w, "define: only the last point of path '" + d->name +
                         "' may give a heading (x y heading)");
            return false;
          }
        }
      }
    }
    return true;
  }

  // --- missions -----------------------------------------------------------------------------
  bool ParseMission(const Sexpr& form, Mission* m) {
    m->where = form.where;
    const auto& items = form.items;
    if (items.size() < 2 || !items[1].IsSymbol()) {
      Error(items.size() < 2 ? form.where : items[1].where,
            "MISSION: expected the mission's name after MISSION");
      return false;
    }
    m->name = items[1].text;
    bool has_main = false;
    bool ok = true;
    for (size_t i = 2; i < items.size(); ++i) {
      const Sexpr& section = items[i];
      if (!section.IsList() || section.items.empty() || !section.items[0].IsSymbol()) {
        Error(section.where, "MISSION " + m->name +
                                 ": expected a section (PRE: ...), (ENV: ...), (LSURV: ...) or "
                                 "(MAIN: ...), found " +
                                 Shown(section));
        ok = false;
        continue;
      }
      const Sexpr& head = section.items[0];
      auto duplicate = [&](bool seen, const char* name) {
        if (seen) Error(head.where, std::string("MISSION ") + m->name + ": a second " + name);
        return seen;
      };
      if (head.IsKeyword("PRE:")) {
        if (duplicate(m->has_pre, "PRE: section")) continue;
        m->has_pre = true;
        for (size_t k = 1; k < section.items.size(); ++k) {
          Test t;
          if (ParseTest(section.items[k], &t)) {
            m->pre.push_back(std::move(t));
          } else {
            ok = false;
          }
        }
      } else if (head.IsKeyword("ENV:")) {
        if (duplicate(m->has_env, "ENV: section")) continue;
        m->has_env = true;
        ok &= ParseStatements(section.items, 1, &m->env);
      } else if (head.IsKeyword("LSURV:")) {
        if (duplicate(m->has_lsurv, "LSURV: section")) continue;
        m->has_lsurv = true;
        ok &= ParseMonitorSequence(section.items, 1, &m->lsurv, "LSURV:");
      } else if (head.IsKeyword("MAIN:")) {
        if (duplicate(has_main, "MAIN: section")) continue;
        has_main = true;
        ok &= ParseStatements(section.items, 1, &m->main);
      } else {
        Error(head.where, "MISSION " + m->name + ": unknown section '" + head.text +
                              "' (expected PRE:, ENV:, LSURV: or MAIN:)");
        ok = false;
      }
    }
    if (!has_main) {
      Error(form.where, "MISSION " + m->name + ": has no (MAIN: ...) section");
      ok = false;
    }
    return ok;
  }

  bool ParseStatements(const std::vector<Sexpr>& items, size_t from, std::vector<Statement>* out) {
    bool ok = true;
    for (size_t i = from; i < items.size(); ++i) {
      Statement s;
      if (ParseStatement(items[i], &s)) {
        out->push_back(std::move(s));
      } else {
        ok = false;
      }
    }
    return ok;
  }

  // A body in IF, a reflex or a control action in parentheses: ((a)(b)) is a list of statements,
  // (a) one statement, () none; { ... } is a list of statements.
  bool ParseBody(const Sexpr& s, std::vector<Statement>* out) {
    if (s.kind == Sexpr::Kind::kBrace) return ParseStatements(s.items, 0, out);
    if (!s.IsList()) {
      Error(s.where, "expected a statement or a list of statements in ( ), found " + Shown(s));
      return false;
    }
    if (s.items.empty()) return true;
    if (s.items[0].IsSymbol()) {
      Statement st;
      if (!ParseStatement(s, &st)) return false;
      out->push_back(std::move(st));
      return true;
    }
    return ParseStatements(s.items, 0, out);
  }

  bool ParseStatement(const Sexpr& s, Statement* st) {
    st->where = s.where;
    if (!s.IsList()) {
      Error(s.where, "expected a statement in ( ), found " + Shown(s));
      return false;
    }
    if (s.items.empty()) {
      Error(s.where, "empty statement ()");
      return false;
    }
    const Sexpr& head = s.items[0];
    if (!head.IsSymbol()) {
      Error(head.where, "a statement starts with an operator or keyword, found " + Shown(head));
      return false;
    }
    const auto& items = s.items;
    if (head.IsKeyword("set")) {
      st->kind = Statement::Kind::kSet;
      if (items.size() != 3 || !items[1].IsSymbol() || items[1].text[0] == '$' ||
          Value::Symbol(items[1].text).IsNil()) {
        Error(s.where, "set: expected (set <variable> <value>)");
        return false;
      }
      st->target = items[1].text;
      return ParseValueExpr(items[2], &st->value);
    }
    if (head.IsKeyword("IF")) {
      st->kind = Statement::Kind::kIf;
      if (items.size() < 3 || items.size() > 4) {
        Error(s.where, "IF: expected (IF <test> <then> [<else>])");
        return false;
      }
      if (!ParseTest(items[1], &st->test)) return false;
      if (!ParseBody(items[2], &st->then_body)) return false;
      if (items.size() == 4) {
        st->has_else = true;
        if (!ParseBody(items[3], &st->else_body)) return false;
      }
      return true;
    }
    if (head.IsKeyword("WHILE")) {
      st->kind = Statement::Kind::kWhile;
      if (items.size() < 2) {
        Error(s.where, "WHILE: expected (WHILE <test> <statement>...)");
        return false;
      }
      if (!ParseTest(items[1], &st->test)) return false;
      bool ok = true;
      for (size_t i = 2; i < items.size(); ++i) {
        if (items[i].IsList() && !items[i].items.empty() && !items[i].items[0].IsSymbol()) {
          ok &= ParseBody(items[i], &st->then_body);
        } else {
          Statement b;
          if (ParseStatement(items[i], &b)) {
            st->then_body.push_back(std::move(b));
          } else {
            ok = false;
          }
        }
      }
      return ok;
    }
    if (head.IsKeyword("NEXT") || head.IsKeyword("FAIL")) {
      st->kind = head.IsKeyword("NEXT") ? Statement::Kind::kNext : Statement::Kind::kFail;
      if (items.size() != 1) {
        Error(items[1].where,
              std::string(head.IsKeyword("NEXT") ? "NEXT" : "FAIL") + " takes no arguments");
        return false;
      }
      return true;
    }
    if (head.IsKeyword("MNTR")) {
      st->kind = Statement::Kind::kMonitor;
      std::vector<Monitor> monitors;
      if (!ParseMonitorSequence(items, 0, &monitors, "MNTR")) return false;
      if (monitors.size() != 1) {
        Error(s.where, "a nested (MNTR ...) holds exactly one monitor");
        return false;
      }
      st->monitor = std::make_shared<Monitor>(std::move(monitors[0]));
      return true;
    }
    if (head.IsKeyword("MISSION")) {
      st->kind = Statement::Kind::kMission;
      auto m = std::make_shared<Mission>();
      if (!ParseMission(s, m.get())) return false;
      st->mission = std::move(m);
      return true;
    }
    if (head.IsKeyword("STATIC") || head.text == "=>" || IsTestKeyword(head)) {
      Error(head.where, "'" + head.text + "' cannot start a statement");
      return false;
    }
    size_t i = 1;
    if (head.IsKeyword("RUN")) {
      st->kind = Statement::Kind::kRun;
      if (items.size() < 2 || !items[1].IsList() || items[1].items.empty() ||
          !items[1].items[0].IsSymbol()) {
        Error(s.where, "RUN: expected (RUN (<process> <parameter>...) <monitor>...)");
        return false;
      }
      st->op = items[1].items[0].text;
      st->op_where = items[1].items[0].where;
      st->args.assign(items[1].items.begin() + 1, items[1].items.end());
      i = 2;
    } else {
      st->kind = Statement::Kind::kCommand;
      st->op = head.text;
      st->op_where = head.where;
      while (i < items.size() && !items[i].IsKeyword("MNTR")) st->args.push_back(items[i++]);
    }
    if (i < items.size() && !items[i].IsKeyword("MNTR")) {
      Error(items[i].where,
            "RUN: expected MNTR or the end of the command, found " + Shown(items[i]));
      return false;
    }
    return ParseMonitorSequence(items, i, &st->monitors, st->op.c_str());
  }

  // MNTR [STATIC] <condition> => <reflex> [<control>] ..., also parenthesized (MNTR ...).
  bool ParseMonitorSequence(const std::vector<Sexpr>& items, size_t i, std::vector<Monitor>* out,
                            const std::string& context) {
    bool ok = true;
    while (i < items.size()) {
      const Sexpr& first = items[i];
      if (first.IsList() && !first.items.empty() && first.items[0].IsKeyword("MNTR")) {
        ok &= ParseMonitorSequence(first.items, 0, out, context);
        ++i;
        continue;
      }
      if (!first.IsKeyword("MNTR")) {
        Error(first.where, context + ": expected MNTR, found " + Shown(first));
        return false;
      }
      Monitor m;
      m.where = first.where;
      ++i;
      if (i < items.size() && items[i].IsKeyword("STATIC")) {
        m.is_static = true;
        ++i;
      }
      if (i >= items.size()) {
        Error(first.where, "MNTR: expected a condition after MNTR");
        return false;
      }
      if (!ParseCondition(items[i], &m.condition, 0)) return false;
      ++i;
      if (i >= items.size() || !(items[i].IsSymbol() && items[i].text == "=>")) {
        Error(i < items.size() ? items[i].where : first.where,
              "MNTR: expected '=>' after the condition " + m.condition.ToText());
        return false;
      }
      ++i;
      if (i >= items.size() || !items[i].IsList()) {
        Error(i < items.size() ? items[i].where : first.where,
              "MNTR: expected the reflex action in ( ) after '=>', as ((stop))");
        return false;
      }
      if (!ParseBody(items[i], &m.reflex)) return false;
      ++i;
      if (i < items.size() && (items[i].kind == Sexpr::Kind::kBrace ||
                               (items[i].IsList() && !(!items[i].items.empty() &&
                                                       items[i].items[0].IsKeyword("MNTR"))))) {
        m.control_form = items[i].kind == Sexpr::Kind::kBrace ? Monitor::ControlForm::kBraces
                                                              : Monitor::ControlForm::kParens;
        if (!ParseBody(items[i], &m.control)) return false;
        ++i;
      }
      out->push_back(std::move(m));
    }
    return ok;
  }

  bool ParseCondition(const Sexpr& s, ConditionNode* c, int depth) {
    c->where = s.where;
    if (!s.IsList() || s.items.empty() || !s.items[0].IsSymbol()) {
      Error(s.where, "expected a condition such as (S_zone IN ZONE109), found " + Shown(s));
      return false;
    }
    const Sexpr& head = s.items[0];
    if (head.IsKeyword("AND") || head.IsKeyword("OR") || head.IsKeyword("NOT")) {
      c->kind = head.IsKeyword("AND")  ? ConditionNode::Kind::kAnd
                : head.IsKeyword("OR") ? ConditionNode::Kind::kOr
                                       : ConditionNode::Kind::kNot;
      const size_t n = s.items.size() - 1;
      if (n == 0 || (c->kind == ConditionNode::Kind::kNot && n != 1)) {
        Error(s.where, head.text + ": expected " +
                           (c->kind == ConditionNode::Kind::kNot ? "one condition"
                                                                 : "one or more conditions"));
        return false;
      }
      for (size_t i = 1; i < s.items.size(); ++i) {
        ConditionNode child;
        if (!ParseCondition(s.items[i], &child, depth + 1)) return false;
        c->children.push_back(std::move(child));
      }
      return true;
    }
    c->kind = ConditionNode::Kind::kAtom;
    c->name = head.text;
    c->args.assign(s.items.begin() + 1, s.items.end());
    return true;
  }

  bool ParseTest(const Sexpr& s, Test* t) {
    t->where = s.where;
    if (!s.IsList() || s.items.empty() || !s.items[0].IsSymbol()) {
      Error(s.where, "expected a test such as (eq motor ON) or (LOA), found " + Shown(s));
      return false;
    }
    const Sexpr& head = s.items[0];
    const auto& items = s.items;
    if (head.IsKeyword("eq")) {
      t->kind = Test::Kind::kEq;
      if (items.size() != 3) {
        Error(s.where, "eq: expected (eq <value> <value>)");
        return false;
      }
      return ParseValueExpr(items[1], &t->lhs) && ParseValueExpr(items[2], &t->rhs);
    }
    if (head.IsKeyword("not") || head.IsKeyword("and") || head.IsKeyword("or")) {
      t->kind = head.IsKeyword("not")   ? Test::Kind::kNot
                : head.IsKeyword("and") ? Test::Kind::kAnd
                                        : Test::Kind::kOr;
      const size_t n = items.size() - 1;
      if (n == 0 || (t->kind == Test::Kind::kNot && n != 1)) {
        Error(s.where, head.text + ": expected " +
                           (t->kind == Test::Kind::kNot ? "one test" : "one or more tests"));
        return false;
      }
      for (size_t i = 1; i < items.size(); ++i) {
        Test child;
        if (!ParseTest(items[i], &child)) return false;
        t->children.push_back(std::move(child));
      }
      return true;
    }
    if (StartsWithS(head.text)) {
      t->kind = Test::Kind::kSensor;
      ConditionNode c;
      if (!ParseCondition(s, &c, 0)) return false;
      t->sensor.push_back(std::move(c));
      return true;
    }
    if (items.size() == 1 && head.text[0] != '$' && !Value::Symbol(head.text).IsNil() &&
        !head.IsKeyword("AND") && !head.IsKeyword("OR") && !head.IsKeyword("NOT")) {
      t->kind = Test::Kind::kVariable;
      t->variable = head.text;
      return true;
    }
    Error(s.where, "unknown test " + Shown(s) +
                       ": expected (eq a b), (not ...), (and ...), (or ...), (<variable>) or a "
                       "sensor condition (S_...)");
    return false;
  }

  std::string file_;
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace

ParseResult ParseMissionText(const std::string& text, const std::string& file) {
  ParseResult result;
  result.file.file = file;
  ReadResult read = ReadSexprs(text, file);
  Parser parser(file);
  for (const Sexpr& form : read.forms) parser.TopLevel(form, &result.file);
  result.diagnostics = std::move(read.diagnostics);
  for (Diagnostic& d : parser.TakeDiagnostics()) result.diagnostics.push_back(std::move(d));
  return result;
}

ParseResult ParseMissionFile(const std::string& path) {
  std::string error;
  const auto text = spott_text::ReadTextFile(path, &error);
  if (!text) {
    ParseResult result;
    result.file.file = path;
    Diagnostic d;
    d.file = path;
    d.message = "cannot read the mission file: " + error;
    result.diagnostics.push_back(d);
    return result;
  }
  return ParseMissionText(*text, path);
}

}  // namespace rpl_executive::noreils_chatila
