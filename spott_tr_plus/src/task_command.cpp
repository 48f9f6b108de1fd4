// Parser of SPOTT task commands (section III-B). Grammar and decisions: task_command.h.
#include "spott_tr_plus/task_command.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "lexer.h"
#include "spott_map/world.h"

namespace spott_tr_plus {

namespace {

using internal::Tok;
using internal::Token;

const std::vector<std::string>& Prepositions() {
  static const std::vector<std::string> v = {"across",
                                             "against",
                                             "along",
                                             "alongside",
                                             "around",
                                             "at",
                                             "behind",
                                             "beside",
                                             "beyond",
                                             "by",
                                             "far",
                                             "in",
                                             "inside",
                                             "in-back-of",
                                             "in-front-of",
                                             "in-line-with",
                                             "near",
                                             "out",
                                             "outside",
                                             "to-the-left-of",
                                             "to-the-right-of",
                                             "to-the-side-of"};
  return v;
}
const std::vector<std::string>& Orientations() {
  static const std::vector<std::string> v = {"forward", "backward", "left", "right",
                                             "north",   "south",    "east", "west"};
  return v;
}
const std::vector<std::string>& Paths() {
  static const std::vector<std::string> v = {"along",  "around", "via",      "to",
                                             "toward", "from",   "away-from"};
  return v;
}
const std::vector<std::string>& TargetWords() {
  static const std::vector<std::string> v = {"door",  "hallway",   "room",    "wall",
                                             "chair", "desk",      "ellipse", "line",
                                             "point", "rectangle", "cuboid",  "cylinder"};
  return v;
}

bool In(const std::vector<std::string>& words, std::string_view w) {
  return std::find(words.begin(), words.end(), w) != words.end();
}

std::string Join(const std::vector<std::string>& words) {
  std::string s;
  for (size_t i = 0; i < words.size(); ++i) {
    s += i == 0 ? "" : (i + 1 == words.size() ? " or " : ", ");
    s += "'" + words[i] + "'";
  }
  return s;
}

struct Abort {};

// Numbers of numeric attributes each target word accepts (a name is accepted by places).
struct Signature {
  std::vector<size_t> counts;
  const char* text;
};

Signature SignatureOf(const std::string& word) {
  if (word == "door") return {{2, 3, 4}, "(x, y[, width[, theta]]) or (NAME)"};
  if (word == "room" || word == "hallway")
    return {{4, 5}, "(x, y, length, width[, theta]) or (NAME)"};
  if (word == "wall" || word == "line") return {{4}, "(x1, y1, x2, y2)"};
  if (word == "chair") return {{2, 3}, "(x, y[, radius])"};
  if (word == "desk") return {{2, 4, 5}, "(x, y[, length, width[, theta]])"};
  if (word == "point") return {{2}, "(x, y) or (NAME)"};
  if (word == "rectangle") return {{4, 5}, "(x, y, length, width[, theta])"};
  if (word == "ellipse")
    return {{4, 5, 6}, "(x, y, a, b[, theta]) as a 2-D model or (x, y, z, a, b, c) as a geon"};
  if (word == "cuboid") return {{6, 7}, "(x, y, z, length, width, height[, theta])"};
  if (word == "cylinder") return {{5}, "(x, y, z, radius, height)"};
  return {{}, ""};
}

// Targets a map knows by id: places, objects, and named places of the world as points.
bool AcceptsName(const std::string& word) {
  return word == "door" || word == "room" || word == "hallway" || word == "wall" ||
         word == "chair" || word == "desk" || word == "point";
}

class TaskParser {
 public:
  TaskParser(const std::string& text, std::string source) : source_(std::move(source)) {
    tokens_ = internal::Tokenize(text, true);
  }

  TaskParseResult Run() {
    TaskParseResult result;
    try {
      TaskCommand c;
      const Token& verb = Peek();
      c.where = verb.where;
      if (IsWord(verb, "go")) {
        c.verb = Verb::kGo;
      } else if (IsWord(verb, "find")) {
        c.verb = Verb::kFind;
      } else {
        Fail(verb, "a verb ('go' or 'find')");
      }
      Next();
      // DESTINATION: the same for both verbs (for `find` the target is the object sought and
      // its attributes with the preposition where to look). Every part may be empty.
      const Token& t = Peek();
      if (IsTarget(t)) {
        c.destination = ParseTarget();
      } else if (t.kind == Tok::kIdent && In(Prepositions(), t.lexeme)) {
        c.preposition = std::string(Next().lexeme);
        if (!IsTarget(Peek())) {
          Fail(Peek(), "a target after '" + c.preposition + "' (" + Join(TargetWords()) + ")");
        }
        c.destination = ParseTarget();
      }
      // DIRECTION
      const Token& d = Peek();
      if (d.kind == Tok::kIdent && In(Orientations(), d.lexeme)) {
        c.orientation = std::string(Next().lexeme);
      } else if (d.kind == Tok::kIdent && In(Paths(), d.lexeme)) {
        c.path = std::string(Next().lexeme);
        if (!IsTarget(Peek())) {
          Fail(Peek(), "a target after '" + c.path + "' (" + Join(TargetWords()) + ")");
        }
        c.path_target = ParseTarget();
      }
      // SPEED
      const Token& s = Peek();
      if (IsWord(s, "slowly")) {
        c.speed = Speed::kSlowly;
      } else if (IsWord(s, "quickly")) {
        c.speed = Speed::kQuickly;
      } else if (IsWord(s, "normal")) {
        c.speed = Speed::kNormal;
      }
      if (IsWord(s, "slowly") || IsWord(s, "quickly") || IsWord(s, "normal")) {
        c.speed_given = true;
        Next();
      }
      if (Peek().kind != Tok::kEnd) Fail(Peek(), Expected(c));
      result.command = std::move(c);
    } catch (const Abort&) {
    }
    result.diagnostics = std::move(diagnostics_);
    return result;
  }

 private:
  // What may follow at the end of what was parsed.
  std::string Expected(const TaskCommand& c) {
    std::vector<std::string> parts;
    if (!c.destination && c.orientation.empty() && c.path.empty() && !c.speed_given) {
      parts.push_back("a preposition or a target");
    }
    if (c.orientation.empty() && c.path.empty() && !c.speed_given) {
      parts.push_back("an orientation or a path word");
    }
    if (!c.speed_given) parts.push_back("a speed ('slowly', 'quickly', 'normal')");
    parts.push_back("the end of the command");
    std::string s;
    for (size_t i = 0; i < parts.size(); ++i) {
      s += i == 0 ? "" : (i + 1 == parts.size() ? " or " : ", ");
      s += parts[i];
    }
    return s;
  }

  const Token& Peek() const { return tokens_[std::min(pos_, tokens_.size() - 1)]; }
  const Token& Next() {
    const Token& t = tokens_[pos_];
    if (pos_ + 1 < tokens_.size()) ++pos_;
    return t;
  }
  static bool IsWord(const Token& t, std::string_view w) {
    return t.kind == Tok::kIdent && t.lexeme == w;
  }
  static bool IsTarget(const Token& t) {
    return t.kind == Tok::kIdent && In(TargetWords(), t.lexeme);
  }

  [[noreturn]] void Fail(const Token& at, const std::string& expected) {
    Diagnostic d;
    d.file = source_;
    d.where = at.where;
    d.message = at.kind == Tok::kError
                    ? at.text + " (expected " + expected + ")"
                    : "expected " + expected + ", found " + internal::Describe(at);
    diagnostics_.push_back(std::move(d));
    throw Abort{};
  }
  [[noreturn]] void FailAt(Location where, const std::string& message) {
    diagnostics_.push_back(Diagnostic{Diagnostic::Severity::kError, source_, where, message});
    throw Abort{};
  }

  const Token& Peek(size_t ahead) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  // `b` follows `a` with no space between them.
  static bool Adjacent(const Token& b, const Token& a) {
    return b.kind != Tok::kEnd && b.where.line == a.where.line &&
           b.where.column == a.where.column + static_cast<int>(a.lexeme.size());
  }
  // The attribute starting at `first` is neither a number nor an id: names it whole (up to
  // the next ',', ')' or space) in the error.
  [[noreturn]] void NotAnId(const Token& first) {
    std::string text(first.lexeme);
    const Token* prev = &first;
    for (size_t k = pos_ + 1; k < tokens_.size(); ++k) {
      const Token& t = tokens_[k];
      if (!Adjacent(t, *prev) || t.kind == Tok::kComma || t.kind == Tok::kRParen) break;
      text += std::string(t.lexeme);
      prev = &t;
    }
    FailAt(first.where, "'" + text + "' is neither a number in metres nor a name: names are " +
                            "the ids of the world's map, and " + spott_map::kIdRule);
  }

  Target ParseTarget() {
    Target t;
    const Token& w = Next();
    t.word = std::string(w.lexeme);
    t.where = w.where;
    if (t.word == "door" || t.word == "hallway" || t.word == "room" || t.word == "wall") {
      t.klass = TargetClass::kPlace;
    } else if (t.word == "chair" || t.word == "desk") {
      t.klass = TargetClass::kMoveableObject;
    } else if (t.word == "cuboid" || t.word == "cylinder") {
      t.klass = TargetClass::kGeon;
    } else {
      t.klass = TargetClass::kModel2D;
    }
    if (Peek().kind != Tok::kLParen) {
      t.either_ellipse = t.word == "ellipse";
      return t;
    }
    t.has_attributes = true;
    const Location open = Next().where;
    const Signature sig = SignatureOf(t.word);
    do {
      const Token& v = Peek();
      if (v.kind == Tok::kMinus) {
        Next();
        const Token& n = Peek();
        if (n.kind != Tok::kNumber) Fail(n, "a number after '-'");
        if (!n.unit.empty() && n.unit != "m") Fail(n, "a number in metres (no unit or 'm')");
        t.numbers.push_back(-Next().number);
      } else if (v.kind == Tok::kNumber) {
        if (!v.unit.empty() && v.unit != "m") {
          if (AcceptsName(t.word)) NotAnId(v);
          Fail(v, "a number in metres (no unit or 'm')");
        }
        t.numbers.push_back(Next().number);
      } else if (v.kind == Tok::kIdent && AcceptsName(t.word) && t.numbers.empty() &&
                 t.name.empty()) {
        // A name is a world id (spott_map's id rule, world.h): exactly what the world loader
        // accepts, so every id of a world can be named and nothing else is taken for one.
        const Token& after = Peek(1);
        const bool glued =
            Adjacent(after, v) && after.kind != Tok::kComma && after.kind != Tok::kRParen;
        if (!spott_map::IsValidId(std::string(v.lexeme)) || glued) NotAnId(v);
        t.name = std::string(Next().lexeme);
      } else {
        Fail(v, AcceptsName(t.word) ? "a number or a name" : "a number");
      }
    } while (Peek().kind == Tok::kComma && (Next(), true));
    if (Peek().kind != Tok::kRParen) Fail(Peek(), "',' or ')'");
    Next();
    if (!t.name.empty()) {
      if (!t.numbers.empty()) FailAt(open, "'" + t.word + "' takes a name or numbers, not both");
      return t;
    }
    if (std::find(sig.counts.begin(), sig.counts.end(), t.numbers.size()) == sig.counts.end()) {
      FailAt(open, "'" + t.word + "' takes " + sig.text + "; found " +
                       std::to_string(t.numbers.size()) + " number(s)");
    }
    // Decision 3: ellipse is a geon when it has three dimensions.
    if (t.word == "ellipse")
      t.klass = t.numbers.size() == 6 ? TargetClass::kGeon : TargetClass::kModel2D;
    return t;
  }

  std::string source_;
  std::vector<Token> tokens_;
  size_t pos_ = 0;
  std::vector<Diagnostic> diagnostics_;
};

std::string Number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", v);
  return buf;
}

std::string TargetText(const Target& t) {
  std::string s = t.word;
  if (!t.has_attributes) return s;
  s += "(";
  if (!t.name.empty()) s += t.name;
  for (size_t i = 0; i < t.numbers.size(); ++i) s += (i ? ", " : "") + Number(t.numbers[i]);
  return s + ")";
}

}  // namespace

TaskParseResult ParseTaskCommand(const std::string& text, const std::string& source) {
  return TaskParser(text, source).Run();
}

std::string ToText(const TaskCommand& c) {
  std::string s = c.verb == Verb::kGo ? "go" : "find";
  if (!c.preposition.empty()) s += " " + c.preposition;
  if (c.destination) s += " " + TargetText(*c.destination);
  if (!c.orientation.empty()) s += " " + c.orientation;
  if (!c.path.empty()) s += " " + c.path + " " + TargetText(*c.path_target);
  if (c.speed_given) {
    s += c.speed == Speed::kSlowly    ? " slowly"
         : c.speed == Speed::kQuickly ? " quickly"
                                      : " normal";
  }
  return s;
}

}  // namespace spott_tr_plus
