// Errors and warnings about a user's mission file, located by file, line and column (columns
// count UTF-8 code points, so a line with "ρ" in it is counted as a reader sees it): the
// project's one diagnostic type (spott_text).
#pragma once

#include "spott_text/diagnostic.h"

namespace rpl_executive::noreils_chatila {

using spott_text::Diagnostic;
using spott_text::FormatDiagnostics;
using spott_text::HasErrors;
using spott_text::Location;
using spott_text::LocationText;

}  // namespace rpl_executive::noreils_chatila
