// Recursive-descent parser of the TR+ text format. Grammar (README "The TR+ language"):
//
// clang-format off
//   file           := { condition_decl | action_decl | program }
//   condition_decl := 'condition' NAME [ '(' cparam { ',' cparam } ')' ] { cattr } ';'
//   cparam         := [ 'in' | 'out' ] NAME
//   cattr          := 'energized' | 'ballistic' | 'at' NUMBER 'hz' | 'every' DURATION
//   action_decl    := 'action' NAME [ '(' [ NAME { ',' NAME } ] ')' ] [ 'energized' | 'ballistic' ] ';'
//   program        := ( 'main' | 'sub' ) NAME [ '(' [ NAME { ',' NAME } ] ')' ] '{' { rule } '}'
//   rule           := cond '->' [ 'energized' | 'ballistic' ] act
//                     [ 'effects' '{' [ lit { ',' lit } ] '}' ] ';'
//   cond           := xor { ( 'or' | '|' ) [ timeout ] xor }
//   xor            := conj { '^' [ timeout ] conj }
//   conj           := unary { ( 'and' | '&' ) [ timeout ] unary }
//   unary          := 'not' unary | 'true' | 'false' | '(' cond ')' | NAME [ '(' [ arg { ',' arg } ] ')' ]
//   timeout        := '[' DURATION ']'
//   DURATION       := NUMBER ( 's' | 'ms' )
//   act            := par { '>' par }
//   par            := aatom { '||' aatom }
//   aatom          := 'nil' | '(' act ')' | NAME [ '(' [ arg { ',' arg } ] ')' ]
//   arg            := [ '-' ] NUMBER | STRING | NAME
//   lit            := [ 'not' ] NAME [ '(' [ arg { ',' arg } ] ')' ]
// clang-format on
//
// Error recovery: an error in a rule skips to the rule's ';' (braces of `effects { }` are
// balanced), or to the start of a later line that reads as a rule (an unterminated string eats
// its line's ';'); a rule complete but for its ';' is kept when a rule or '}' follows; an error
// in a program's header skips to its '{' and the rules are parsed; a declaration keyword ends
// the program it appears in. So one run reports each error once and no error of a later rule
// is skipped.
#include "spott_tr_plus/parser.h"

#include <sstream>
#include <unordered_set>

#include "lexer.h"
#include "spott_text/file_reading.h"

namespace spott_tr_plus {

namespace {

using internal::Tok;
using internal::Token;

constexpr int kMaxDepth = 200;
constexpr size_t kMaxErrors = 50;

const std::unordered_set<std::string_view>& Reserved() {
  static const std::unordered_set<std::string_view> words = {
      "and",       "or",        "not",       "true",   "false", "nil", "effects",
      "energized", "ballistic", "condition", "action", "main",  "sub"};
  return words;
}

struct ParseAbort {};  // Thrown to leave a statement after an error; caught at recovery points.

class Parser {
 public:
  Parser(std::string_view text, std::string file) : file_(std::move(file)) {
    tokens_ = internal::Tokenize(text, false);
  }

  ParseResult Run() {
    result_.program.file = file_;
    while (Peek().kind != Tok::kEnd && result_.diagnostics.size() < kMaxErrors) {
      try {
        TopLevel();
      } catch (const ParseAbort&) {
        RecoverTopLevel();
      }
    }
    ResolveCalls(result_.program);
    return std::move(result_);
  }

 private:
  const Token& Peek(size_t ahead = 0) const {
    const size_t i = std::min(pos_ + ahead, tokens_.size() - 1);
    return tokens_[i];
  }
  const Token& Next() {
    const Token& t = tokens_[pos_];
    if (pos_ + 1 < tokens_.size()) ++pos_;
    return t;
  }
  bool IsWord(const Token& t, std::string_view w) const {
    return t.kind == Tok::kIdent && t.lexeme == w;
  }
  bool AcceptWord(std::string_view w) {
    if (!IsWord(Peek(), w)) return false;
    Next();
    return true;
  }
  bool Accept(Tok k) {
    if (Peek().kind != k) return false;
    Next();
    return true;
  }

  [[noreturn]] void Fail(const Token& at, const std::string& expected) {
    Diagnostic d;
    d.file = file_;
    d.where = at.where;
    if (at.kind == Tok::kError) {
      d.message = at.text + " (expected " + expected + ")";
    } else {
      d.message = "expected " + expected + ", found " + internal::Describe(at);
    }
    result_.diagnostics.push_back(std::move(d));
    throw ParseAbort{};
  }
  void Error(Location where, const std::string& message) {
    result_.diagnostics.push_back(Diagnostic{Diagnostic::Severity::kError, file_, where, message});
  }

  const Token& Expect(Tok k, const char* what) {
    if (Peek().kind != k) Fail(Peek(), what);
    return Next();
  }
  void ExpectWord(std::string_view w) {
    if (!IsWord(Peek(), w)) Fail(Peek(), "'" + std::string(w) + "'");
    Next();
  }

  std::string Name(const char* what) {
    const Token& t = Peek();
    if (t.kind != Tok::kIdent) Fail(t, what);
    if (Reserved().count(t.lexeme)) {
      Fail(t, std::string(what) + " (the keyword '" + std::string(t.lexeme) +
                  "' cannot be used as a name)");
    }
    Next();
    return std::string(t.lexeme);
  }

  double Duration(const char* what) {
    const Token& t = Peek();
    if (t.kind != Tok::kNumber) Fail(t, what);
    Next();
    if (t.unit == "s") return t.number;
    if (t.unit == "ms") return t.number / 1000.0;
    Diagnostic d{
        Diagnostic::Severity::kError, file_, t.where,
        "expected a duration with its unit ('0.5s' or '500ms'), found " + internal::Describe(t)};
    result_.diagnostics.push_back(d);
    throw ParseAbort{};
  }

  bool IsDeclarationKeyword(const Token& t) const {
    return IsWord(t, "condition") || IsWord(t, "action") || IsWord(t, "main") || IsWord(t, "sub");
  }

  void RecoverTopLevel() {
    // Skip to the next declaration keyword at the start of a statement, or past a '}'.
    while (Peek().kind != Tok::kEnd) {
      const Token& t = Peek();
      if (IsDeclarationKeyword(t)) return;
      Next();
      if (t.kind == Tok::kSemicolon || t.kind == Tok::kRBrace) return;
    }
  }

  // True when the tokens from the current one read as the start of a rule: an '->' comes
  // before the next ';', '}', '{' or declaration keyword.
  bool RuleAhead() const {
    for (size_t i = pos_; i < tokens_.size(); ++i) {
      const Token& t = tokens_[i];
      if (t.kind == Tok::kArrow) return true;
      if (t.kind == Tok::kSemicolon || t.kind == Tok::kRBrace || t.kind == Tok::kLBrace ||
          t.kind == Tok::kEnd || IsDeclarationKeyword(t)) {
        return false;
      }
    }
    return false;
  }

  // After an error in the rule that started at token `start`: skips to the end of the rule.
  // Stops after its ';', before the '}' closing the program (braces opened inside the rule,
  // `effects { }`, are balanced), before a declaration keyword, or at the first token of a
  // later line than the error that reads as a new rule.
  void RecoverRule(size_t start) {
    int depth = 0;
    for (size_t i = start; i < pos_; ++i) {
      if (tokens_[i].kind == Tok::kLBrace) ++depth;
      if (tokens_[i].kind == Tok::kRBrace && depth > 0) --depth;
    }
    const int error_line = Peek().where.line;
    while (Peek().kind != Tok::kEnd) {
      const Token& t = Peek();
      if (t.kind == Tok::kRBrace) {
        if (depth == 0) return;
        --depth;
      } else if (t.kind == Tok::kLBrace) {
        ++depth;
      } else if (t.kind == Tok::kSemicolon) {
        Next();
        return;
      } else if (IsDeclarationKeyword(t)) {
        return;
      } else if (t.where.line > error_line && depth == 0 && FirstOnItsLine() && RuleAhead()) {
        return;
      }
      Next();
    }
  }

  bool FirstOnItsLine() const {
    return pos_ == 0 || tokens_[pos_ - 1].where.line < tokens_[pos_].where.line;
  }

  void TopLevel() {
    const Token& t = Peek();
    if (IsWord(t, "condition")) {
      ConditionDeclaration();
    } else if (IsWord(t, "action")) {
      ActionDeclaration();
    } else if (IsWord(t, "main") || IsWord(t, "sub")) {
      ProgramDefinition();
    } else {
      Fail(t, "'condition', 'action', 'main' or 'sub'");
    }
  }

  void ConditionDeclaration() {
    ConditionDecl d;
    d.where = Next().where;
    d.name = Name("a condition name");
    if (Accept(Tok::kLParen)) {
      if (!Accept(Tok::kRParen)) {
        do {
          ConditionParam p;
          if (AcceptWord("out")) {
            p.is_output = true;
          } else {
            AcceptWord("in");
          }
          p.name = Name("a parameter name");
          d.params.push_back(p);
        } while (Accept(Tok::kComma));
        Expect(Tok::kRParen, "',' or ')'");
      }
    }
    while (!Accept(Tok::kSemicolon)) {
      const Token& t = Peek();
      if (AcceptWord("energized")) {
        d.semantics = Semantics::kEnergized;
      } else if (AcceptWord("ballistic")) {
        d.semantics = Semantics::kBallistic;
      } else if (AcceptWord("at")) {
        const Token& n = Expect(Tok::kNumber, "a frequency ('at 2 hz')");
        if (!n.unit.empty()) {
          Error(n.where, "expected a frequency as 'at 2 hz', found " + internal::Describe(n));
        }
        ExpectWord("hz");
        if (!(n.number > 0.0)) Error(n.where, "the frequency must be > 0 Hz");
        d.frequency_hz = n.number;
      } else if (AcceptWord("every")) {
        const Location where = Peek().where;
        const double period = Duration("a period ('every 0.5s')");
        if (!(period > 0.0)) {
          Error(where, "the period must be > 0 s");
        } else {
          d.frequency_hz = 1.0 / period;
        }
      } else {
        Fail(t, "'energized', 'ballistic', 'at', 'every' or ';'");
      }
    }
    result_.program.conditions.push_back(std::move(d));
  }

  void ActionDeclaration() {
    ActionDecl d;
    d.where = Next().where;
    d.name = Name("an action name");
    if (Accept(Tok::kLParen)) {
      if (!Accept(Tok::kRParen)) {
        do {
          d.params.push_back(Name("a parameter name"));
        } while (Accept(Tok::kComma));
        Expect(Tok::kRParen, "',' or ')'");
      }
    }
    if (AcceptWord("energized")) {
      d.semantics = Semantics::kEnergized;
    } else if (AcceptWord("ballistic")) {
      d.semantics = Semantics::kBallistic;
    }
    Expect(Tok::kSemicolon, "'energized', 'ballistic' or ';'");
    result_.program.actions.push_back(std::move(d));
  }

  void ProgramDefinition() {
    Program p;
    const Token& kw = Next();
    p.is_main = kw.lexeme == "main";
    p.where = kw.where;
    try {
      p.name = Name("a program name");
      if (Accept(Tok::kLParen)) {
        if (!Accept(Tok::kRParen)) {
          do {
            p.params.push_back(Name("a parameter name"));
          } while (Accept(Tok::kComma));
          Expect(Tok::kRParen, "',' or ')'");
        }
      }
      Expect(Tok::kLBrace, "'{'");
    } catch (const ParseAbort&) {
      // A bad header: its rules are still parsed when its '{' follows.
      while (Peek().kind != Tok::kEnd && Peek().kind != Tok::kLBrace &&
             !IsDeclarationKeyword(Peek())) {
        Next();
      }
      if (!Accept(Tok::kLBrace)) return;
    }
    while (true) {
      const Token& t = Peek();
      if (t.kind == Tok::kRBrace) {
        p.end = t.where;
        Next();
        break;
      }
      if (t.kind == Tok::kEnd || IsDeclarationKeyword(t)) {
        Error(t.where, "expected a rule or '}' to close program '" + p.name + "' (opened at line " +
                           std::to_string(p.where.line) + "), found " + internal::Describe(t));
        break;
      }
      if (result_.diagnostics.size() >= kMaxErrors) break;
      const size_t start = pos_;
      try {
        p.rules.push_back(ParseRule());
      } catch (const ParseAbort&) {
        RecoverRule(start);
      }
    }
    result_.program.programs.push_back(std::move(p));
  }

  Rule ParseRule() {
    Rule r;
    r.where = Peek().where;
    depth_ = 0;
    r.condition = Cond();
    Expect(Tok::kArrow, "'->' or a condition operator (and, or, &, |, ^)");
    if (AcceptWord("energized")) {
      r.semantics = Semantics::kEnergized;
    } else if (AcceptWord("ballistic")) {
      r.semantics = Semantics::kBallistic;
    }
    depth_ = 0;
    r.action = Act();
    if (AcceptWord("effects")) {
      r.has_effects = true;
      Expect(Tok::kLBrace, "'{' after 'effects'");
      if (!Accept(Tok::kRBrace)) {
        do {
          EffectLiteral e;
          e.where = Peek().where;
          e.positive = !AcceptWord("not");
          e.name = Name("a condition name");
          if (Accept(Tok::kLParen)) e.args = Args();
          r.effects.push_back(std::move(e));
        } while (Accept(Tok::kComma));
        Expect(Tok::kRBrace, "',' or '}'");
      }
    }
    const char* end = "';' to end the rule ('||' or '>' to compose actions)";
    if (Peek().kind != Tok::kSemicolon && (Peek().kind == Tok::kRBrace || RuleAhead())) {
      // Complete but for its ';', and a rule or the program's end follows: keep it and go on.
      const Token& t = Peek();
      Error(t.where, std::string("expected ") + end + ", found " + internal::Describe(t));
      return r;
    }
    Expect(Tok::kSemicolon, end);
    return r;
  }

  // After '(' : arguments up to and including ')'.
  std::vector<Arg> Args() {
    std::vector<Arg> args;
    if (Accept(Tok::kRParen)) return args;
    do {
      Arg a;
      const Token& t = Peek();
      a.where = t.where;
      if (t.kind == Tok::kMinus && Peek(1).kind == Tok::kNumber && Peek(1).unit.empty()) {
        Next();
        a.kind = Arg::Kind::kNumber;
        a.number = -Next().number;
      } else if (t.kind == Tok::kNumber) {
        if (!t.unit.empty()) Fail(t, "an argument (a number without a unit, a string or a name)");
        a.kind = Arg::Kind::kNumber;
        a.number = Next().number;
      } else if (t.kind == Tok::kString) {
        a.kind = Arg::Kind::kString;
        a.text = Next().text;
      } else if (t.kind == Tok::kIdent && !Reserved().count(t.lexeme)) {
        a.kind = Arg::Kind::kVariable;
        a.text = std::string(Next().lexeme);
      } else {
        Fail(t, "an argument (a number, a string or a variable name)");
      }
      args.push_back(std::move(a));
    } while (Accept(Tok::kComma));
    Expect(Tok::kRParen, "',' or ')'");
    return args;
  }

  void Enter() {
    if (++depth_ > kMaxDepth) Fail(Peek(), "a shallower expression (nested too deeply)");
  }

  double OptionalTimeout() {
    if (!Accept(Tok::kLBracket)) return -1.0;
    const double t = Duration("a timeout ('[0.5s]')");
    Expect(Tok::kRBracket, "']'");
    return t;
  }

  CondExpr Binary(CondOp op, CondExpr left, CondExpr right, double timeout, Location where) {
    CondExpr e;
    e.op = op;
    e.timeout_s = timeout;
    e.where = where;
    e.children.push_back(std::move(left));
    e.children.push_back(std::move(right));
    return e;
  }

  CondExpr Cond() {
    Enter();
    CondExpr left = Xor();
    while (true) {
      const Token& t = Peek();
      CondOp op;
      if (IsWord(t, "or")) {
        op = CondOp::kSeqOr;
      } else if (t.kind == Tok::kBar) {
        op = CondOp::kParOr;
      } else {
        break;
      }
      Next();
      const double timeout = OptionalTimeout();
      left = Binary(op, std::move(left), Xor(), timeout, t.where);
    }
    --depth_;
    return left;
  }

  CondExpr Xor() {
    CondExpr left = Conj();
    while (Peek().kind == Tok::kCaret) {
      const Location where = Next().where;
      const double timeout = OptionalTimeout();
      left = Binary(CondOp::kXor, std::move(left), Conj(), timeout, where);
    }
    return left;
  }

  CondExpr Conj() {
    CondExpr left = Unary();
    while (true) {
      const Token& t = Peek();
      CondOp op;
      if (IsWord(t, "and")) {
        op = CondOp::kSeqAnd;
      } else if (t.kind == Tok::kAmp) {
        op = CondOp::kParAnd;
      } else {
        break;
      }
      Next();
      const double timeout = OptionalTimeout();
      left = Binary(op, std::move(left), Unary(), timeout, t.where);
    }
    return left;
  }

  CondExpr Unary() {
    Enter();
    CondExpr e;
    const Token& t = Peek();
    e.where = t.where;
    if (AcceptWord("not")) {
      e.op = CondOp::kNot;
      e.children.push_back(Unary());
    } else if (AcceptWord("true")) {
      e.op = CondOp::kTrue;
    } else if (AcceptWord("false")) {
      e.op = CondOp::kFalse;
    } else if (Accept(Tok::kLParen)) {
      e = Cond();
      Expect(Tok::kRParen, "')' or a condition operator");
    } else if (t.kind == Tok::kIdent && !Reserved().count(t.lexeme)) {
      e.op = CondOp::kAtom;
      e.name = std::string(Next().lexeme);
      if (Accept(Tok::kLParen)) e.args = Args();
    } else {
      Fail(t, "a condition (a name, 'not', 'true', 'false' or '(')");
    }
    --depth_;
    return e;
  }

  ActExpr Act() {
    Enter();
    ActExpr first = Par();
    if (Peek().kind != Tok::kGreater) {
      --depth_;
      return first;
    }
    ActExpr seq;
    seq.op = ActOp::kSequence;
    seq.where = first.where;
    seq.children.push_back(std::move(first));
    while (Accept(Tok::kGreater)) seq.children.push_back(Par());
    --depth_;
    return seq;
  }

  ActExpr Par() {
    ActExpr first = ActAtom();
    if (Peek().kind != Tok::kBarBar) return first;
    ActExpr par;
    par.op = ActOp::kParallel;
    par.where = first.where;
    par.children.push_back(std::move(first));
    while (Accept(Tok::kBarBar)) par.children.push_back(ActAtom());
    return par;
  }

  ActExpr ActAtom() {
    Enter();
    ActExpr a;
    const Token& t = Peek();
    a.where = t.where;
    if (AcceptWord("nil")) {
      a.op = ActOp::kNil;
    } else if (Accept(Tok::kLParen)) {
      a = Act();
      Expect(Tok::kRParen, "')', '||' or '>'");
    } else if (t.kind == Tok::kIdent && !Reserved().count(t.lexeme)) {
      a.op = ActOp::kInvoke;
      a.name = std::string(Next().lexeme);
      if (Accept(Tok::kLParen)) a.args = Args();
    } else {
      Fail(t, "an action (a name, 'nil' or '(')");
    }
    --depth_;
    return a;
  }

  std::string file_;
  std::vector<Token> tokens_;
  size_t pos_ = 0;
  int depth_ = 0;
  ParseResult result_;
};

}  // namespace

ParseResult ParseProgramText(const std::string& text, const std::string& file) {
  return Parser(text, file).Run();
}

ParseResult ParseProgramFile(const std::string& path) {
  std::string error;
  const auto text = spott_text::ReadTextFile(path, &error);
  if (!text) {
    ParseResult r;
    r.program.file = path;
    r.diagnostics.push_back(
        Diagnostic{Diagnostic::Severity::kError, path, {}, "cannot read the program file: " + error});
    return r;
  }
  return ParseProgramText(*text, path);
}

}  // namespace spott_tr_plus
