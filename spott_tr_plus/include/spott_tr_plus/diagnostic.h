// Errors and warnings about a user's TR+ program or task command, located by file, line and
// column: the project's one diagnostic type (spott_text).
#pragma once

#include "spott_text/diagnostic.h"

namespace spott_tr_plus {

using spott_text::Diagnostic;
using spott_text::FormatDiagnostics;
using spott_text::HasErrors;
using spott_text::Location;

}  // namespace spott_tr_plus
