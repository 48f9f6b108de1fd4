#include "lexer.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace spott_tr_plus {
namespace internal {

namespace {

bool IsIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool IsIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

}  // namespace

std::vector<Token> Tokenize(std::string_view s, bool hyphen_words) {
  std::vector<Token> tokens;
  tokens.reserve(s.size() / 3 + 2);
  size_t i = 0;
  int line = 1;
  size_t line_start = 0;
  auto here = [&](size_t at) { return Location{line, static_cast<int>(at - line_start) + 1}; };
  while (true) {
    // Whitespace and comments.
    while (i < s.size()) {
      const char c = s[i];
      if (c == '\n') {
        ++i;
        ++line;
        line_start = i;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++i;
      } else if (c == '#' || (c == '/' && i + 1 < s.size() && s[i + 1] == '/')) {
        while (i < s.size() && s[i] != '\n') ++i;
      } else {
        break;
      }
    }
    Token t;
    t.where = here(i);
    if (i >= s.size()) {
      t.kind = Tok::kEnd;
      tokens.push_back(std::move(t));
      return tokens;
    }
    const size_t start = i;
    const char c = s[i];
    if (IsIdentStart(c)) {
      while (i < s.size() && (IsIdentChar(s[i]) || (hyphen_words && s[i] == '-' &&
                                                    i + 1 < s.size() && IsIdentStart(s[i + 1])))) {
        ++i;
      }
      t.kind = Tok::kIdent;
    } else if (IsDigit(c) || (c == '.' && i + 1 < s.size() && IsDigit(s[i + 1]))) {
      while (i < s.size() && IsDigit(s[i])) ++i;
      if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && IsDigit(s[i])) ++i;
      }
      if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        size_t j = i + 1;
        if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
        if (j < s.size() && IsDigit(s[j])) {
          i = j;
          while (i < s.size() && IsDigit(s[i])) ++i;
        }
      }
      const std::string digits(s.substr(start, i - start));
      t.number = std::strtod(digits.c_str(), nullptr);
      t.kind = Tok::kNumber;
      if (!std::isfinite(t.number)) {
        // Found by task_command_fuzz: 0.2e09999 overflowed to inf, which prints as a name.
        t.kind = Tok::kError;
        t.text = "number " + digits + " is out of range";
      }
      const size_t unit_start = i;
      while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;
      t.unit = s.substr(unit_start, i - unit_start);
    } else if (c == '"') {
      ++i;
      bool closed = false;
      while (i < s.size()) {
        const char d = s[i];
        if (d == '"') {
          ++i;
          closed = true;
          break;
        }
        if (d == '\n') break;
        if (d == '\\' && i + 1 < s.size()) {
          const char e = s[i + 1];
          t.text += e == 'n' ? '\n' : e;
          i += 2;
          continue;
        }
        t.text += d;
        ++i;
      }
      if (closed) {
        t.kind = Tok::kString;
      } else {
        t.kind = Tok::kError;
        t.text = "unterminated string (a string ends with '\"' on the same line)";
      }
    } else {
      auto two = [&](char a, char b) { return c == a && i + 1 < s.size() && s[i + 1] == b; };
      if (two('-', '>')) {
        t.kind = Tok::kArrow;
        i += 2;
      } else if (two('|', '|')) {
        t.kind = Tok::kBarBar;
        i += 2;
      } else {
        ++i;
        switch (c) {
          case '|':
            t.kind = Tok::kBar;
            break;
          case '&':
            t.kind = Tok::kAmp;
            break;
          case '^':
            t.kind = Tok::kCaret;
            break;
          case '>':
            t.kind = Tok::kGreater;
            break;
          case '-':
            t.kind = Tok::kMinus;
            break;
          case '(':
            t.kind = Tok::kLParen;
            break;
          case ')':
            t.kind = Tok::kRParen;
            break;
          case '{':
            t.kind = Tok::kLBrace;
            break;
          case '}':
            t.kind = Tok::kRBrace;
            break;
          case '[':
            t.kind = Tok::kLBracket;
            break;
          case ']':
            t.kind = Tok::kRBracket;
            break;
          case ',':
            t.kind = Tok::kComma;
            break;
          case ';':
            t.kind = Tok::kSemicolon;
            break;
          case '=':
            t.kind = Tok::kEquals;
            break;
          default: {
            t.kind = Tok::kError;
            const unsigned char u = static_cast<unsigned char>(c);
            if (std::isprint(u)) {
              t.text = std::string("unexpected character '") + c + "'";
            } else {
              char buf[32];
              std::snprintf(buf, sizeof(buf), "unexpected byte 0x%02x", u);
              t.text = buf;
            }
          }
        }
      }
    }
    t.lexeme = s.substr(start, i - start);
    tokens.push_back(std::move(t));
  }
}

std::string Describe(const Token& t) {
  switch (t.kind) {
    case Tok::kEnd:
      return "end of input";
    case Tok::kIdent:
      return "'" + std::string(t.lexeme) + "'";
    case Tok::kNumber:
      return "number " + std::string(t.lexeme);
    case Tok::kString:
      return "string " + std::string(t.lexeme);
    case Tok::kError:
      return t.text;
    default:
      return "'" + std::string(t.lexeme) + "'";
  }
}

}  // namespace internal
}  // namespace spott_tr_plus
