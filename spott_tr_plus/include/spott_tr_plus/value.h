// Values that condition processes output and actions take as arguments (SPOTT III.C.1: "the
// process can also return other (logical or non-logical) values through variables attached to
// the condition").
#pragma once

#include <string>
#include <variant>
#include <vector>

namespace spott_tr_plus {

/// A value bound to a variable: nothing yet, a truth value, a number, a text, or a vector of
/// numbers (a position (m), a pose (m, m, rad), ...).
using Value = std::variant<std::monostate, bool, double, std::string, std::vector<double>>;

/// "nil", "true", "1.5", "\"text\"" or "[1, 2]": used in live states and interpretations.
std::string ValueToString(const Value& value);

}  // namespace spott_tr_plus

namespace spott_tr_plus {

/// The inverse of ValueToString: "nil", "true", "1.5", "\"text\"", "[1, 2]"; other text is taken
/// as a string value as it is.
Value ValueFromText(const std::string& text);

}  // namespace spott_tr_plus
