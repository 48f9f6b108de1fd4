#include "rpl_executive/rpl/reader.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "rpl_executive/rpl/value.h"
#include "spott_text/lexemes.h"

namespace rpl_executive {
namespace rpl {

const std::string& Datum::Head() const {
  static const std::string* empty = new std::string();
  if (kind == Kind::kList && !items.empty() && items[0].kind == Kind::kSymbol) {
    return items[0].text;
  }
  return *empty;
}

namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
bool IsDelimiter(char c) { return IsSpace(c) || c == '(' || c == ')' || c == '"' || c == ';'; }
// Characters a symbol may contain besides letters and digits.
bool IsSymbolPunctuation(char c) {
  switch (c) {
    case '-':
    case '*':
    case '+':
    case '/':
    case '<':
    case '>':
    case '=':
    case '?':
    case '!':
    case '&':
    case '%':
    case '$':
    case ':':
    case '_':
    case '.':
    case '~':
    case '^':
    case '@':
      return true;
    default:
      return false;
  }
}

bool LooksNumeric(const std::string& atom) {
  size_t i = 0;
  if (i < atom.size() && (atom[i] == '+' || atom[i] == '-')) ++i;
  if (i < atom.size() && atom[i] == '.') ++i;
  return i < atom.size() && std::isdigit(static_cast<unsigned char>(atom[i]));
}

class Reader {
 public:
  Reader(const std::string& text, const std::string& file) : text_(text), file_(file) {}

  ReadResult Run() {
    ReadResult result;
    while (true) {
      SkipSpaceAndComments();
      if (AtEnd()) break;
      if (Peek() == ')') {
        Error(line_, column_, "unexpected ')' with no list open");
        Advance();
        continue;
      }
      Datum d;
      if (ReadDatum(&d, 0)) result.forms.push_back(std::move(d));
    }
    result.diagnostics = std::move(diagnostics_);
    return result;
  }

 private:
  bool AtEnd() const { return pos_ >= text_.size(); }
  char Peek() const { return text_[pos_]; }
  void Advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }
  void Error(int line, int column, std::string message) {
    diagnostics_.push_back(
        {Diagnostic::Severity::kError, file_, {line, column}, std::move(message)});
  }

  void SkipSpaceAndComments() {
    while (!AtEnd()) {
      char c = Peek();
      if (IsSpace(c)) {
        Advance();
      } else if (c == ';') {
        while (!AtEnd() && Peek() != '\n') Advance();
      } else if (c == '#' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '|') {
        const int line = line_, column = column_;
        Advance();
        Advance();
        bool closed = false;
        while (!AtEnd()) {
          if (Peek() == '|' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '#') {
            Advance();
            Advance();
            closed = true;
            break;
          }
          Advance();
        }
        if (!closed) Error(line, column, "unterminated block comment '#|' (no '|#' follows)");
      } else {
        return;
      }
    }
  }

  // Reads one datum at the current position (not a ')'). False on an error (reported).
  bool ReadDatum(Datum* out, int depth) {
    out->line = line_;
    out->column = column_;
    const char c = Peek();
    if (c == '(') return ReadList(out, depth);
    if (c == '"') return ReadString(out);
    if (c == '\'') {
      Advance();
      SkipSpaceAndComments();
      if (AtEnd() || Peek() == ')') {
        Error(out->line, out->column, "a quote ' must be followed by a datum");
        return false;
      }
      Datum quoted;
      if (!ReadDatum(&quoted, depth + 1)) return false;
      out->kind = Datum::Kind::kList;
      Datum head;
      head.kind = Datum::Kind::kSymbol;
      head.text = "QUOTE";
      head.line = out->line;
      head.column = out->column;
      out->items.push_back(std::move(head));
      out->items.push_back(std::move(quoted));
      return true;
    }
    return ReadAtom(out);
  }

  bool ReadList(Datum* out, int depth) {
    const int line = line_, column = column_;
    if (depth >= kMaxNestingDepth) {
      Error(line, column,
            "lists nested deeper than " + std::to_string(kMaxNestingDepth) + " levels");
      SkipToMatchingParen();
      return false;
    }
    Advance();  // '('
    out->kind = Datum::Kind::kList;
    bool ok = true;
    while (true) {
      SkipSpaceAndComments();
      if (AtEnd()) {
        Error(line, column, "unclosed '(': the text ends before its ')'");
        return false;
      }
      if (Peek() == ')') {
        Advance();
        return ok;
      }
      Datum item;
      if (ReadDatum(&item, depth + 1)) {
        out->items.push_back(std::move(item));
      } else {
        ok = false;
        if (AtEnd()) return false;
      }
    }
  }

  // After a too-deep list: skip to the ')' that closes the current '(' (or the end).
  void SkipToMatchingParen() {
    int open = 0;
    while (!AtEnd()) {
      const char c = Peek();
      if (c == '"') {
        Datum ignored;
        ReadString(&ignored);
        continue;
      }
      if (c == ';') {
        SkipSpaceAndComments();
        continue;
      }
      Advance();
      if (c == '(') ++open;
      if (c == ')' && --open == 0) return;
    }
  }

  bool ReadString(Datum* out) {
    const int line = line_, column = column_;
    Advance();  // '"'
    out->kind = Datum::Kind::kString;
    bool ok = true;
    while (true) {
      if (AtEnd()) {
        Error(line, column, "unterminated string: no closing '\"'");
        return false;
      }
      char c = Peek();
      if (c == '"') {
        Advance();
        return ok;
      }
      if (c == '\\') {
        const int escape_line = line_, escape_column = column_;
        Advance();
        if (AtEnd()) continue;
        const char e = Peek();
        Advance();
        if (e == '"' || e == '\\') {
          out->text += e;
        } else if (e == 'n') {
          out->text += '\n';
        } else {
          Error(escape_line, escape_column,
                std::string("unknown escape '\\") +
                    (std::isprint(static_cast<unsigned char>(e)) ? std::string(1, e)
                                                                 : std::string("?")) +
                    "' in a string (use \\\", \\\\ or \\n)");
          ok = false;
        }
        continue;
      }
      out->text += c;
      Advance();
    }
  }

  bool ReadAtom(Datum* out) {
    const int line = line_, column = column_;
    std::string atom;
    bool bad = false;
    int bad_column = 0;
    unsigned char bad_char = 0;
    while (!AtEnd() && !IsDelimiter(Peek())) {
      const char c = Peek();
      const unsigned char u = static_cast<unsigned char>(c);
      if (!bad && !(std::isalnum(u) || IsSymbolPunctuation(c))) {
        bad = true;
        bad_column = column_;
        bad_char = u;
      }
      atom += c;
      Advance();
    }
    if (atom.empty()) {  // cannot happen: callers skip spaces and handle delimiters
      Advance();
      return false;
    }
    if (bad) {
      char what[64];
      if (bad_char >= 33 && bad_char <= 126) {
        std::snprintf(what, sizeof what, "'%c'", bad_char);
      } else {
        std::snprintf(what, sizeof what, "byte 0x%02X", bad_char);
      }
      Error(line, bad_column,
            std::string("unexpected character ") + what +
                " (symbols are letters, digits and - * + / < > = ? ! & % $ : _ . ~ ^ @)");
      return false;
    }
    if (LooksNumeric(atom)) {
      if (!spott_text::IsNumberSyntax(atom)) {
        Error(line, column, "malformed number '" + atom + "'");
        return false;
      }
      errno = 0;
      const double x = std::strtod(atom.c_str(), nullptr);
      if (errno == ERANGE && std::isinf(x)) {
        Error(line, column, "number '" + atom + "' is out of range");
        return false;
      }
      out->kind = Datum::Kind::kNumber;
      out->number = x;
      return true;
    }
    std::string name;
    name.reserve(atom.size());
    for (char c : atom) name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (name.find(':', 1) != std::string::npos) {
      Error(line, column,
            "symbol '" + name +
                "' has a ':' inside (only keywords start with ':'; there are no packages)");
      return false;
    }
    if (name == ":") {
      Error(line, column, "a keyword needs a name after ':'");
      return false;
    }
    out->kind = Datum::Kind::kSymbol;
    out->text = std::move(name);
    return true;
  }

  const std::string& text_;
  const std::string& file_;
  size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
  std::vector<Diagnostic> diagnostics_;
};

void Print(const Datum& d, std::string* out) {
  switch (d.kind) {
    case Datum::Kind::kNumber:
      *out += Value::Number(d.number).ToString();
      return;
    case Datum::Kind::kString:
      *out += Value::String(d.text).ToString();
      return;
    case Datum::Kind::kSymbol:
      *out += d.text;
      return;
    case Datum::Kind::kList:
      *out += '(';
      for (size_t i = 0; i < d.items.size(); ++i) {
        if (i) *out += ' ';
        Print(d.items[i], out);
      }
      *out += ')';
      return;
  }
}

}  // namespace

ReadResult ReadPlanText(const std::string& text, const std::string& file) {
  return Reader(text, file).Run();
}

std::string PrintDatum(const Datum& datum) {
  std::string out;
  Print(datum, &out);
  return out;
}

}  // namespace rpl
}  // namespace rpl_executive
