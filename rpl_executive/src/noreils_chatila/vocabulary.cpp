#include "rpl_executive/noreils_chatila/vocabulary.h"

#include <cmath>
#include <cstdio>

namespace rpl_executive::noreils_chatila {

const std::vector<OperatorSpec>& Operators() {
  static const std::vector<OperatorSpec> kOperators = [] {
    std::vector<OperatorSpec> ops;
    auto add = [&](OperatorSpec s) { ops.push_back(std::move(s)); };
    OperatorSpec s;
    s = OperatorSpec{};
    s.name = "smooth-move";
    s.module = "PILOT";
    s.long_running = true;
    s.min_args = s.max_args = 1;
    s.resources = {"wheels"};
    s.usage = "(smooth-move (PATH)): PATH a Tpath or a list of points (x y) in cm";
    add(s);
    s = OperatorSpec{};
    s.name = "wall-following";
    s.module = "WALL-FOLLOWING";
    s.process = true;
    s.long_running = true;
    s.min_args = s.max_args = 1;
    s.resources = {"wheels"};
    s.usage = "(RUN (wall-following (right-side 25))): side right-side or left-side, distance cm";
    add(s);
    s = OperatorSpec{};
    s.name = "obstacle-avoidance";
    s.module = "OBSTACLE-AVOIDANCE";
    s.process = true;
    s.long_running = true;
    s.resources = {"wheels"};
    s.usage = "(RUN (obstacle-avoidance))";
    add(s);
    s = OperatorSpec{};
    s.name = "avoid-obstacle";
    s.module = "OBSTACLE-AVOIDANCE";
    s.long_running = true;
    s.resources = {"wheels"};
    s.required_env = {{"LOA", Value::True()}};
    s.usage = "(avoid-obstacle): the elementary task running the avoidance process; needs LOA T";
    add(s);
    s = OperatorSpec{};
    s.name = "resume-order";
    s.module = "EM";
    s.usage = "(resume-order): re-sends the order a terminal monitor interrupted";
    add(s);
    s = OperatorSpec{};
    s.name = "set-speed";
    s.module = "PILOT";
    s.reflex_allowed = true;
    s.min_args = s.max_args = 1;
    s.usage = "(set-speed v): v in cm/s";
    add(s);
    s = OperatorSpec{};
    s.name = "stop";
    s.module = "PILOT";
    s.reflex_allowed = true;
    s.halts_current_action = true;
    s.usage = "(stop)";
    add(s);
    s = OperatorSpec{};
    s.name = "read-all-us-data";
    s.module = "US";
    s.results = {"r-us-data", "r-position"};
    s.usage = "(read-all-us-data): sets r-us-data ((id cm)...) and r-position (x y heading)";
    add(s);
    s = OperatorSpec{};
    s.name = "read-pos";
    s.module = "ODOMETER";
    s.results = {"r-position"};
    s.usage = "(read-pos): sets r-position (x y heading) in cm and tenths of a degree";
    add(s);
    s = OperatorSpec{};
    s.name = "draw";
    s.module = "GRAPHICS";
    s.reflex_allowed = true;
    s.min_args = 1;
    s.max_args = -1;
    s.usage = "(draw %G_pos%G_echoes r-position r-us-data): one format per datum";
    add(s);
    return ops;
  }();
  return kOperators;
}

const OperatorSpec* FindOperator(const std::string& name) {
  for (const OperatorSpec& s : Operators()) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

const std::vector<ConditionSpec>& Conditions() {
  static const std::vector<ConditionSpec> kConditions = {
      {"S_zone", SensorKind::kPose, "(S_zone IN|OUT ZONE): ZONE a Tclist polygon in cm"},
      {"S_us-threshold", SensorKind::kSonar,
       "(S_us-threshold LIST): LIST ((sensor cm)...), sensors numbered from 1"},
      {"S_us-perception", SensorKind::kSonar,
       "(S_us-perception line (rho theta)): rho cm, theta tenths of a degree, robot frame"},
      {"S_straight-line", SensorKind::kPose,
       "(S_straight-line (x y phi)): x, y cm, phi tenths of a degree, map frame"},
      {"S_battery-level", SensorKind::kBattery, "(S_battery-level BELOW|ABOVE percent)"},
      {"S_laser-threshold", SensorKind::kLaser, "(S_laser-threshold cm)"},
  };
  return kConditions;
}

const ConditionSpec* FindCondition(const std::string& name) {
  for (const ConditionSpec& c : Conditions()) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

const std::vector<std::string>& BuiltinVariables() {
  static const std::vector<std::string> kVariables = {"motor", "motors", "LOA", "r-us-data",
                                                      "r-position"};
  return kVariables;
}

// --- resolution ---------------------------------------------------------------------------------

namespace {

template <typename T>
Decoded<T> Fail(Location where, std::string error) {
  Decoded<T> d;
  d.status = Decoded<T>::Status::kError;
  d.error = std::move(error);
  d.where = where;
  return d;
}

template <typename T, typename U>
Decoded<T> Forward(const Decoded<U>& from) {
  Decoded<T> d;
  d.status = static_cast<typename Decoded<T>::Status>(from.status);
  d.error = from.error;
  d.where = from.where;
  return d;
}

template <typename T>
Decoded<T> Ok(T value) {
  Decoded<T> d;
  d.value = std::move(value);
  return d;
}

Decoded<Value> Unknown(Location where) {
  Decoded<Value> d;
  d.status = Decoded<Value>::Status::kUnknown;
  d.where = where;
  return d;
}

// (PATH) written as a call's argument list: a list of one element that is itself a list of
// lists unwraps to that element (smooth-move(PATH) in Example 2).
Value Unwrap(const Value& v) {
  if (v.IsList() && v.list().size() == 1 && v.list()[0].IsList() && !v.list()[0].list().empty() &&
      v.list()[0].list()[0].IsList()) {
    return v.list()[0];
  }
  return v;
}

bool AllNumbers(const Value& v, size_t min_count, size_t max_count) {
  if (!v.IsList() || v.list().size() < min_count || v.list().size() > max_count) return false;
  for (const Value& n : v.list()) {
    if (!n.IsNumber()) return false;
  }
  return true;
}

std::string Short(const Value& v) {
  std::string t = v.ToText();
  if (t.size() > 40) t = t.substr(0, 37) + "...";
  return t;
}

Decoded<std::vector<double>> Numbers(const Value& v, size_t count, Location where,
                                     const std::string& what) {
  if (!AllNumbers(v, count, count)) {
    return Fail<std::vector<double>>(where, what + " must be a list of " + std::to_string(count) +
                                                " numbers, found " + Short(v));
  }
  std::vector<double> out;
  for (const Value& n : v.list()) out.push_back(n.number());
  return Ok(out);
}

}  // namespace

Decoded<Value> ResolveArgument(const Sexpr& arg, const Resolver& resolve) {
  switch (arg.kind) {
    case Sexpr::Kind::kNumber:
      return Ok(Value::Number(arg.number));
    case Sexpr::Kind::kSymbol: {
      const bool deref = arg.text.size() > 1 && arg.text[0] == '$';
      const std::string name = deref ? arg.text.substr(1) : arg.text;
      Value symbol = Value::Symbol(arg.text);
      if (!deref && symbol.IsNil()) return Ok(symbol);
      const Lookup l = resolve(name);
      if (l.kind == Lookup::Kind::kValue) return Ok(l.value);
      if (l.kind == Lookup::Kind::kUnknownValue) return Unknown(arg.where);
      if (deref) return Fail<Value>(arg.where, "'" + arg.text + "' names no variable");
      return Ok(symbol);
    }
    case Sexpr::Kind::kParen: {
      std::vector<Value> items;
      bool unknown = false;
      for (const Sexpr& item : arg.items) {
        Decoded<Value> d = ResolveArgument(item, resolve);
        if (d.status == Decoded<Value>::Status::kError) return d;
        if (d.status == Decoded<Value>::Status::kUnknown) unknown = true;
        items.push_back(d.value);
      }
      if (unknown) return Unknown(arg.where);
      return Ok(Value::List(std::move(items)));
    }
    default:
      return Fail<Value>(arg.where, "an argument cannot be a { } or [ ] block");
  }
}

Decoded<Value> ResolveValueExpr(const ValueExpr& expr, const Resolver& resolve) {
  if (expr.kind == ValueExpr::Kind::kLiteral) return Ok(expr.literal);
  const Lookup l = resolve(expr.name);
  if (l.kind == Lookup::Kind::kValue) return Ok(l.value);
  if (l.kind == Lookup::Kind::kUnknownValue) return Unknown(expr.where);
  if (expr.kind == ValueExpr::Kind::kDeref) {
    return Fail<Value>(expr.where, "'$" + expr.name + "' names no variable");
  }
  return Ok(Value::Symbol(expr.name));
}

Decoded<std::vector<Point2>> PolygonFromValue(const Value& raw) {
  if (raw.IsSymbol()) {
    return Fail<std::vector<Point2>>({}, "'" + raw.symbol() +
                                             "' names no variable (a zone is a "
                                             "list of 3 or more points (x y) in cm)");
  }
  const Value v = Unwrap(raw);
  if (!v.IsList() || v.list().size() < 3) {
    return Fail<std::vector<Point2>>({},
                                     "a zone must be a list of 3 or more points (x y) in cm, "
                                     "found " +
                                         Short(raw));
  }
  std::vector<Point2> polygon;
  for (const Value& p : v.list()) {
    if (!AllNumbers(p, 2, 2)) {
      return Fail<std::vector<Point2>>(
          {}, "each point of a zone must be (x y) in cm, found " + Short(p));
    }
    polygon.push_back(Point2{p.list()[0].number() * kMetresPerMissionLength,
                             p.list()[1].number() * kMetresPerMissionLength});
  }
  return Ok(polygon);
}

Value PolygonToValue(const std::vector<Point2>& polygon_m) {
  std::vector<Value> points;
  for (const Point2& p : polygon_m) {
    points.push_back(
        Value::List({Value::Number(std::round(p.x / kMetresPerMissionLength * 1e6) / 1e6),
                     Value::Number(std::round(p.y / kMetresPerMissionLength * 1e6) / 1e6)}));
  }
  return Value::List(std::move(points));
}

// --- operators ----------------------------------------------------------------------------------

namespace {

Decoded<OperatorCommand> DecodePath(const Sexpr& arg, const Resolver& resolve) {
  Decoded<Value> r = ResolveArgument(arg, resolve);
  if (!r.ok()) return Forward<OperatorCommand>(r);
  const Value v = Unwrap(r.value);
  if (!v.IsList()) {
    return Fail<OperatorCommand>(arg.where,
                                 "smooth-move: the path must be a list of points "
                                 "(x y) in cm, found " +
                                     Short(r.value));
  }
  SmoothMoveCommand c;
  const auto& points = v.list();
  for (size_t i = 0; i < points.size(); ++i) {
    if (!AllNumbers(points[i], 2, 3)) {
      return Fail<OperatorCommand>(arg.where,
                                   "smooth-move: each point of the path must be "
                                   "(x y) or, last, (x y heading), found " +
                                       Short(points[i]));
    }
    const auto& n = points[i].list();
    if (n.size() == 3) {
      if (i + 1 != points.size()) {
        return Fail<OperatorCommand>(arg.where,
                                     "smooth-move: only the path's last point may "
                                     "give a heading");
      }
      c.final_yaw_rad = WrapAngle(n[2].number() * kRadiansPerMissionAngle);
    }
    c.path_m.push_back(
        Point2{n[0].number() * kMetresPerMissionLength, n[1].number() * kMetresPerMissionLength});
  }
  return Ok<OperatorCommand>(c);
}

Decoded<OperatorCommand> DecodeWallFollowing(const Sexpr& arg, const Resolver& resolve) {
  Decoded<Value> r = ResolveArgument(arg, resolve);
  if (!r.ok()) return Forward<OperatorCommand>(r);
  const Value& v = r.value;
  const char* usage = "wall-following: expected (right-side <cm>) or (left-side <cm>), found ";
  if (!v.IsList() || v.list().size() != 2 || !v.list()[0].IsSymbol() || !v.list()[1].IsNumber()) {
    return Fail<OperatorCommand>(arg.where, usage + Short(v));
  }
  WallFollowingCommand c;
  const std::string& side = v.list()[0].symbol();
  if (side == "right-side") {
    c.side = WallSide::kRight;
  } else if (side == "left-side") {
    c.side = WallSide::kLeft;
  } else {
    return Fail<OperatorCommand>(arg.where, usage + Short(v));
  }
  const double cm = v.list()[1].number();
  if (!(cm > 0.0)) {
    return Fail<OperatorCommand>(arg.where, "wall-following: the distance must be above 0 cm");
  }
  c.distance_m = cm * kMetresPerMissionLength;
  return Ok<OperatorCommand>(c);
}

Decoded<OperatorCommand> DecodeDraw(const Statement& st, const Resolver& resolve) {
  DrawCommand c;
  size_t i = 0;
  while (i < st.args.size() && st.args[i].IsSymbol() && !st.args[i].text.empty() &&
         st.args[i].text[0] == '%') {
    const std::string& f = st.args[i].text;
    size_t start = 1;
    while (start <= f.size()) {
      size_t end = f.find('%', start);
      if (end == std::string::npos) end = f.size();
      if (end == start) {
        return Fail<OperatorCommand>(st.args[i].where, "draw: empty format in '" + f + "'");
      }
      c.formats.push_back(f.substr(start, end - start));
      start = end + 1;
    }
    ++i;
  }
  if (c.formats.empty()) {
    return Fail<OperatorCommand>(st.where, "draw: expected formats first (%G_pos%G_echoes)");
  }
  bool unknown = false;
  for (; i < st.args.size(); ++i) {
    Decoded<Value> r = ResolveArgument(st.args[i], resolve);
    if (r.status == Decoded<Value>::Status::kError) return Forward<OperatorCommand>(r);
    if (r.status == Decoded<Value>::Status::kUnknown) unknown = true;
    c.data.push_back(r.value);
  }
  if (c.data.size() != c.formats.size()) {
    return Fail<OperatorCommand>(st.where, "draw: " + std::to_string(c.formats.size()) +
                                               " format(s) for " + std::to_string(c.data.size()) +
                                               " datum/data: give one format per datum");
  }
  if (unknown) {
    Decoded<OperatorCommand> d;
    d.status = Decoded<OperatorCommand>::Status::kUnknown;
    return d;
  }
  return Ok<OperatorCommand>(c);
}

}  // namespace

Decoded<OperatorCommand> DecodeOperator(const Statement& st, const Resolver& resolve) {
  const OperatorSpec* spec = FindOperator(st.op);
  if (spec == nullptr) {
    return Fail<OperatorCommand>(st.op_where, "unknown operator '" + st.op + "'");
  }
  if (st.kind == Statement::Kind::kRun && !spec->process) {
    return Fail<OperatorCommand>(st.op_where, "RUN: '" + st.op +
                                                  "' is not a process (processes: "
                                                  "wall-following, obstacle-avoidance)");
  }
  if (st.kind == Statement::Kind::kCommand && spec->process) {
    return Fail<OperatorCommand>(st.op_where, "'" + st.op +
                                                  "' is a process: start it with "
                                                  "(RUN (" +
                                                  st.op + " ...))");
  }
  const int n = static_cast<int>(st.args.size());
  if (n < spec->min_args || (spec->max_args >= 0 && n > spec->max_args)) {
    std::string expected =
        spec->max_args < 0 ? "at least " + std::to_string(spec->min_args)
        : spec->min_args == spec->max_args
            ? std::to_string(spec->min_args)
            : std::to_string(spec->min_args) + " to " + std::to_string(spec->max_args);
    return Fail<OperatorCommand>(st.op_where, "'" + st.op + "' takes " + expected +
                                                  " argument(s), found " + std::to_string(n) +
                                                  ": " + spec->usage);
  }
  const std::string& op = st.op;
  if (op == "smooth-move") return DecodePath(st.args[0], resolve);
  if (op == "wall-following") return DecodeWallFollowing(st.args[0], resolve);
  if (op == "obstacle-avoidance") return Ok<OperatorCommand>(ObstacleAvoidanceCommand{});
  if (op == "avoid-obstacle") return Ok<OperatorCommand>(AvoidObstacleCommand{});
  if (op == "stop") return Ok<OperatorCommand>(StopCommand{});
  if (op == "read-all-us-data") return Ok<OperatorCommand>(ReadAllUsDataCommand{});
  if (op == "read-pos") return Ok<OperatorCommand>(ReadPosCommand{});
  if (op == "draw") return DecodeDraw(st, resolve);
  if (op == "set-speed") {
    Decoded<Value> r = ResolveArgument(st.args[0], resolve);
    if (!r.ok()) return Forward<OperatorCommand>(r);
    if (!r.value.IsNumber() || !(r.value.number() >= 0.0)) {
      return Fail<OperatorCommand>(st.args[0].where,
                                   "set-speed: the speed must be a number of "
                                   "cm/s from 0, found " +
                                       Short(r.value));
    }
    return Ok<OperatorCommand>(SetSpeedCommand{r.value.number() * kMpsPerMissionSpeed});
  }
  return Fail<OperatorCommand>(st.op_where, "'" + op +
                                                "' is carried out by the executive, not "
                                                "sent to a module");
}

// --- conditions ---------------------------------------------------------------------------------

namespace {

Decoded<AtomicCondition> DecodeAtom(const ConditionNode& c, const Resolver& resolve,
                                    int sonar_count) {
  const ConditionSpec* spec = FindCondition(c.name);
  if (spec == nullptr) {
    std::string known;
    for (const ConditionSpec& s : Conditions()) known += (known.empty() ? "" : ", ") + s.name;
    return Fail<AtomicCondition>(c.where,
                                 "unknown condition '" + c.name + "' (known: " + known + ")");
  }
  auto arity = [&](size_t n) -> std::optional<Decoded<AtomicCondition>> {
    if (c.args.size() == n) return std::nullopt;
    return Fail<AtomicCondition>(c.where, c.name + " takes " + std::to_string(n) +
                                              " argument(s), found " +
                                              std::to_string(c.args.size()) + ": " + spec->usage);
  };
  auto resolved = [&](size_t i) { return ResolveArgument(c.args[i], resolve); };
  if (c.name == "S_zone") {
    if (auto e = arity(2)) return *e;
    ZoneCondition z;
    if (c.args[0].IsKeyword("IN")) {
      z.inside = true;
    } else if (c.args[0].IsKeyword("OUT")) {
      z.inside = false;
    } else {
      return Fail<AtomicCondition>(
          c.args[0].where, "S_zone: expected IN or OUT, found '" + c.args[0].ToText() + "'");
    }
    Decoded<Value> r = resolved(1);
    if (!r.ok()) return Forward<AtomicCondition>(r);
    Decoded<std::vector<Point2>> p = PolygonFromValue(r.value);
    if (!p.ok()) return Fail<AtomicCondition>(c.args[1].where, "S_zone: " + p.error);
    z.polygon_m = p.value;
    return Ok<AtomicCondition>(z);
  }
  if (c.name == "S_us-threshold") {
    if (auto e = arity(1)) return *e;
    Decoded<Value> r = resolved(0);
    if (!r.ok()) return Forward<AtomicCondition>(r);
    const Value v = Unwrap(r.value);
    if (v.IsSymbol()) {
      return Fail<AtomicCondition>(c.args[0].where,
                                   "S_us-threshold: '" + v.symbol() + "' names no variable");
    }
    if (!v.IsList()) {
      return Fail<AtomicCondition>(c.args[0].where,
                                   "S_us-threshold: expected ((sensor cm)...), "
                                   "found " +
                                       Short(r.value));
    }
    UsThresholdCondition u;
    for (const Value& pair : v.list()) {
      if (!AllNumbers(pair, 2, 2)) {
        return Fail<AtomicCondition>(c.args[0].where,
                                     "S_us-threshold: each entry must be "
                                     "(sensor cm), found " +
                                         Short(pair));
      }
      const double id = pair.list()[0].number();
      const double cm = pair.list()[1].number();
      if (id != std::floor(id) || id < 1 || id > sonar_count) {
        return Fail<AtomicCondition>(c.args[0].where, "S_us-threshold: sensor " + NumberText(id) +
                                                          " does not exist (sensors 1 to " +
                                                          std::to_string(sonar_count) + ")");
      }
      if (!(cm > 0.0)) {
        return Fail<AtomicCondition>(c.args[0].where, "S_us-threshold: the threshold of sensor " +
                                                          NumberText(id) + " must be above 0 cm");
      }
      u.thresholds_m.emplace_back(static_cast<int>(id), cm * kMetresPerMissionLength);
    }
    return Ok<AtomicCondition>(u);
  }
  if (c.name == "S_us-perception") {
    if (auto e = arity(2)) return *e;
    if (!c.args[0].IsKeyword("line")) {
      return Fail<AtomicCondition>(c.args[0].where,
                                   "S_us-perception: the sonar interpretation perceives lines "
                                   "only: expected 'line', found '" +
                                       c.args[0].ToText() + "'");
    }
    Decoded<Value> r = resolved(1);
    if (!r.ok()) return Forward<AtomicCondition>(r);
    auto n = Numbers(r.value, 2, c.args[1].where, "S_us-perception: (rho theta)");
    if (!n.ok()) return Forward<AtomicCondition>(n);
    if (!(n.value[0] >= 0.0)) {
      return Fail<AtomicCondition>(c.args[1].where, "S_us-perception: rho must be 0 cm or more");
    }
    return Ok<AtomicCondition>(UsPerceptionCondition{
        n.value[0] * kMetresPerMissionLength, WrapAngle(n.value[1] * kRadiansPerMissionAngle)});
  }
  if (c.name == "S_straight-line") {
    if (auto e = arity(1)) return *e;
    Decoded<Value> r = resolved(0);
    if (!r.ok()) return Forward<AtomicCondition>(r);
    auto n = Numbers(r.value, 3, c.args[0].where, "S_straight-line: (x y phi)");
    if (!n.ok()) return Forward<AtomicCondition>(n);
    return Ok<AtomicCondition>(StraightLineCondition{
        Point2{n.value[0] * kMetresPerMissionLength, n.value[1] * kMetresPerMissionLength},
        WrapAngle(n.value[2] * kRadiansPerMissionAngle)});
  }
  if (c.name == "S_battery-level") {
    if (auto e = arity(2)) return *e;
    BatteryCondition b;
    if (c.args[0].IsKeyword("BELOW")) {
      b.below = true;
    } else if (c.args[0].IsKeyword("ABOVE")) {
      b.below = false;
    } else {
      return Fail<AtomicCondition>(c.args[0].where,
                                   "S_battery-level: expected BELOW or ABOVE, "
                                   "found '" +
                                       c.args[0].ToText() + "'");
    }
    Decoded<Value> r = resolved(1);
    if (!r.ok()) return Forward<AtomicCondition>(r);
    if (!r.value.IsNumber() || r.value.number() < 0 || r.value.number() > 100) {
      return Fail<AtomicCondition>(c.args[1].where,
                                   "S_battery-level: the level must be a "
                                   "percentage from 0 to 100");
    }
    b.level_percent = r.value.number();
    return Ok<AtomicCondition>(b);
  }
  // S_laser-threshold
  if (auto e = arity(1)) return *e;
  Decoded<Value> r = resolved(0);
  if (!r.ok()) return Forward<AtomicCondition>(r);
  if (!r.value.IsNumber() || !(r.value.number() > 0)) {
    return Fail<AtomicCondition>(c.args[0].where,
                                 "S_laser-threshold: the distance must be a "
                                 "number of cm above 0");
  }
  return Ok<AtomicCondition>(LaserThresholdCondition{r.value.number() * kMetresPerMissionLength});
}

}  // namespace

Decoded<CompiledCondition> DecodeCondition(const ConditionNode& c, const Resolver& resolve,
                                           int sonar_count) {
  CompiledCondition out;
  out.text = c.ToText();
  if (c.kind == ConditionNode::Kind::kAtom) {
    Decoded<AtomicCondition> a = DecodeAtom(c, resolve, sonar_count);
    if (!a.ok()) return Forward<CompiledCondition>(a);
    out.op = CompiledCondition::Op::kAtom;
    out.atom = a.value;
    return Ok(out);
  }
  out.op = c.kind == ConditionNode::Kind::kAnd  ? CompiledCondition::Op::kAnd
           : c.kind == ConditionNode::Kind::kOr ? CompiledCondition::Op::kOr
                                                : CompiledCondition::Op::kNot;
  bool unknown = false;
  for (const ConditionNode& child : c.children) {
    Decoded<CompiledCondition> d = DecodeCondition(child, resolve, sonar_count);
    if (d.status == Decoded<CompiledCondition>::Status::kError) return d;
    if (d.status == Decoded<CompiledCondition>::Status::kUnknown) unknown = true;
    out.children.push_back(std::move(d.value));
  }
  if (unknown) {
    Decoded<CompiledCondition> d;
    d.status = Decoded<CompiledCondition>::Status::kUnknown;
    return d;
  }
  return Ok(out);
}

}  // namespace rpl_executive::noreils_chatila
