// What the mission language knows: the execution operators, processes and conditions of
// sections 5 and 6, their arguments, and how those arguments are decoded from mission units
// (cm, tenths of a degree, cm/s, percent) into SI commands. The checker (checker.h) decodes with
// what it knows before anything runs; the executive decodes again with the run's values.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "rpl_executive/noreils_chatila/conditions.h"
#include "rpl_executive/noreils_chatila/mission.h"
#include "rpl_executive/noreils_chatila/robot_modules.h"
#include "rpl_executive/noreils_chatila/value.h"

namespace rpl_executive::noreils_chatila {

/// Mission units (README "Units of the mission language"): the paper's ZONE109 and PATH are in
/// centimetres and PATH's 2700 is a heading in tenths of a degree.
constexpr double kMetresPerMissionLength = 0.01;        // 1 cm
constexpr double kRadiansPerMissionAngle = kPi / 1800;  // 0.1 degree
constexpr double kMpsPerMissionSpeed = 0.01;            // 1 cm/s

struct OperatorSpec {
  std::string name;
  std::string module;         ///< Fig. 5's module names (PILOT, US, ...), EM for resume-order
  bool process = false;       ///< started by RUN, never by a plain command (section 3.3)
  bool long_running = false;  ///< answers kRunning and reports later
  bool halts_current_action = false;  ///< stop: makes a monitor terminal (README)
  bool reflex_allowed = false;        ///< may appear in a reflex action
  int min_args = 0;
  int max_args = 0;  ///< -1: any number
  /// Resources it holds while running; a non-terminal monitor's concurrent action waits while
  /// the current action holds one of them (section 5).
  std::vector<std::string> resources;
  /// Its execution environment: variable = value pairs that must hold while it runs
  /// (avoid-obstacle needs LOA = T, Example 2). One that stops holding stops the task.
  std::vector<std::pair<std::string, Value>> required_env;
  std::vector<std::string> results;  ///< variables its reply sets
  std::string usage;
};

/// Every operator, process and executive keyword operator (resume-order).
const std::vector<OperatorSpec>& Operators();
/// nullptr when unknown. Names are case-sensitive, as the paper writes them.
const OperatorSpec* FindOperator(const std::string& name);

struct ConditionSpec {
  std::string name;
  SensorKind sensor;
  std::string usage;
};
const std::vector<ConditionSpec>& Conditions();
const ConditionSpec* FindCondition(const std::string& name);

/// Variables the executive provides without a define: the robot's state (motor, motors: set by
/// the caller, e.g. ON), the environment (LOA) and operator results (r-us-data, r-position).
const std::vector<std::string>& BuiltinVariables();

/// What a name means while decoding.
struct Lookup {
  enum class Kind { kNotVariable, kUnknownValue, kValue };
  Kind kind = Kind::kNotVariable;
  Value value;
};
using Resolver = std::function<Lookup(const std::string& name)>;

/// A decoded value, or why not. kUnknown: it names a variable whose value is only known when the
/// mission runs (the checker then skips the shape check).
template <typename T>
struct Decoded {
  enum class Status { kOk, kUnknown, kError };
  Status status = Status::kOk;
  T value{};
  std::string error;
  Location where;
  bool ok() const { return status == Status::kOk; }
};

/// Resolves a written argument: numbers stay, a bare symbol naming a variable gives its value
/// (otherwise the symbol itself), $name must name a variable, lists resolve item by item.
Decoded<Value> ResolveArgument(const Sexpr& arg, const Resolver& resolve);
Decoded<Value> ResolveValueExpr(const ValueExpr& expr, const Resolver& resolve);

/// Decodes a command or RUN statement into the command its module receives. resume-order has
/// no command (the executive re-sends the interrupted order) and is refused here.
Decoded<OperatorCommand> DecodeOperator(const Statement& statement, const Resolver& resolve);

/// Decodes a monitor's condition. `sonar_count` bounds the sensor ids of S_us-threshold.
Decoded<CompiledCondition> DecodeCondition(const ConditionNode& condition, const Resolver& resolve,
                                           int sonar_count);

/// A polygon value in mission units ((x y)...) -> metres; error text when it is not one.
Decoded<std::vector<Point2>> PolygonFromValue(const Value& value);

/// Metres -> a mission value ((x y) ...) in centimetres (for zones served by the world).
Value PolygonToValue(const std::vector<Point2>& polygon_m);

}  // namespace rpl_executive::noreils_chatila
