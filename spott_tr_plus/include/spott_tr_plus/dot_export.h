// DOT export of TR+ programs, drawn as the SPOTT paper draws them (Fig. 2, Figs. 3-13; the
// paper used Dotty): a TR tree, where conditions are nodes and actions are arcs from a rule's
// condition to the condition its action achieves (its regression parent; the rule just above
// when no effects are declared), and a TR sequence, where the rules are chained in the order the
// interpreter evaluates them. True conditions are shaded and the firing arc is drawn bold red.
#pragma once

#include <string>
#include <vector>

#include "spott_tr_plus/ast.h"
#include "spott_tr_plus/checker.h"

namespace spott_tr_plus {

/// What to highlight: the value of each rule's condition and the firing rule (-1: none).
struct DotLiveState {
  std::vector<bool> rule_values;
  int firing_rule = -1;
};

/// The TR tree of one program as a DOT digraph. `parent[i]` is rule i's arc target (from
/// ProgramVerdict::parent; -1 for the top rule). `live` may be null.
std::string TrTreeDot(const Program& program, const std::vector<int>& parent,
                      const DotLiveState* live = nullptr);

/// The TR sequence of one program (Fig. 2(b)): K1 else K2 else ... with each rule's action.
std::string TrSequenceDot(const Program& program, const DotLiveState* live = nullptr);

/// Every program of a checked file as TR trees, one cluster per program, in one digraph.
std::string ProgramFileDot(const ProgramFile& file, const CheckReport& report);

/// Escapes text for a double-quoted DOT string.
std::string DotEscape(const std::string& text);

}  // namespace spott_tr_plus
