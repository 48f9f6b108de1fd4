#include "spott_tr_plus/dot_export.h"

#include <sstream>

namespace spott_tr_plus {

namespace {

bool IsTrue(const DotLiveState* live, size_t i) {
  return live && i < live->rule_values.size() && live->rule_values[i];
}

// The nodes and arcs of one program's tree, with ids prefixed by `prefix`.
void TreeBody(std::ostringstream& out, const Program& p, const std::vector<int>& parent,
              const DotLiveState* live, const std::string& prefix, const std::string& indent) {
  // The placeholder the top condition's arc attaches to (the paper's subroutines have one).
  out << indent << prefix << "top [shape=point, width=0.12];\n";
  for (size_t i = 0; i < p.rules.size(); ++i) {
    out << indent << prefix << "K" << i + 1 << " [label=\"K" << i + 1 << ": "
        << DotEscape(ToText(p.rules[i].condition)) << "\"";
    if (IsTrue(live, i)) out << ", style=filled, fillcolor=\"gray75\"";
    out << "];\n";
  }
  for (size_t i = 0; i < p.rules.size(); ++i) {
    const int to = i < parent.size() ? parent[i] : static_cast<int>(i) - 1;
    const std::string target = to < 0 ? prefix + "top" : prefix + "K" + std::to_string(to + 1);
    out << indent << prefix << "K" << i + 1 << " -> " << target << " [label=\"a" << i + 1 << ": "
        << DotEscape(ToText(p.rules[i].action)) << "\"";
    if (live && live->firing_rule == static_cast<int>(i)) {
      out << ", color=red, fontcolor=red, penwidth=3";
    }
    out << "];\n";
  }
}

}  // namespace

std::string DotEscape(const std::string& text) {
  std::string s;
  for (char c : text) {
    if (c == '"' || c == '\\') s += '\\';
    if (c == '\n') {
      s += "\\n";
      continue;
    }
    s += c;
  }
  return s;
}

std::string TrTreeDot(const Program& program, const std::vector<int>& parent,
                      const DotLiveState* live) {
  std::ostringstream out;
  out << "digraph \"" << DotEscape(program.name) << "\" {\n"
      << "  rankdir=BT;\n  node [shape=ellipse, fontname=\"Helvetica\"];\n"
      << "  edge [fontname=\"Helvetica\", fontsize=10];\n"
      << "  label=\"" << DotEscape(program.name) << "\"; labelloc=t;\n";
  TreeBody(out, program, parent, live, "", "  ");
  out << "}\n";
  return out.str();
}

std::string TrSequenceDot(const Program& program, const DotLiveState* live) {
  std::ostringstream out;
  out << "digraph \"" << DotEscape(program.name) << "_sequence\" {\n"
      << "  rankdir=TB;\n  node [fontname=\"Helvetica\"];\n"
      << "  edge [fontname=\"Helvetica\", fontsize=10];\n"
      << "  label=\"" << DotEscape(program.name) << " (TR sequence)\"; labelloc=t;\n";
  const size_t m = program.rules.size();
  for (size_t i = 0; i < m; ++i) {
    out << "  K" << i + 1 << " [shape=ellipse, label=\"K" << i + 1 << ": "
        << DotEscape(ToText(program.rules[i].condition)) << "\"";
    if (IsTrue(live, i)) out << ", style=filled, fillcolor=\"gray75\"";
    out << "];\n";
    out << "  a" << i + 1 << " [shape=box, label=\"a" << i + 1 << ": "
        << DotEscape(ToText(program.rules[i].action)) << "\"];\n";
    out << "  { rank=same; K" << i + 1 << "; a" << i + 1 << "; }\n";
    out << "  K" << i + 1 << " -> a" << i + 1 << " [label=\"true\"";
    if (live && live->firing_rule == static_cast<int>(i)) {
      out << ", color=red, fontcolor=red, penwidth=3";
    }
    out << "];\n";
    if (i + 1 < m)
      out << "  K" << i + 1 << " -> K" << i + 2 << " [label=\"false\", style=dashed];\n";
  }
  out << "}\n";
  return out.str();
}

std::string ProgramFileDot(const ProgramFile& file, const CheckReport& report) {
  std::ostringstream out;
  out << "digraph \"" << DotEscape(file.file) << "\" {\n"
      << "  rankdir=BT;\n  compound=true;\n  node [shape=ellipse, fontname=\"Helvetica\"];\n"
      << "  edge [fontname=\"Helvetica\", fontsize=10];\n";
  for (size_t k = 0; k < file.programs.size(); ++k) {
    const Program& p = file.programs[k];
    const ProgramVerdict* v = report.Find(p.name);
    std::vector<int> parent;
    if (v) parent = v->parent;
    out << "  subgraph \"cluster_" << DotEscape(p.name) << "\" {\n"
        << "    label=\"" << DotEscape(p.name) << (v ? " (" + v->Verdict() + ")" : "") << "\";\n";
    TreeBody(out, p, parent, nullptr, "p" + std::to_string(k) + "_", "    ");
    out << "  }\n";
  }
  out << "}\n";
  return out.str();
}

}  // namespace spott_tr_plus
