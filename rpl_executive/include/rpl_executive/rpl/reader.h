// The reader of the S-expression notation of RPL plans ("RPL programs look very much like LISP
// programs", Beetz et al. section 3): numbers, strings, symbols (folded to upper case), lists,
// 'x for (QUOTE x), ; line comments and #| block comments |#. Every datum keeps its line and
// column; every error names file, line and column.
#pragma once

#include <string>
#include <vector>

#include "rpl_executive/rpl/source.h"

namespace rpl_executive {
namespace rpl {

/// One S-expression as read, with where it starts.
struct Datum {
  enum class Kind { kNumber, kString, kSymbol, kList };
  Kind kind = Kind::kList;
  double number = 0.0;       // kNumber
  std::string text;          // kString: the text; kSymbol: the upper-case name
  std::vector<Datum> items;  // kList
  int line = 0;
  int column = 0;

  bool IsSymbol() const { return kind == Kind::kSymbol; }
  bool IsSymbol(const char* name) const { return kind == Kind::kSymbol && text == name; }
  bool IsList() const { return kind == Kind::kList; }
  /// The operator of a non-empty list whose head is a symbol; "" otherwise.
  const std::string& Head() const;
};

/// The deepest list nesting the reader accepts (deeper input is an error, not a stack overflow).
constexpr int kMaxNestingDepth = 200;

struct ReadResult {
  std::vector<Datum> forms;  // the top-level data read (those before and after errors too)
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return !HasErrors(diagnostics); }
};

/// Reads every top-level datum of `text`; `file` names it in diagnostics.
ReadResult ReadPlanText(const std::string& text, const std::string& file);

/// Prints a datum so that ReadPlanText reads it back to the same datum (locations aside).
std::string PrintDatum(const Datum& datum);

}  // namespace rpl
}  // namespace rpl_executive
