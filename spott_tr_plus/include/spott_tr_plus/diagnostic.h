// Errors and warnings about a user's TR+ program or task command, located by file, line, column.
#pragma once

#include <string>
#include <vector>

namespace spott_tr_plus {

/// A position in a text; line and column are 1-based (0 = unknown).
struct Location {
  int line = 0;
  int column = 0;
};

/// One error or warning: "file:line:column: [warning: ]message".
struct Diagnostic {
  enum class Severity { kError, kWarning };
  Severity severity = Severity::kError;
  std::string file;
  Location where;
  std::string message;

  bool IsError() const { return severity == Severity::kError; }
  std::string ToString() const;
};

/// Joins diagnostics one per line.
std::string FormatDiagnostics(const std::vector<Diagnostic>& diagnostics);

/// True when any of the diagnostics is an error.
bool HasErrors(const std::vector<Diagnostic>& diagnostics);

}  // namespace spott_tr_plus
