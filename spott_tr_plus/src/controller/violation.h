// The one wording of a parameter that breaks its rule, for the controller's validators.
#pragma once

#include <sstream>
#include <string>

namespace spott_tr_plus::controller {

inline std::string Violation(const std::string& name, const std::string& rule, double value) {
  std::ostringstream out;
  out << name << " must be " << rule << " (got " << value << ")";
  return out.str();
}

}  // namespace spott_tr_plus::controller
