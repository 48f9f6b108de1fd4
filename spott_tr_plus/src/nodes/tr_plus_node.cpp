// tr_plus_node: runs a TR+ program (SPOTT III.C) loaded at run time and shows its live state.
//
// Conditions are pushed on ~set_condition (spott_msgs/ConditionState: name "cond" or
// "cond(input, ...)", value, outputs as attributes). Primitive actions are announced on
// ~action_events (std_msgs/String "start TICKET name(args)" / "stop TICKET name") and complete
// when their name or ticket arrives on ~action_done (std_msgs/String). The live state is
// published latched on ~state (spott_msgs/TRProgramState) and ~tree_dot (std_msgs/String: the
// active programs' TR trees with true conditions shaded and the firing arc marked) on every
// change. Services: ~load (spott_msgs/LoadTRProgram; a bad program is refused with located
// errors and the running one keeps running), ~parse_task (spott_msgs/ParseTask).
// The interpreter is event-driven: it scans on each message and on a one-shot timer set to its
// next wake time (a condition's period, a timeout), never on a fixed tick. Sim time via /clock.
#include <ros/ros.h>
#include <spott_msgs/LoadTRProgram.h>
#include <spott_msgs/ParseTask.h>
#include <std_msgs/String.h>

#include <cmath>
#include <map>

#include "spott_ros/parameter_reader.h"
#include "spott_tr_plus/checker.h"
#include "spott_tr_plus/dot_export.h"
#include "spott_tr_plus/interpreter.h"
#include "spott_tr_plus/parser.h"
#include "spott_tr_plus/ros/conversions.h"
#include "spott_tr_plus/ros/parameters.h"
#include "spott_tr_plus/task_command.h"

namespace spott_tr_plus {
namespace {

namespace conv = ros_conversions;

class TrPlusNode {
 public:
  TrPlusNode(ros::NodeHandle& pnh, NodeParameters params) : pnh_(pnh), params_(std::move(params)) {
    state_pub_ = pnh.advertise<spott_msgs::TRProgramState>("state", 1, true);
    dot_pub_ = pnh.advertise<std_msgs::String>("tree_dot", 1, true);
    events_pub_ = pnh.advertise<std_msgs::String>("action_events", 100);
    condition_sub_ = pnh.subscribe("set_condition", 100, &TrPlusNode::OnCondition, this);
    done_sub_ = pnh.subscribe("action_done", 100, &TrPlusNode::OnActionDone, this);
    load_srv_ = pnh.advertiseService("load", &TrPlusNode::OnLoad, this);
    task_srv_ = pnh.advertiseService("parse_task", &TrPlusNode::OnParseTask, this);
  }

  /// Parses, checks and binds; on success replaces the running program.
  bool Load(const ParseResult& parsed, const std::string& main, std::vector<Diagnostic>* diags,
            CheckReport* report) {
    diags->insert(diags->end(), parsed.diagnostics.begin(), parsed.diagnostics.end());
    if (!parsed.ok()) return false;
    *report = CheckProgram(parsed.program);
    Registry registry;
    for (const ConditionDecl& c : parsed.program.conditions) registry.ExternalCondition(c.name);
    for (const ActionDecl& a : parsed.program.actions) {
      registry.Action(
          a.name,
          [this](const ActionCall& call) { Announce("start", call.ticket, call.name, &call.args); },
          [this, name = a.name](Ticket t) { Announce("stop", t, name, nullptr); });
    }
    Interpreter::Options options;
    options.max_call_depth = params_.max_call_depth;
    std::vector<Diagnostic> d;
    auto next = Interpreter::Create(parsed.program, registry, &d, main, options);
    diags->insert(diags->end(), d.begin(), d.end());
    if (!next) return false;
    if (interpreter_) interpreter_->Stop(Now());
    interpreter_ = std::move(next);
    // The TR tree arcs (regression parents) do not change while a program runs: check once.
    parents_.clear();
    for (const ProgramVerdict& v : report->programs) parents_[v.program] = v.parent;
    running_.clear();
    interpreter_->Start(Now());
    AfterEvent();
    return true;
  }

 private:
  double Now() const { return ros::Time::now().toSec(); }

  void Announce(const char* what, Ticket ticket, const std::string& name,
                const std::vector<Value>* args) {
    std::string text = std::string(what) + " " + std::to_string(ticket) + " " + name;
    if (args) {
      text += "(";
      for (size_t i = 0; i < args->size(); ++i) text += (i ? ", " : "") + ValueToString((*args)[i]);
      text += ")";
      running_[ticket] = name;
    } else {
      running_.erase(ticket);
    }
    std_msgs::String msg;
    msg.data = text;
    events_pub_.publish(msg);
  }

  void OnCondition(const spott_msgs::ConditionState& msg) {
    if (!interpreter_) return;
    conv::ConditionUpdate u;
    std::string error;
    if (!conv::FromMsg(msg, interpreter_->program(), &u, &error)) {
      ROS_WARN("tr_plus_node: set_condition refused: %s", error.c_str());
      return;
    }
    if (!interpreter_->SetCondition(u.name, u.value, Now(), u.outputs, u.inputs)) {
      ROS_WARN("tr_plus_node: set_condition refused: '%s' is not an external condition",
               u.name.c_str());
      return;
    }
    AfterEvent();
  }

  void OnActionDone(const std_msgs::String& msg) {
    if (!interpreter_) return;
    // A ticket number, or an action name (completes its oldest running start).
    for (const auto& [ticket, name] : running_) {
      if (msg.data == name || msg.data == std::to_string(ticket)) {
        const Ticket t = ticket;
        running_.erase(t);
        interpreter_->CompleteAction(t, true, Now());
        AfterEvent();
        return;
      }
    }
    ROS_WARN("tr_plus_node: action_done '%s' matches no running action", msg.data.c_str());
  }

  bool OnLoad(spott_msgs::LoadTRProgram::Request& req, spott_msgs::LoadTRProgram::Response& res) {
    const ParseResult parsed =
        req.text.empty() ? ParseProgramFile(req.path) : ParseProgramText(req.text, "<request>");
    std::vector<Diagnostic> diags;
    CheckReport report;
    res.success = Load(parsed, req.main, &diags, &report);
    for (const Diagnostic& d : diags) {
      (d.IsError() ? res.errors : res.warnings).push_back(d.ToString());
    }
    res.verdict = report.Summary();
    if (!res.success) {
      ROS_WARN("tr_plus_node: program refused, the running one keeps running:\n%s",
               FormatDiagnostics(diags).c_str());
    } else {
      ROS_INFO("tr_plus_node: running '%s'\n%s", interpreter_->main_name().c_str(),
               res.verdict.c_str());
    }
    return true;
  }

  bool OnParseTask(spott_msgs::ParseTask::Request& req, spott_msgs::ParseTask::Response& res) {
    const TaskParseResult parsed = ParseTaskCommand(req.command);
    if (!parsed.ok()) {
      res.success = false;
      res.message = FormatDiagnostics(parsed.diagnostics);
      return true;
    }
    // The robot pose is not known to this node yet: interpret from the map origin.
    const TaskInterpretResult in = InterpretTask(*parsed.command, 0, 0, 0, params_.task);
    res.success = in.ok();
    res.message = FormatDiagnostics(in.diagnostics);
    if (in.ok()) res.interpretation = in.interpretation->ToString();
    return true;
  }

  void OnTimer(const ros::TimerEvent&) {
    if (!interpreter_) return;
    interpreter_->Advance(Now());
    AfterEvent();
  }

  void AfterEvent() {
    const InterpreterState s = interpreter_->State();
    state_pub_.publish(conv::ToMsg(s, interpreter_->program(), ros::Time::now()));
    std_msgs::String dot;
    dot.data = LiveDot(s);
    dot_pub_.publish(dot);
    const double wake = interpreter_->NextWakeTime();
    if (std::isfinite(wake)) {
      const double delay = std::max(wake - Now(), 1e-6);
      timer_ = pnh_.createTimer(ros::Duration(delay), &TrPlusNode::OnTimer, this, true);
    } else {
      timer_.stop();
    }
  }

  // The TR trees of the active programs, one after another in one DOT text per program.
  std::string LiveDot(const InterpreterState& s) const {
    std::string text;
    const ProgramFile& file = interpreter_->program();
    for (const FrameState& f : s.frames) {
      const Program* p = file.FindProgram(f.program);
      auto parent = parents_.find(f.program);
      if (!p || parent == parents_.end()) continue;
      DotLiveState live;
      live.rule_values = f.rule_values;
      live.firing_rule = f.firing_rule;
      text += TrTreeDot(*p, parent->second, &live);
    }
    return text;
  }

  ros::NodeHandle pnh_;
  NodeParameters params_;
  std::unique_ptr<Interpreter> interpreter_;
  std::map<Ticket, std::string> running_;
  std::map<std::string, std::vector<int>> parents_;  ///< per program: TR tree arc targets
  ros::Publisher state_pub_, dot_pub_, events_pub_;
  ros::Subscriber condition_sub_, done_sub_;
  ros::ServiceServer load_srv_, task_srv_;
  ros::Timer timer_;
};

}  // namespace
}  // namespace spott_tr_plus

int main(int argc, char** argv) {
  ros::init(argc, argv, "tr_plus_node");
  ros::NodeHandle pnh("~");
  const auto read = spott_ros::ReadNodeParameters<spott_tr_plus::NodeParameters>(
      pnh, "tr_plus_node", spott_tr_plus::ReadParameters);
  if (!read) return 1;
  const spott_tr_plus::NodeParameters& params = *read;
  spott_tr_plus::TrPlusNode node(pnh, params);
  std::vector<spott_tr_plus::Diagnostic> diags;
  spott_tr_plus::CheckReport report;
  if (!node.Load(spott_tr_plus::ParseProgramFile(params.program_file), params.main, &diags,
                 &report)) {
    ROS_FATAL("tr_plus_node: cannot run %s:\n%s", params.program_file.c_str(),
              spott_tr_plus::FormatDiagnostics(diags).c_str());
    return 1;
  }
  if (!diags.empty()) ROS_WARN("%s", spott_tr_plus::FormatDiagnostics(diags).c_str());
  ROS_INFO("tr_plus_node: running %s\n%s", params.program_file.c_str(), report.Summary().c_str());
  ros::spin();
  return 0;
}
