// Errors and warnings about a user's file (a TR+ program, a task command, an RPL plan, a
// mission), located by file, line and column: one type for every language of the project.
#pragma once

#include <string>
#include <vector>

namespace spott_text {

/// A position in a text; line and column are 1-based (0 = unknown). What a column counts
/// (bytes or UTF-8 code points) is the reader's to say.
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

/// "file:line:column", "file:line" when the column is unknown, "file" when the line is;
/// "<input>" stands for an unnamed file.
std::string LocationText(const std::string& file, Location where);

/// Joins diagnostics one per line (no newline after the last).
std::string FormatDiagnostics(const std::vector<Diagnostic>& diagnostics);

/// True when any of the diagnostics is an error.
bool HasErrors(const std::vector<Diagnostic>& diagnostics);

}  // namespace spott_text
