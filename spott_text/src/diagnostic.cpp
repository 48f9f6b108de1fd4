#include "spott_text/diagnostic.h"

namespace spott_text {

std::string LocationText(const std::string& file, Location where) {
  std::string out = file.empty() ? std::string("<input>") : file;
  if (where.line > 0) {
    out += ':' + std::to_string(where.line);
    if (where.column > 0) out += ':' + std::to_string(where.column);
  }
  return out;
}

std::string Diagnostic::ToString() const {
  return LocationText(file, where) + ": " + (IsError() ? "" : "warning: ") + message;
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

}  // namespace spott_text
