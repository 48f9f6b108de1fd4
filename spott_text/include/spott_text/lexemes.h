// The lexemes the project's readers agree on, so that "1e3" is a number and "\"a\\\"b\"" a
// string the same way in a TR+ program, an RPL plan and a mission file.
#pragma once

#include <string>

namespace spott_text {

/// True when all of `atom` is a decimal number:
/// [+-]? (digits (. digits*)? | . digits) ([eE] [+-]? digits)?
bool IsNumberSyntax(const std::string& atom);

/// `s` between double quotes with `"` and `\` escaped by a backslash and newlines as `\n`: the
/// form the readers read back to `s`.
std::string QuoteString(const std::string& s);

}  // namespace spott_text
