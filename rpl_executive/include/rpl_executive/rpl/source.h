// Where something is in a plan file, and errors that say so ("file:line:column: message"):
// the project's one diagnostic type (spott_text).
#pragma once

#include <string>

#include "spott_text/diagnostic.h"

namespace rpl_executive {
namespace rpl {

/// A position in a plan text; line and column are 1-based (0 = unknown). Columns count bytes.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
  std::string ToString() const;  // "file:line:column"
};

using spott_text::Diagnostic;
using spott_text::FormatDiagnostics;
using spott_text::HasErrors;

}  // namespace rpl
}  // namespace rpl_executive
