#include "spott_map/pose_text.h"

#include <cmath>
#include <cstdlib>

namespace spott_map {

namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

std::optional<Pose2> ParsePoseText(const std::string& text, std::string* error) {
  const auto fail = [&](const std::string& why) -> std::optional<Pose2> {
    if (error) *error = "expected 'x y yaw' (three numbers: m, m, rad), got '" + text + "': " + why;
    return std::nullopt;
  };
  // c_str() is terminated, so strtod stops at the end; an embedded NUL ends it early (below).
  const char* const begin = text.c_str();
  const char* p = begin;
  double values[3];
  for (int i = 0; i < 3; ++i) {
    while (IsSpace(*p)) ++p;
    if (*p == '\0') return fail("only " + std::to_string(i) + " of 3 numbers");
    char* end = nullptr;
    values[i] = std::strtod(p, &end);
    if (end == p || (*end != '\0' && !IsSpace(*end)))
      return fail("number " + std::to_string(i + 1) + " at column " +
                  std::to_string(p - begin + 1) + " is not a number");
    if (!std::isfinite(values[i]))
      return fail("number " + std::to_string(i + 1) + " is not finite");
    p = end;
  }
  while (IsSpace(*p)) ++p;
  if (*p != '\0') return fail("text after the yaw at column " + std::to_string(p - begin + 1));
  if (p != begin + text.size()) return fail("a NUL character in the text");
  return Pose2{values[0], values[1], values[2]};
}

}  // namespace spott_map
