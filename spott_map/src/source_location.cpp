#include "spott_map/source_location.h"

#include "spott_text/diagnostic.h"

namespace spott_map {

std::string SourceError::ToString() const {
  return spott_text::LocationText(where.file, {where.line, where.column}) + ": " + message;
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
