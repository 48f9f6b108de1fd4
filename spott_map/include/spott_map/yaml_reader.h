// Strict reading of user YAML files (worlds, scenarios): every error carries the file, line and
// column and says what was expected. Unknown keys are errors (with a "did you mean" hint),
// duplicate keys are errors, numbers must be finite.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "spott_map/geometry.h"
#include "spott_map/source_location.h"
#include "spott_map/world.h"

namespace spott_map {

/// Limits a number read from a file must respect.
enum class NumberRule { kAny, kPositive, kNonNegative };

class YamlReader {
 public:
  /// `file` names the source in errors.
  explicit YamlReader(std::string file) : file_(std::move(file)) {}

  /// Parses `text`; on a syntax error records it and returns a null node. Rejects documents
  /// nested deeper than `max_depth` before handing them to yaml-cpp (which recurses).
  YAML::Node Parse(const std::string& text, int max_depth = 64);

  SourceLocation Where(const YAML::Node& node) const;
  void Error(const YAML::Node& node, const std::string& message);
  void Error(const SourceLocation& where, const std::string& message);
  void Warning(const YAML::Node& node, const std::string& message);

  /// Checks that `node` is a mapping whose keys are all in `allowed` and appear once.
  bool ExpectMap(const YAML::Node& node, const std::string& what,
                 std::initializer_list<const char*> allowed);
  /// Checks that `node` is a sequence.
  bool ExpectSequence(const YAML::Node& node, const std::string& what);
  /// Records an error when `map[key]` is absent.
  bool Require(const YAML::Node& map, const char* key, const std::string& what);

  std::optional<std::string> String(const YAML::Node& map, const char* key, const std::string& what,
                                    bool required);
  std::optional<double> Number(const YAML::Node& map, const char* key, const std::string& what,
                               bool required, NumberRule rule = NumberRule::kAny);
  std::optional<bool> Bool(const YAML::Node& map, const char* key, const std::string& what,
                           bool required);
  /// [x, y] in metres.
  std::optional<Vec2> Point(const YAML::Node& map, const char* key, const std::string& what,
                            bool required);
  /// [x, y, yaw]: metres and radians.
  std::optional<Pose2> Pose(const YAML::Node& map, const char* key, const std::string& what,
                            bool required);
  /// [[x, y], ...] with at least `min_points` points.
  std::optional<Polygon> Points(const YAML::Node& map, const char* key, const std::string& what,
                                bool required, std::size_t min_points);
  /// A fixed-length list of numbers, e.g. [lx, ly].
  std::optional<std::vector<double>> Numbers(const YAML::Node& map, const char* key,
                                             const std::string& what, bool required,
                                             std::size_t count, NumberRule rule);

  const std::vector<SourceError>& errors() const { return errors_; }
  const std::vector<SourceError>& warnings() const { return warnings_; }
  const std::string& file() const { return file_; }

 private:
  std::optional<double> ScalarNumber(const YAML::Node& node, const std::string& what,
                                     NumberRule rule);

  std::string file_;
  std::vector<SourceError> errors_;
  std::vector<SourceError> warnings_;
};

/// The candidate closest to `word` by edit distance, if it is close enough to be a likely typo.
std::optional<std::string> ClosestWord(const std::string& word,
                                       std::initializer_list<const char*> candidates);

}  // namespace spott_map
