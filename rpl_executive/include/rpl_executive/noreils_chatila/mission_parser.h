// Parser of Noreils-Chatila mission files (section 5; README "Mission files"). Errors name
// the file, line and column and what was expected; the parser goes on with the next form so
// one run reports every error it can. Names are not resolved here: that is the checker's job
// (checker.h), which also knows the operators and conditions.
#pragma once

#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/diagnostic.h"
#include "rpl_executive/noreils_chatila/mission.h"

namespace rpl_executive::noreils_chatila {

struct ParseResult {
  MissionFile file;  ///< Whatever was parsed; complete only when ok().
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return !HasErrors(diagnostics); }
};

/// Parses mission text; `file` names it in diagnostics.
ParseResult ParseMissionText(const std::string& text, const std::string& file = "<input>");

/// Reads and parses a file; a file that cannot be read is an error located at the file.
ParseResult ParseMissionFile(const std::string& path);

}  // namespace rpl_executive::noreils_chatila
