// rpl_executive: the executives of SPOTT-ROS on the stack. Serves /mission (spott_msgs/Mission)
// for both languages: RPL structured reactive plans (Beetz et al. section 3; rpl_binding.h) and
// Noreils-Chatila missions (sections 4-6; nc_binding.h). Glue only: reads and validates the
// parameters, resolves a goal's text (or a shipped plan / mission by name), hands it to the
// language's binding and turns the binding's state into feedback, the result, the latched
// ~state (spott_msgs/ExecutiveState) and an rviz text view (~text_view).
//
// Topics, services, parameters and frames: README.md ("The node"), config/rpl_executive.yaml.
#include <actionlib/server/simple_action_server.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <spott_msgs/ExecutiveState.h>
#include <spott_msgs/MissionAction.h>
#include <visualization_msgs/Marker.h>

#include <memory>
#include <sstream>

#include "../ros/conversions.h"
#include "../ros/nc_binding.h"
#include "../ros/parameters.h"
#include "../ros/rpl_binding.h"
#include "spott_ros/parameter_reader.h"
#include "spott_text/file_reading.h"

namespace rpl_executive {
namespace {

namespace conv = ros_conversions;
using Goal = spott_msgs::MissionGoal;

const char* RplStateName(rpl::PlanState s) {
  switch (s) {
    case rpl::PlanState::kNoPlan:
    case rpl::PlanState::kLoaded:
      return "idle";
    case rpl::PlanState::kRunning:
      return "running";
    case rpl::PlanState::kSucceeded:
      return "succeeded";
    case rpl::PlanState::kFailed:
      return "failed";
    case rpl::PlanState::kAborted:
      return "aborted";
  }
  return "?";
}

// The text of a shipped plan (plans/<name>.rpl) or mission (missions/<name>.nc); "" + error.
std::string ShippedText(const std::string& name, bool rpl, std::string* file, std::string* error) {
  for (char c : name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) {
      *error =
          "name '" + name + "': a shipped plan or mission is named by letters, digits, _ and -";
      return "";
    }
  }
  const std::string dir = ros::package::getPath("rpl_executive");
  const std::string path = dir + (rpl ? "/plans/" + name + ".rpl" : "/missions/" + name + ".nc");
  std::string why;
  const auto text = spott_text::ReadTextFile(path, &why);
  if (!text) {
    *error = "no shipped " + std::string(rpl ? "plan" : "mission") + " '" + name + "' (" + path +
             ": " + why + ")";
    return "";
  }
  *file = path;
  return *text;
}

class MissionNode {
 public:
  MissionNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const ros_parameters::NodeParameters& p)
      : params_(p),
        refusals_(nh, "rpl_executive"),
        server_(nh, "mission", false),
        rpl_(nh, p, &refusals_, [this] { Changed(false); }),
        nc_(nh, p, &refusals_, [this] { Changed(false); }) {
    state_pub_ = pnh.advertise<spott_msgs::ExecutiveState>("state", 1, true);
    text_pub_ = pnh.advertise<visualization_msgs::Marker>("text_view", 1, true);
    server_.registerGoalCallback([this] { OnGoal(); });
    server_.registerPreemptCallback([this] { OnPreempt(); });
    server_.start();
    if (p.state_rate_hz > 0) {
      state_timer_ = nh.createTimer(ros::Duration(1.0 / p.state_rate_hz),
                                    [this](const ros::TimerEvent&) { Changed(true); });
    }
    Changed(true);
    ROS_INFO("rpl_executive: serving /mission (RPL and NOREILS_CHATILA)");
  }

 private:
  bool Rpl() const { return language_ == Goal::RPL; }
  bool BindingRunning() const { return Rpl() ? rpl_.running() : nc_.running(); }

  void OnGoal() {
    // A new goal replaces the running one (actionlib preempts it).
    if (active_ && BindingRunning()) {
      if (Rpl()) {
        rpl_.Abort();
      } else {
        nc_.Abort("preempted by a new mission");
      }
    }
    active_ = false;
    const auto goal = server_.acceptNewGoal();
    spott_msgs::MissionResult result;
    result.success = false;
    result.outcome = "rejected";
    if (goal->language != Goal::RPL && goal->language != Goal::NOREILS_CHATILA) {
      result.message =
          "language must be RPL (0) or NOREILS_CHATILA (1), got " + std::to_string(goal->language);
      server_.setAborted(result, result.message);
      return;
    }
    const bool rpl = goal->language == Goal::RPL;
    std::string text = goal->text, file = goal->source_name, error;
    if (text.empty()) {
      if (goal->name.empty()) {
        result.message = "the goal has neither text nor the name of a shipped plan or mission";
        server_.setAborted(result, result.message);
        return;
      }
      std::string path;
      text = ShippedText(goal->name, rpl, &path, &error);
      if (!error.empty()) {
        result.message = error;
        server_.setAborted(result, result.message);
        return;
      }
      if (file.empty()) file = goal->name + (rpl ? ".rpl" : ".nc");
    }
    if (file.empty()) file = "<mission>";
    language_ = goal->language;
    if (rpl) {
      error = rpl_.Load(text, file, goal->bindings);
      if (error.empty()) error = rpl_.Start();
    } else {
      if (!goal->bindings.empty()) {
        error = "bindings are for RPL plans; a Noreils-Chatila mission defines its variables";
      } else {
        error = nc_.Start(text, file);
      }
    }
    if (!error.empty()) {
      result.message = error;
      ROS_WARN("rpl_executive: mission %s rejected:\n%s", file.c_str(), error.c_str());
      server_.setAborted(result, result.message);
      Changed(true);
      return;
    }
    ROS_INFO("rpl_executive: %s %s started", rpl ? "plan" : "mission", file.c_str());
    active_ = true;
    Changed(true);
  }

  void OnPreempt() {
    if (!active_) return;
    if (Rpl()) {
      rpl_.Abort();  // cleanups run; the result comes when the plan is aborted
    } else {
      nc_.Abort("preempted");
    }
    Changed(true);
  }

  spott_msgs::ExecutiveState State() {
    spott_msgs::ExecutiveState s;
    s.header.stamp = ros::Time::now();
    s.header.frame_id = params_.map_frame;
    s.language = language_;
    if (Rpl()) {
      s.mission = rpl_.file();
      s.state = RplStateName(rpl_.state());
      s.tasks = rpl_.Tasks();
      s.fluents = rpl_.Fluents();
      s.events = rpl_.TakeEvents();
      s.travel_mode = rpl_.travel_mode();
      s.text_view = conv::TaskTreeText(s.tasks, s.fluents);
    } else {
      s.mission = nc_.mission_name();
      s.state = nc_.NotReady().empty() ? noreils_chatila::MissionStateName(nc_.state())
                                       : "not ready: " + nc_.NotReady();
      s.current_command = nc_.CurrentCommand();
      s.active_monitors = nc_.ActiveMonitors();
      if (nc_.last_event()) s.last_event = *nc_.last_event();
      s.events = nc_.TakeEvents();
      std::ostringstream t;
      t << s.mission << ": " << s.state << "\n" << s.current_command << "\n";
      for (const std::string& m : s.active_monitors) t << "  " << m << "\n";
      s.text_view = t.str();
    }
    return s;
  }

  // After every change of a binding (and at state_rate_hz): state, feedback, the result.
  void Changed(bool periodic) {
    if (in_changed_) return;
    in_changed_ = true;
    spott_msgs::ExecutiveState s = State();
    const bool different =
        !s.events.empty() || s.state != last_.state || s.current_command != last_.current_command ||
        s.active_monitors != last_.active_monitors || s.tasks.size() != last_.tasks.size() ||
        s.travel_mode != last_.travel_mode;
    if (periodic || different) {
      state_pub_.publish(s);
      text_pub_.publish(
          conv::TextViewMarker(s.text_view, params_.base_frame, 0.0, 0.0, s.header.stamp));
      if (active_ && server_.isActive()) {
        spott_msgs::MissionFeedback f;
        f.current_command = s.current_command;
        f.active_monitors = s.active_monitors;
        f.last_event = s.last_event;
        f.fluents = s.fluents;
        f.state = s.state;
        f.tasks = s.tasks;
        server_.publishFeedback(f);
      }
      last_ = s;
    }
    if (active_ && !BindingRunning()) Finish();
    in_changed_ = false;
  }

  void Finish() {
    active_ = false;
    spott_msgs::MissionResult r;
    if (Rpl()) {
      const rpl::PlanState st = rpl_.state();
      r.success = st == rpl::PlanState::kSucceeded;
      r.outcome = r.success ? "completed" : st == rpl::PlanState::kAborted ? "preempted" : "failed";
      r.message = r.success ? "the plan succeeded" : rpl_.FailureText();
    } else {
      const noreils_chatila::MissionState st = nc_.state();
      r.success = st == noreils_chatila::MissionState::kSucceeded;
      r.outcome = r.success                                       ? "completed"
                  : st == noreils_chatila::MissionState::kAborted ? "preempted"
                                                                  : "failed";
      r.message = r.success ? "mission " + nc_.mission_name() + " succeeded" : nc_.FailureText();
      r.events = nc_.Fired();
    }
    ROS_INFO("rpl_executive: %s: %s", r.outcome.c_str(), r.message.c_str());
    if (!server_.isActive()) return;
    if (r.outcome == "preempted") {
      server_.setPreempted(r, r.message);
    } else if (r.success) {
      server_.setSucceeded(r, r.message);
    } else {
      server_.setAborted(r, r.message);
    }
  }

  ros_parameters::NodeParameters params_;
  spott_ros::InputRefusals refusals_;  // before the bindings, which count into it
  actionlib::SimpleActionServer<spott_msgs::MissionAction> server_;
  RplBinding rpl_;
  NcBinding nc_;
  uint8_t language_ = Goal::RPL;
  bool active_ = false;
  bool in_changed_ = false;
  spott_msgs::ExecutiveState last_;
  ros::Publisher state_pub_, text_pub_;
  ros::Timer state_timer_;
};

int Main(int argc, char** argv) {
  ros::init(argc, argv, "rpl_executive");
  ros::NodeHandle nh, pnh("~");
  const auto params = spott_ros::ReadNodeParameters<ros_parameters::NodeParameters>(
      pnh, "rpl_executive", ros_parameters::Read);
  if (!params) return 1;
  MissionNode node(nh, pnh, *params);
  ros::spin();
  return 0;
}

}  // namespace
}  // namespace rpl_executive

int main(int argc, char** argv) { return rpl_executive::Main(argc, argv); }
