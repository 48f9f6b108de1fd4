#include "spott_text/lexemes.h"

#include <cctype>
#include <cstddef>

namespace spott_text {

bool IsNumberSyntax(const std::string& atom) {
  std::size_t i = 0;
  const std::size_t n = atom.size();
  const auto digits_from = [&](std::size_t* count) {
    while (i < n && std::isdigit(static_cast<unsigned char>(atom[i]))) ++i, ++*count;
  };
  if (i < n && (atom[i] == '+' || atom[i] == '-')) ++i;
  std::size_t mantissa = 0;
  digits_from(&mantissa);
  if (i < n && atom[i] == '.') {
    ++i;
    digits_from(&mantissa);
  }
  if (mantissa == 0) return false;  // ".", "+", "-." are symbols
  if (i < n && (atom[i] == 'e' || atom[i] == 'E')) {
    ++i;
    if (i < n && (atom[i] == '+' || atom[i] == '-')) ++i;
    std::size_t exponent = 0;
    digits_from(&exponent);
    if (exponent == 0) return false;  // "1e" is a symbol
  }
  return i == n;
}

std::string QuoteString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  out += '"';
  return out;
}

}  // namespace spott_text
