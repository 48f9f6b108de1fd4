// How the core's constructors refuse bad parameters: every violation (ValidateParameters' texts)
// in one std::invalid_argument, joined by "; ", so that a caller sees all of them at once.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace markov_localization {

inline void ThrowIfInvalid(const std::vector<std::string>& violations) {
  if (violations.empty()) return;
  std::string text;
  for (std::size_t i = 0; i < violations.size(); ++i) text += (i ? "; " : "") + violations[i];
  throw std::invalid_argument(text);
}

}  // namespace markov_localization
