// Tokens of the TR+ text format and of task commands (internal to spott_tr_plus).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "spott_tr_plus/diagnostic.h"

namespace spott_tr_plus {
namespace internal {

enum class Tok {
  kEnd,
  kIdent,    ///< Letters, digits, '_' and (when allowed) '-', starting with a letter or '_'.
  kNumber,   ///< Unsigned decimal; `unit` holds letters that follow it at once ("0.5s").
  kString,   ///< "..." with \" \\ \n escapes; `text` holds the unescaped value.
  kArrow,    ///< ->
  kBarBar,   ///< ||
  kBar,      ///< |
  kAmp,      ///< &
  kCaret,    ///< ^
  kGreater,  ///< >
  kMinus,    ///< -
  kLParen,
  kRParen,
  kLBrace,
  kRBrace,
  kLBracket,
  kRBracket,
  kComma,
  kSemicolon,
  kEquals,
  kError,  ///< A character no token starts with, or an unterminated string.
};

struct Token {
  Tok kind = Tok::kEnd;
  std::string_view lexeme;  ///< Into the source text.
  std::string text;         ///< kString: the value; kError: what went wrong.
  std::string_view unit;    ///< kNumber: an attached unit ("s", "ms", ...), else empty.
  double number = 0.0;
  Location where;
};

/// Splits `source` into tokens, ending with kEnd. `#` and `//` start comments to the end of the
/// line. With `hyphen_words`, '-' inside a word belongs to it ("to-the-left-of").
std::vector<Token> Tokenize(std::string_view source, bool hyphen_words);

/// "end of input", "'{'", "identifier 'foo'", "number 3", ... for "expected X, found Y".
std::string Describe(const Token& t);

}  // namespace internal
}  // namespace spott_tr_plus
