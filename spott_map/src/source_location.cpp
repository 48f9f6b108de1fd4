#include "spott_map/source_location.h"

#include <sstream>

namespace spott_map {

std::string SourceError::ToString() const {
  std::ostringstream out;
  out << (where.file.empty() ? "<input>" : where.file);
  if (where.line > 0) {
    out << ':' << where.line;
    if (where.column > 0) out << ':' << where.column;
  }
  out << ": " << message;
  return out.str();
}

std::string FormatErrors(const std::vector<SourceError>& errors) {
  std::string text;
  for (const SourceError& e : errors) {
    if (!text.empty()) text += '\n';
    text += e.ToString();
  }
  return text;
}

}  // namespace spott_map
