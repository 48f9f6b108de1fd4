#include "spott_map/yaml_reader.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace spott_map {

namespace {

std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

const char* KindName(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map:
      return "a mapping";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Scalar:
      return "a scalar";
    case YAML::NodeType::Null:
      return "nothing";
    case YAML::NodeType::Undefined:
      break;
  }
  return "nothing";
}

// Deepest bracket/indentation nesting of flow collections, a cheap guard against inputs that
// would exhaust the stack of yaml-cpp's recursive-descent parser.
int FlowNestingDepth(const std::string& text) {
  int depth = 0;
  int deepest = 0;
  for (char c : text) {
    if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
    if ((c == ']' || c == '}') && depth > 0) --depth;
  }
  return deepest;
}

}  // namespace

std::optional<std::string> ClosestWord(const std::string& word,
                                       std::initializer_list<const char*> candidates) {
  std::optional<std::string> best;
  std::size_t best_distance = 0;
  for (const char* c : candidates) {
    const std::size_t d = EditDistance(word, c);
    if (!best || d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  if (best && best_distance <= std::max<std::size_t>(2, word.size() / 3)) return best;
  return std::nullopt;
}

YAML::Node YamlReader::Parse(const std::string& text, int max_depth) {
  if (FlowNestingDepth(text) > max_depth) {
    Error(SourceLocation{file_, 1, 1},
          "lists or mappings nested deeper than " + std::to_string(max_depth) + " levels");
    return YAML::Node();
  }
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    SourceLocation where{file_, e.mark.is_null() ? 0 : e.mark.line + 1,
                         e.mark.is_null() ? 0 : e.mark.column + 1};
    Error(where, "YAML syntax error: " + e.msg);
  }
  return YAML::Node();
}

SourceLocation YamlReader::Where(const YAML::Node& node) const {
  if (!node.IsDefined()) return SourceLocation{file_, 0, 0};
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return SourceLocation{file_, 0, 0};
  return SourceLocation{file_, mark.line + 1, mark.column + 1};
}

void YamlReader::Error(const YAML::Node& node, const std::string& message) {
  errors_.push_back(SourceError{Where(node), message});
}

void YamlReader::Error(const SourceLocation& where, const std::string& message) {
  errors_.push_back(SourceError{where, message});
}

void YamlReader::Warning(const YAML::Node& node, const std::string& message) {
  warnings_.push_back(SourceError{Where(node), message});
}

bool YamlReader::ExpectMap(const YAML::Node& node, const std::string& what,
                           std::initializer_list<const char*> allowed) {
  if (!node.IsMap()) {
    Error(node, what + ": expected a mapping, got " + KindName(node));
    return false;
  }
  std::set<std::string> seen;
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (!it->first.IsScalar()) {
      Error(it->first, what + ": keys must be plain words");
      continue;
    }
    const std::string key = it->first.Scalar();
    if (!seen.insert(key).second) {
      Error(it->first, what + ": duplicate key '" + key + "'");
      continue;
    }
    const bool known =
        std::any_of(allowed.begin(), allowed.end(), [&key](const char* a) { return key == a; });
    if (!known) {
      std::string message = what + ": unknown key '" + key + "'";
      if (auto hint = ClosestWord(key, allowed)) message += " (did you mean '" + *hint + "'?)";
      std::string list;
      for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
      message += "; allowed keys: " + list;
      Error(it->first, message);
    }
  }
  return true;
}

bool YamlReader::ExpectSequence(const YAML::Node& node, const std::string& what) {
  if (!node.IsSequence()) {
    Error(node, what + ": expected a list, got " + KindName(node));
    return false;
  }
  return true;
}

bool YamlReader::Require(const YAML::Node& map, const char* key, const std::string& what) {
  if (map[key]) return true;
  Error(map, what + ": missing required key '" + std::string(key) + "'");
  return false;
}

std::optional<std::string> YamlReader::String(const YAML::Node& map, const char* key,
                                              const std::string& what, bool required) {
  const YAML::Node node = map[key];
  if (!node) {
    if (required) Require(map, key, what);
    return std::nullopt;
  }
  if (!node.IsScalar()) {
    Error(node, what + ": " + key + ": expected a word or text, got " + KindName(node));
    return std::nullopt;
  }
  return node.Scalar();
}

std::optional<double> YamlReader::ScalarNumber(const YAML::Node& node, const std::string& what,
                                               NumberRule rule) {
  if (!node.IsScalar()) {
    Error(node, what + ": expected a number, got " + KindName(node));
    return std::nullopt;
  }
  double value = 0.0;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    Error(node, what + ": expected a number, got '" + node.Scalar() + "'");
    return std::nullopt;
  }
  if (!std::isfinite(value)) {
    Error(node, what + ": must be a finite number, got '" + node.Scalar() + "'");
    return std::nullopt;
  }
  if (rule == NumberRule::kPositive && !(value > 0.0)) {
    Error(node, what + ": must be greater than 0, got " + node.Scalar());
    return std::nullopt;
  }
  if (rule == NumberRule::kNonNegative && value < 0.0) {
    Error(node, what + ": must not be negative, got " + node.Scalar());
    return std::nullopt;
  }
  return value;
}

std::optional<double> YamlReader::Number(const YAML::Node& map, const char* key,
                                         const std::string& what, bool required, NumberRule rule) {
  const YAML::Node node = map[key];
  if (!node) {
    if (required) Require(map, key, what);
    return std::nullopt;
  }
  return ScalarNumber(node, what + ": " + key, rule);
}

std::optional<bool> YamlReader::Bool(const YAML::Node& map, const char* key,
                                     const std::string& what, bool required) {
  const YAML::Node node = map[key];
  if (!node) {
    if (required) Require(map, key, what);
    return std::nullopt;
  }
  bool value = false;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value)) {
    Error(node, what + ": " + key + ": expected true or false");
    return std::nullopt;
  }
  return value;
}

std::optional<std::vector<double>> YamlReader::Numbers(const YAML::Node& map, const char* key,
                                                       const std::string& what, bool required,
                                                       std::size_t count, NumberRule rule) {
  const YAML::Node node = map[key];
  if (!node) {
    if (required) Require(map, key, what);
    return std::nullopt;
  }
  const std::string label = what + ": " + key;
  if (!node.IsSequence() || node.size() != count) {
    Error(node, label + ": expected a list of " + std::to_string(count) + " numbers");
    return std::nullopt;
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < count; ++i) {
    auto v = ScalarNumber(node[i], label + "[" + std::to_string(i) + "]", rule);
    if (!v) return std::nullopt;
    values.push_back(*v);
  }
  return values;
}

std::optional<Vec2> YamlReader::Point(const YAML::Node& map, const char* key,
                                      const std::string& what, bool required) {
  auto v = Numbers(map, key, what, required, 2, NumberRule::kAny);
  if (!v) return std::nullopt;
  return Vec2((*v)[0], (*v)[1]);
}

std::optional<Pose2> YamlReader::Pose(const YAML::Node& map, const char* key,
                                      const std::string& what, bool required) {
  auto v = Numbers(map, key, what, required, 3, NumberRule::kAny);
  if (!v) return std::nullopt;
  return Pose2{(*v)[0], (*v)[1], (*v)[2]};
}

std::optional<Polygon> YamlReader::Points(const YAML::Node& map, const char* key,
                                          const std::string& what, bool required,
                                          std::size_t min_points) {
  const YAML::Node node = map[key];
  if (!node) {
    if (required) Require(map, key, what);
    return std::nullopt;
  }
  const std::string label = what + ": " + key;
  if (!node.IsSequence()) {
    Error(node, label + ": expected a list of [x, y] points, got " + KindName(node));
    return std::nullopt;
  }
  if (node.size() < min_points) {
    Error(node, label + ": needs at least " + std::to_string(min_points) + " points, got " +
                    std::to_string(node.size()));
    return std::nullopt;
  }
  Polygon points;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node p = node[i];
    const std::string item = label + "[" + std::to_string(i) + "]";
    if (!p.IsSequence() || p.size() != 2) {
      Error(p, item + ": expected a point [x, y]");
      return std::nullopt;
    }
    auto x = ScalarNumber(p[0], item + ".x", NumberRule::kAny);
    auto y = ScalarNumber(p[1], item + ".y", NumberRule::kAny);
    if (!x || !y) return std::nullopt;
    points.emplace_back(*x, *y);
  }
  return points;
}

}  // namespace spott_map
