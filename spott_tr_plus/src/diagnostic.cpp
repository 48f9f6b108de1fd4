#include "spott_tr_plus/diagnostic.h"

#include <sstream>

namespace spott_tr_plus {

std::string Diagnostic::ToString() const {
  std::ostringstream out;
  out << (file.empty() ? "<input>" : file);
  if (where.line > 0) {
    out << ':' << where.line;
    if (where.column > 0) out << ':' << where.column;
  }
  out << ": " << (IsError() ? "" : "warning: ") << message;
  return out.str();
}

std::string FormatDiagnostics(const std::vector<Diagnostic>& diagnostics) {
  std::string text;
  for (const Diagnostic& d : diagnostics) {
    if (!text.empty()) text += '\n';
    text += d.ToString();
  }
  return text;
}

bool HasErrors(const std::vector<Diagnostic>& diagnostics) {
  for (const Diagnostic& d : diagnostics) {
    if (d.IsError()) return true;
  }
  return false;
}

}  // namespace spott_tr_plus
