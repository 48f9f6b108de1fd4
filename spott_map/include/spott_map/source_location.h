// Where something came from in a user's file, and errors that say so.
#pragma once

#include <string>
#include <vector>

namespace spott_map {

/// A position in a text file; line and column are 1-based (0 = unknown).
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

/// An error or warning about a user's file: "file:line:column: message".
struct SourceError {
  SourceLocation where;
  std::string message;
  std::string ToString() const;
};

/// Joins errors one per line.
std::string FormatErrors(const std::vector<SourceError>& errors);

}  // namespace spott_map
