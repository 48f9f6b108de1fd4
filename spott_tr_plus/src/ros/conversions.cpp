#include "spott_tr_plus/ros/conversions.h"

#include <cmath>

#include "spott_tr_plus/value.h"

namespace spott_tr_plus {
namespace ros_conversions {

spott_msgs::TRProgramState ToMsg(const InterpreterState& state, const ProgramFile& program,
                                 const ros::Time& stamp) {
  spott_msgs::TRProgramState msg;
  msg.header.stamp = stamp;
  msg.program = state.main;
  for (const FrameState& f : state.frames) {
    std::string call = f.program;
    if (f.depth > 0) {
      call += "(";
      for (size_t i = 0; i < f.args.size(); ++i) call += (i ? ", " : "") + f.args[i];
      call += ")";
    }
    msg.call_chain.push_back(call);
  }
  // The deepest frame with a firing rule is where the executing action is.
  for (auto it = state.frames.rbegin(); it != state.frames.rend(); ++it) {
    if (it->firing_rule < 0) continue;
    msg.firing_program = it->program;
    msg.firing_rule = static_cast<uint32_t>(it->firing_rule);
    if (const Program* p = program.FindProgram(it->program)) {
      msg.firing_action = ToText(p->rules[it->firing_rule].action);
    }
    msg.action_running = it->action_running;
    break;
  }
  for (const ProcessState& p : state.processes) {
    spott_msgs::ConditionState c;
    c.name = p.name;
    c.value = p.value;
    c.active = p.active;
    c.computing = p.computing;
    c.semantics = p.semantics == Semantics::kBallistic ? spott_msgs::ConditionState::BALLISTIC
                                                       : spott_msgs::ConditionState::ENERGIZED;
    c.frequency = p.frequency_hz;
    if (std::isfinite(p.last_update) && p.last_update >= 0) c.last_update.fromSec(p.last_update);
    for (const auto& [key, value] : p.outputs) {
      spott_msgs::Attribute a;
      a.key = key;
      a.value = value;
      c.outputs.push_back(a);
    }
    msg.conditions.push_back(c);
  }
  return msg;
}

namespace {

// Splits "a, \"b,c\", [1, 2]" at top-level commas.
std::vector<std::string> SplitArgs(const std::string& s) {
  std::vector<std::string> parts;
  std::string cur;
  int depth = 0;
  bool quoted = false;
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (quoted) {
      cur += c;
      if (c == '\\' && i + 1 < s.size()) {
        cur += s[++i];
      } else if (c == '"') {
        quoted = false;
      }
      continue;
    }
    if (c == '"') quoted = true;
    if (c == '[') ++depth;
    if (c == ']') --depth;
    if (c == ',' && depth == 0) {
      parts.push_back(cur);
      cur.clear();
      continue;
    }
    cur += c;
  }
  if (!cur.empty() || !parts.empty()) parts.push_back(cur);
  return parts;
}

}  // namespace

bool FromMsg(const spott_msgs::ConditionState& msg, const ProgramFile& program,
             ConditionUpdate* update, std::string* error) {
  ConditionUpdate u;
  const size_t open = msg.name.find('(');
  u.name = msg.name.substr(0, open);
  if (open != std::string::npos) {
    if (msg.name.back() != ')') {
      *error = "condition name '" + msg.name + "' has no closing ')'";
      return false;
    }
    for (const std::string& a : SplitArgs(msg.name.substr(open + 1, msg.name.size() - open - 2))) {
      u.inputs.push_back(ValueFromText(a));
    }
  }
  const ConditionDecl* d = program.FindCondition(u.name);
  if (!d) {
    *error = "no condition named '" + u.name + "' in the running program";
    return false;
  }
  if (static_cast<int>(u.inputs.size()) != d->NumInputs()) {
    *error = "condition '" + u.name + "' takes " + std::to_string(d->NumInputs()) +
             " input(s), the message gives " + std::to_string(u.inputs.size());
    return false;
  }
  u.value = msg.value;
  for (const ConditionParam& p : d->params) {
    if (!p.is_output) continue;
    Value v;
    for (const auto& a : msg.outputs) {
      if (a.key == p.name) v = ValueFromText(a.value);
    }
    u.outputs.push_back(v);
  }
  for (const auto& a : msg.outputs) {
    bool known = false;
    for (const ConditionParam& p : d->params) known = known || (p.is_output && p.name == a.key);
    if (!known) {
      *error = "condition '" + u.name + "' has no output named '" + a.key + "'";
      return false;
    }
  }
  *update = std::move(u);
  return true;
}

}  // namespace ros_conversions
}  // namespace spott_tr_plus
