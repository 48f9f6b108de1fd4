#include "rpl_executive/noreils_chatila/sexpr.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "spott_text/lexemes.h"

namespace rpl_executive::noreils_chatila {

bool EqualsIgnoreCase(const std::string& a, const char* b) {
  const size_t n = std::strlen(b);
  if (a.size() != n) return false;
  for (size_t i = 0; i < n; ++i) {
    if (std::toupper(static_cast<unsigned char>(a[i])) !=
        std::toupper(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
}

bool Sexpr::IsKeyword(const char* keyword) const {
  return kind == Kind::kSymbol && EqualsIgnoreCase(text, keyword);
}

std::string Sexpr::ToText() const {
  switch (kind) {
    case Kind::kSymbol:
    case Kind::kNumber:
      return text;
    case Kind::kParen:
    case Kind::kBrace:
    case Kind::kBracket: {
      const char open = kind == Kind::kParen ? '(' : kind == Kind::kBrace ? '{' : '[';
      const char close = kind == Kind::kParen ? ')' : kind == Kind::kBrace ? '}' : ']';
      std::string out(1, open);
      for (size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += ' ';
        out += items[i].ToText();
      }
      out += close;
      return out;
    }
  }
  return text;
}

namespace {

bool IsDelimiter(char c) {
  return c == '(' || c == ')' || c == '{' || c == '}' || c == '[' || c == ']' || c == ',' ||
         c == ';' || c == '"' || std::isspace(static_cast<unsigned char>(c));
}

class Reader {
 public:
  Reader(const std::string& text, const std::string& file) : text_(text), file_(file) {}

  ReadResult Run() {
    ReadResult result;
    while (true) {
      SkipBlanks();
      if (AtEnd()) break;
      const char c = text_[pos_];
      if (c == ')' || c == '}' || c == ']') {
        Error(Here(), std::string("unexpected '") + c + "' with no opening bracket");
        Advance();
        continue;
      }
      Sexpr form;
      if (ReadOne(&form, 0)) result.forms.push_back(std::move(form));
    }
    result.diagnostics = std::move(diagnostics_);
    return result;
  }

 private:
  bool AtEnd() const { return pos_ >= text_.size(); }
  Location Here() const { return Location{line_, column_}; }

  void Advance() {
    const unsigned char c = static_cast<unsigned char>(text_[pos_]);
    ++pos_;
    if (c == '\n') {
      ++line_;
      column_ = 1;
    } else if ((c & 0xC0) != 0x80) {
      ++column_;  // an ASCII or UTF-8 lead byte; continuation bytes do not move the column
    }
  }

  void SkipBlanks() {
    while (!AtEnd()) {
      const char c = text_[pos_];
      if (c == ';') {
        while (!AtEnd() && text_[pos_] != '\n') Advance();
      } else if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
        Advance();
      } else {
        break;
      }
    }
  }

  void Error(Location where, std::string message) {
    Diagnostic d;
    d.file = file_;
    d.where = where;
    d.message = std::move(message);
    diagnostics_.push_back(std::move(d));
  }

  // Reads one node at pos_ (blanks skipped). Returns false when nothing usable was read.
  bool ReadOne(Sexpr* out, int depth) {
    const Location start = Here();
    const char c = text_[pos_];
    if (c == '(' || c == '{' || c == '[') {
      if (depth >= kMaxSexprDepth) {
        Error(start, "brackets nested deeper than " + std::to_string(kMaxSexprDepth));
        SkipToEnd();
        return false;
      }
      const char close = c == '(' ? ')' : c == '{' ? '}' : ']';
      out->kind = c == '('   ? Sexpr::Kind::kParen
                  : c == '{' ? Sexpr::Kind::kBrace
                             : Sexpr::Kind::kBracket;
      out->where = start;
      Advance();
      while (true) {
        SkipBlanks();
        if (AtEnd()) {
          Error(start, std::string("'") + c + "' is never closed (expected '" + close +
                           "' before the end of the file)");
          return true;  // keep what was read: the parser reports what it can
        }
        const char d = text_[pos_];
        if (d == close) {
          Advance();
          return true;
        }
        if (d == ')' || d == '}' || d == ']') {
          Error(Here(), std::string("'") + d + "' closes '" + c + "' opened at " +
                            std::to_string(start.line) + ":" + std::to_string(start.column) +
                            " (expected '" + close + "')");
          Advance();
          return true;
        }
        Sexpr item;
        if (ReadOne(&item, depth + 1)) out->items.push_back(std::move(item));
        if (giving_up_) return false;
      }
    }
    if (c == '"') {
      Error(start, "strings are not part of the mission language (found '\"')");
      Advance();
      while (!AtEnd() && text_[pos_] != '"' && text_[pos_] != '\n') Advance();
      if (!AtEnd() && text_[pos_] == '"') Advance();
      return false;
    }
    std::string token;
    while (!AtEnd() && !IsDelimiter(text_[pos_])) {
      token += text_[pos_];
      Advance();
    }
    out->where = start;
    out->text = token;
    if (spott_text::IsNumberSyntax(token)) {
      out->kind = Sexpr::Kind::kNumber;
      out->number = std::strtod(token.c_str(), nullptr);
      if (!std::isfinite(out->number)) {
        Error(start, "number '" + token + "' is out of range");
        return false;
      }
    } else {
      out->kind = Sexpr::Kind::kSymbol;
    }
    return true;
  }

  void SkipToEnd() {
    giving_up_ = true;
    while (!AtEnd()) Advance();
  }

  const std::string& text_;
  const std::string& file_;
  size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
  bool giving_up_ = false;
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace

ReadResult ReadSexprs(const std::string& text, const std::string& file) {
  return Reader(text, file).Run();
}

}  // namespace rpl_executive::noreils_chatila
