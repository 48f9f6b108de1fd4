// Parser of the TR+ text format (README "The TR+ language"). Errors name the file, line and
// column and what was expected; the parser recovers at the next `;` or declaration so one run
// reports every error it can.
#pragma once

#include <string>
#include <vector>

#include "spott_tr_plus/ast.h"
#include "spott_tr_plus/diagnostic.h"

namespace spott_tr_plus {

struct ParseResult {
  ProgramFile program;  ///< Whatever was parsed; complete only when ok().
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return !HasErrors(diagnostics); }
};

/// Parses TR+ program text. `file` names it in diagnostics. Subroutine calls are resolved
/// (ActExpr::is_call) but names are not checked: that is the checker's job (checker.h).
ParseResult ParseProgramText(const std::string& text, const std::string& file = "<input>");

/// Reads and parses a file; a file that cannot be read is an error located at the file.
ParseResult ParseProgramFile(const std::string& path);

}  // namespace spott_tr_plus
