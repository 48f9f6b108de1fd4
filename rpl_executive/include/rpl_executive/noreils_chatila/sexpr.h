// The reader of mission text: S-expressions with the paper's three brackets, ( ) for forms,
// { } for control actions (Example 2) and [ ] for sizes (Tclist[4]). Each node keeps where it
// starts in the file. The mission parser (mission_parser.h) gives the nodes their meaning.
//
// Lexical rules (README "Mission files"): `;` starts a comment to the end of the line; commas
// are separators like blanks (the paper prints "(ρ, θ)"); a token that reads fully as a decimal
// number is a number, anything else a symbol (UTF-8 letters such as ρ, θ, φ included).
#pragma once

#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/diagnostic.h"

namespace rpl_executive::noreils_chatila {

struct Sexpr {
  enum class Kind { kSymbol, kNumber, kParen, kBrace, kBracket };
  Kind kind = Kind::kSymbol;
  std::string text;  ///< kSymbol: the symbol; kNumber: the number as written.
  double number = 0.0;
  std::vector<Sexpr> items;  ///< kParen, kBrace, kBracket.
  Location where;            ///< Where the token or opening bracket is.

  bool IsSymbol() const { return kind == Kind::kSymbol; }
  bool IsList() const { return kind == Kind::kParen; }
  /// A symbol equal to `keyword` ignoring ASCII case (MNTR, mntr).
  bool IsKeyword(const char* keyword) const;
  /// The node printed back as text (canonical spacing).
  std::string ToText() const;
};

struct ReadResult {
  std::vector<Sexpr> forms;
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return !HasErrors(diagnostics); }
};

/// Nesting deeper than this is an error (keeps hostile input from exhausting the stack).
constexpr int kMaxSexprDepth = 200;

/// Reads every top-level form of `text`; `file` names it in diagnostics.
ReadResult ReadSexprs(const std::string& text, const std::string& file);

/// Case-insensitive ASCII comparison.
bool EqualsIgnoreCase(const std::string& a, const char* b);

}  // namespace rpl_executive::noreils_chatila
