#include <cstdlib>

#include "spott_tr_plus/value.h"

namespace spott_tr_plus {

namespace {

bool ParseNumber(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

std::string Trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

}  // namespace

Value ValueFromText(const std::string& raw) {
  const std::string s = Trim(raw);
  if (s.empty() || s == "nil") return Value{};
  if (s == "true") return true;
  if (s == "false") return false;
  double d;
  if (ParseNumber(s, d)) return d;
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') {
    std::string out;
    for (size_t i = 1; i + 1 < s.size(); ++i) {
      if (s[i] == '\\' && i + 2 < s.size()) {
        ++i;
        out += s[i] == 'n' ? '\n' : s[i];
      } else {
        out += s[i];
      }
    }
    return out;
  }
  if (s.size() >= 2 && s.front() == '[' && s.back() == ']') {
    std::vector<double> v;
    std::string inner = s.substr(1, s.size() - 2);
    size_t start = 0;
    while (!Trim(inner).empty() && start <= inner.size()) {
      const size_t comma = inner.find(',', start);
      const std::string item =
          Trim(inner.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (!ParseNumber(item, d)) return s;  // not a vector of numbers: keep the text
      v.push_back(d);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    return v;
  }
  return s;
}

}  // namespace spott_tr_plus
