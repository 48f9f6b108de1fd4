#include "rpl_executive/rpl/source.h"

namespace rpl_executive {
namespace rpl {

std::string SourceLocation::ToString() const {
  return spott_text::LocationText(file.empty() ? std::string("<plan>") : file, {line, column});
}

}  // namespace rpl
}  // namespace rpl_executive
