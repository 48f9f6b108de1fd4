#include "rpl_binding.h"

#include <spott_msgs/ReleaseWheels.h>
#include <spott_msgs/SetSpeedLimits.h>
#include <spott_msgs/TakeWheels.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>

#include <cmath>
#include <limits>

#include "conversions.h"
#include "rpl_executive/rpl/office_robot.h"
#include "spott_map/ros/conversions.h"
#include "spott_ros/pose_conversions.h"

namespace rpl_executive {

namespace conv = ros_conversions;
namespace office = rpl::office;

RplBinding::RplBinding(ros::NodeHandle& nh, const ros_parameters::NodeParameters& params,
                       spott_ros::InputRefusals* refusals, std::function<void()> changed)
    : params_(params),
      changed_(std::move(changed)),
      nh_(nh),
      refusals_(refusals),
      executive_(params.rpl),
      navigate_(nh, params.navigate_action, false),
      active_(nh, params.active_localize_action, false) {
  for (const rpl::FluentSpec& f : office::Fluents()) executive_.DeclareFluent(f);
  navigation_ =
      std::make_shared<office::NavigationModule>(&executive_, this, this, params.navigation);
  localization_ = std::make_shared<office::ActiveLocalizationModule>(&executive_, this,
                                                                     params.active_localization);
  tracking_ = std::make_shared<office::PositionTrackingModule>(&executive_,
                                                               params.tracking_status_timeout_s);
  executive_.AddModule(navigation_);
  executive_.AddModule(localization_);
  executive_.AddModule(tracking_);
  // (PLACE "name"): a named place of the world (world_server's world_places) as (X Y), m.
  executive_.AddFunction(
      {"PLACE", 1, 1, "the position (X Y) in m of a named place of world_server's world"},
      [this](const std::vector<rpl::Value>& args) -> rpl::HostResult {
        const std::string name = args[0].text();
        for (const auto& [n, p] : places_) {
          if (n == name) return {rpl::Value::Point(p.x_m, p.y_m), ""};
        }
        return rpl::HostResult::Error("PLACE: no place '" + name + "' in world_places (" +
                                      std::to_string(places_.size()) + " places known)");
      });
  executive_.SetEventCallback([this](const rpl::Event& e) {
    event_logged_ = true;
    events_.push_back(e.ToString());
    if (auto ended = conv::EndedThread(e)) {
      ended_.push_back(*ended);
      while (ended_.size() > static_cast<std::size_t>(params_.ended_threads_kept)) {
        ended_.pop_front();
      }
    }
  });

  const std::string arbiter = params.arbiter + "/";
  take_ = nh.serviceClient<spott_msgs::TakeWheels>(arbiter + "take_wheels");
  release_ = nh.serviceClient<spott_msgs::ReleaseWheels>(arbiter + "release_wheels");
  limits_ = nh.serviceClient<spott_msgs::SetSpeedLimits>(arbiter + "set_speed_limits");
  global_ = nh.serviceClient<std_srvs::Empty>(params.global_localization_service);
  sonar_ = nh.serviceClient<std_srvs::SetBool>(params.enable_sonar_service);
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  status_sub_ = nh.subscribe("localization_status", 5, &RplBinding::OnStatus, this, hints);
  graph_sub_ = nh.subscribe("room_door_graph", 1, &RplBinding::OnGraph, this);
  places_sub_ = nh.subscribe("world_places", 1, &RplBinding::OnPlaces, this);
  arbiter_sub_ = nh.subscribe(arbiter + "status", 5, &RplBinding::OnArbiter, this);
  planner_sub_ = nh.subscribe<geometry_msgs::Twist>(
      params.planner_cmd_topic, 5,
      [this](const geometry_msgs::Twist::ConstPtr& m) { Relay(*m, false); }, ros::VoidConstPtr(),
      hints);
  wander_sub_ = nh.subscribe<geometry_msgs::Twist>(
      params.wander_cmd_topic, 5,
      [this](const geometry_msgs::Twist::ConstPtr& m) { Relay(*m, true); }, ros::VoidConstPtr(),
      hints);
  cmd_pub_ = nh.advertise<geometry_msgs::Twist>("cmd_vel/" + params.wheels_source, 5);
  watchdog_timer_ = nh.createTimer(ros::Duration(0.5), [this](const ros::TimerEvent&) {
    if (spott_ros::GoalLostInTransport(nav_ack_, navigate_, "rpl_executive",
                                       params_.navigate_action)) {
      PublishNavigate();
    }
    tracking_->OnTime(Now());
    Tick();
  });
}

RplBinding::~RplBinding() {
  // The modules cancel through this object's clients, which the members' destruction would
  // take away before the executive: they stop now, while everything is alive.
  executive_.Shutdown();
  if (sonars_off_) SwitchSonars(true);
  if (have_wheels_) {
    spott_msgs::ReleaseWheels r;
    r.request.source = params_.wheels_source;
    release_.call(r);
  }
}

std::string RplBinding::Load(const std::string& text, const std::string& file,
                             const std::vector<std::string>& bindings) {
  if (running()) return "a plan is running";
  std::vector<std::pair<std::string, rpl::Value>> globals;
  std::string errors;
  for (const std::string& b : bindings) {
    std::string error;
    auto parsed = conv::ParseBinding(b, &error);
    if (!parsed) {
      errors += (errors.empty() ? "" : "\n") + error;
      continue;
    }
    globals.push_back(*parsed);
  }
  const std::vector<rpl::Diagnostic> d = executive_.Load(text, file);
  if (rpl::HasErrors(d)) errors = rpl::FormatDiagnostics(d) + (errors.empty() ? "" : "\n" + errors);
  if (!errors.empty()) return errors;
  file_ = file;
  globals_ = std::move(globals);
  return "";
}

std::string RplBinding::Start() {
  // The plan's fluents X*, Y*, O*, POS-CERTAINTY* come from the localization: before its first
  // status they hold no value, and a policy such as WHENEVER (<= POS-CERTAINTY* 0.8) would take
  // the robot for lost at once (the office delivery then localized globally from a certain pose
  // and drove into a wall on a twin corridor's estimate).
  if (!have_status_) return "not ready: no localization status yet (localization_status)";
  ended_.clear();
  const std::string why = executive_.Start(Now(), globals_);
  if (why.empty()) Tick();
  return why;
}

void RplBinding::Abort() {
  executive_.Abort(Now());
  Tick();
}

std::string RplBinding::FailureText() const {
  const rpl::Failure* f = executive_.failure();
  return f ? f->ToString() : "";
}

void RplBinding::Tick() {
  const double now = Now();
  int steps = 0;
  // Service calls run after the Step that asked for them; what they report is stepped at once.
  for (int round = 0; round < 10; ++round) {
    steps += executive_.Step(now).instructions;
    while (navigation_->AfterStep(now)) steps += executive_.Step(now).instructions;
    SyncWheels();
    if (deferred_.empty()) break;
    RunDeferred();
  }
  ArmWakeUp();
  if (steps > 0 || event_logged_) {
    event_logged_ = false;
    if (changed_) changed_();
  }
}

void RplBinding::ArmWakeUp() {
  const std::optional<double> at = executive_.NextWakeUp();
  if (!at) {
    wake_timer_.stop();
    return;
  }
  const double in = std::max(0.001, *at - Now());
  wake_timer_ = nh_.createTimer(
      ros::Duration(in), [this](const ros::TimerEvent&) { Tick(); }, /*oneshot=*/true);
}

// ---- the fluents
// ---------------------------------------------------------------------------------

void RplBinding::OnStatus(const spott_msgs::LocalizationStatus& status) {
  if (const std::string problem = conv::StatusProblem(status); !problem.empty()) {
    refusals_->RefuseProblem("localization_status", problem);
    return;
  }
  const double now = Now();
  have_status_ = true;
  executive_.SetFluent(office::kX, rpl::Value::Number(status.estimate.x), now);
  executive_.SetFluent(office::kY, rpl::Value::Number(status.estimate.y), now);
  executive_.SetFluent(office::kO, rpl::Value::Number(status.estimate.theta), now);
  executive_.SetFluent(office::kPosCertainty, rpl::Value::Number(status.certainty), now);
  navigation_->OnPose({status.estimate.x, status.estimate.y}, now);
  tracking_->OnStatus(now);
  Tick();
}

void RplBinding::OnGraph(const spott_msgs::RoomDoorGraph& graph) {
  if (const std::string problem = conv::GraphProblem(graph); !problem.empty()) {
    refusals_->Refuse("room_door_graph", "rooms/doors", problem);
    return;
  }
  if (graph.rooms.empty() && have_graph_) {
    refusals_->Refuse("room_door_graph", "rooms", "an empty graph would replace the building's");
    return;
  }
  have_graph_ = !graph.rooms.empty();
  navigation_->SetMap(conv::FromMsg(graph));
}

void RplBinding::OnPlaces(const spott_msgs::WorldPlaces& places) {
  if (const std::string problem = spott_map::ros_conversions::PlacesProblem(places);
      !problem.empty()) {
    refusals_->RefuseProblem("world_places", problem);
    return;
  }
  places_.clear();
  for (const spott_msgs::NamedPlace& p : places.places) {
    // Plans write names as strings or symbols; symbols are upper-cased by the reader.
    places_.push_back({p.name, {p.pose.x, p.pose.y}});
    std::string upper = p.name;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (upper != p.name) places_.push_back({upper, {p.pose.x, p.pose.y}});
  }
}

// ---- NAVIGATION through Navigate ----------------------------------------------------------------

void RplBinding::SendGoal(const office::Point& target, double tolerance_m, double) {
  spott_msgs::NavigateGoal goal;
  goal.target = spott_ros::ToPoseStamped(spott_ros::MakePose2D(target.x_m, target.y_m, 0.0),
                                         params_.map_frame, ros::Time::now());
  goal.speed_mode = spott_msgs::NavigateGoal::NORMAL;
  goal.direction_bias = std::numeric_limits<double>::quiet_NaN();
  goal.position_tolerance = tolerance_m;
  goal.heading_tolerance = 0.0;
  goal.ignore_heading = true;
  const int generation = ++nav_generation_;
  if (!navigate_.isServerConnected()) {
    // Reported after this Step (the module must not hear back inside Activate twice).
    deferred_.push_back([this, generation] {
      if (generation != nav_generation_) return;
      navigation_->OnGoalDone(
          office::GoalOutcome::kFailed,
          "the Navigate server '" + params_.navigate_action + "' is not running", Now());
    });
    return;
  }
  nav_goal_ = goal;
  PublishNavigate();
}

void RplBinding::PublishNavigate() {
  const int generation = nav_generation_;
  spott_ros::MarkGoalSent(nav_ack_);
  navigate_.sendGoal(nav_goal_, [this, generation](const actionlib::SimpleClientGoalState& s,
                                                   const spott_msgs::NavigateResultConstPtr& r) {
    Post([this, generation, s, r] { OnNavigateDone(generation, s, r); });
  });
}

void RplBinding::Post(std::function<void()> fn) {
  posted_.push_back(std::move(fn));
  post_timer_ = nh_.createSteadyTimer(
      ros::WallDuration(1e-4),
      [this](const ros::SteadyTimerEvent&) {
        while (!posted_.empty()) {
          std::function<void()> next = std::move(posted_.front());
          posted_.pop_front();
          next();
        }
      },
      true);
}

void RplBinding::CancelGoal(double) {
  ++nav_generation_;  // a result that still comes belongs to the cancelled goal
  nav_ack_.Stop();
  if (navigate_.isServerConnected()) navigate_.cancelGoal();
}

void RplBinding::OnNavigateDone(int generation, const actionlib::SimpleClientGoalState& state,
                                const spott_msgs::NavigateResultConstPtr& result) {
  if (generation != nav_generation_) return;
  office::GoalOutcome outcome = office::GoalOutcome::kFailed;
  std::string reason = result ? result->reason : "";
  if (result) {
    switch (result->outcome) {
      case spott_msgs::NavigateResult::SUCCEEDED:
        outcome = state == actionlib::SimpleClientGoalState::SUCCEEDED
                      ? office::GoalOutcome::kSucceeded
                      : office::GoalOutcome::kFailed;
        break;
      case spott_msgs::NavigateResult::UNREACHABLE:
        outcome = office::GoalOutcome::kUnreachable;
        break;
      case spott_msgs::NavigateResult::PREEMPTED:
        outcome = office::GoalOutcome::kPreempted;
        if (reason.empty()) reason = "preempted by another Navigate client";
        break;
      default:
        outcome = office::GoalOutcome::kFailed;
    }
  }
  if (reason.empty() && outcome != office::GoalOutcome::kSucceeded) {
    reason = "Navigate ended " + state.toString() +
             (state.getText().empty() ? "" : ": " + state.getText());
  }
  navigation_->OnGoalDone(outcome, reason, Now());
  Tick();
}

// ---- ACTIVE-LOCALIZATION through markov_localization
// ----------------------------------------------

void RplBinding::Start(bool uniform_start, double certainty_threshold, double timeout_s, double) {
  const int generation = ++active_generation_;
  // In this order, after the Step: the uniform belief (/global_localization), then the action.
  deferred_.push_back([this, generation, uniform_start, certainty_threshold, timeout_s] {
    if (generation != active_generation_) return;
    if (uniform_start) {
      std_srvs::Empty e;
      if (!global_.waitForExistence(ros::Duration(params_.service_timeout_s)) || !global_.call(e)) {
        ROS_WARN("rpl_executive: %s failed: ActiveLocalize starts from the current belief",
                 params_.global_localization_service.c_str());
      }
    }
    if (!active_.isServerConnected()) {
      localization_->OnDone(
          false,
          "the ActiveLocalize server '" + params_.active_localize_action + "' is not running",
          Now());
      return;
    }
    spott_msgs::ActiveLocalizeGoal goal;
    goal.certainty_threshold = certainty_threshold;
    goal.timeout = timeout_s;
    goal.start_uniform = false;  // done above through /global_localization
    active_.sendGoal(goal, [this, generation](const actionlib::SimpleClientGoalState& s,
                                              const spott_msgs::ActiveLocalizeResultConstPtr& r) {
      Post([this, generation, s, r] { OnActiveDone(generation, s, r); });
    });
  });
}

void RplBinding::Cancel(double) {
  ++active_generation_;
  if (active_.isServerConnected()) active_.cancelGoal();
}

void RplBinding::OnActiveDone(int generation, const actionlib::SimpleClientGoalState& state,
                              const spott_msgs::ActiveLocalizeResultConstPtr& result) {
  if (generation != active_generation_) return;
  const bool success = result && result->success;
  std::string reason = result ? result->reason : "";
  if (reason.empty() && !success) reason = "ActiveLocalize ended " + state.toString();
  localization_->OnDone(success, reason, Now());
  Tick();
}

// ---- travel modes
// --------------------------------------------------------------------------------

void RplBinding::SetTravelMode(office::TravelMode mode, const std::string& region, double) {
  mode_ = mode;
  spott_msgs::SetSpeedLimits s;
  const auto& t = params_.travel;
  switch (mode) {
    case office::TravelMode::kOffice:
      s.request.max_linear_mps = t.office_max_linear_mps;
      s.request.max_angular_rps = t.office_max_angular_rps;
      s.request.reason = "office" + (region.empty() ? "" : " " + region) + ": slow";
      break;
    case office::TravelMode::kHallway:
      s.request.max_linear_mps = t.hallway_max_linear_mps;
      s.request.max_angular_rps = t.hallway_max_angular_rps;
      s.request.reason = "hallway" + (region.empty() ? "" : " " + region) + ": fast";
      break;
    case office::TravelMode::kDoorway:
      s.request.max_linear_mps = t.doorway_max_linear_mps;
      s.request.max_angular_rps = t.doorway_max_angular_rps;
      s.request.reason = "doorway" + (region.empty() ? "" : " " + region) + ": slow" +
                         (t.doorway_sonars_off ? ", sonars off" : "");
      break;
    case office::TravelMode::kNone:
      s.request.reason = "";
      break;
  }
  deferred_.push_back([this, s]() mutable {
    if (!limits_.exists()) return;  // no arbiter: nothing to limit
    if (!limits_.call(s) || !s.response.success) {
      ROS_WARN("rpl_executive: set_speed_limits (%s) failed: %s", s.request.reason.c_str(),
               s.response.message.c_str());
    }
  });
  const bool off = mode == office::TravelMode::kDoorway && t.doorway_sonars_off;
  if (off != sonars_off_) deferred_.push_back([this, off] { SwitchSonars(!off); });
  sonars_off_ = off;
}

void RplBinding::SwitchSonars(bool on) {
  std_srvs::SetBool b;
  b.request.data = on;
  if (!sonar_.exists()) {
    ROS_WARN_THROTTLE(10.0, "rpl_executive: no %s service: sonars stay %s",
                      params_.enable_sonar_service.c_str(), on ? "on" : "as they are");
    return;
  }
  if (!sonar_.call(b) || !b.response.success) {
    ROS_WARN("rpl_executive: %s %s failed: %s", params_.enable_sonar_service.c_str(),
             on ? "true" : "false", b.response.message.c_str());
  }
}

std::string RplBinding::travel_mode() const { return office::TravelModeName(mode_); }

// ---- WHEELS through the arbiter
// ------------------------------------------------------------------

void RplBinding::SyncWheels() {
  if (seized_) return;  // the outside holder has them; ours come back when it releases
  const bool want = !executive_.ValveHolder(office::kWheels).empty();
  if (want == have_wheels_) return;
  have_wheels_ = want;
  if (want) {
    deferred_.push_back([this] {
      spott_msgs::TakeWheels t;
      t.request.source = params_.wheels_source;
      if (!take_.call(t) || !t.response.success) {
        ROS_WARN("rpl_executive: take_wheels as '%s' failed: %s", params_.wheels_source.c_str(),
                 t.response.message.c_str());
      }
    });
  } else {
    deferred_.push_back([this] {
      spott_msgs::ReleaseWheels r;
      r.request.source = params_.wheels_source;
      if (!release_.call(r) || !r.response.success) {
        ROS_WARN("rpl_executive: release_wheels failed: %s", r.response.message.c_str());
      }
    });
  }
}

void RplBinding::OnArbiter(const spott_msgs::ArbiterStatus& status) {
  const double now = Now();
  const std::string& holder = status.exclusive_holder;
  if (have_wheels_ && !seized_ && !holder.empty() && holder != params_.wheels_source) {
    // A source above ours took the wheels: the plan's holder is pre-empted (its modules stop).
    int priority = 0, ours = 0;
    for (const auto& s : status.sources) {
      if (s.name == holder) priority = s.priority;
      if (s.name == params_.wheels_source) ours = s.priority;
    }
    if (priority > ours) {
      seized_ = true;
      executive_.SeizeValve(office::kWheels, "arbiter source " + holder, now);
      Tick();
    }
  } else if (seized_ && holder == params_.wheels_source) {
    seized_ = false;
    executive_.ReturnValve(office::kWheels, now);
    Tick();
  }
}

void RplBinding::Relay(const geometry_msgs::Twist& cmd, bool wander) {
  if (const std::string problem = conv::TwistProblem(cmd); !problem.empty()) {
    refusals_->Refuse(wander ? params_.wander_cmd_topic : params_.planner_cmd_topic,
                      "linear/angular", problem);
    return;
  }
  if (!have_wheels_ || seized_) return;
  const bool drives =
      wander ? localization_->active() : (navigation_->active() || localization_->active());
  if (drives) cmd_pub_.publish(cmd);
}

void RplBinding::RunDeferred() {
  while (!deferred_.empty()) {
    auto call = std::move(deferred_.front());
    deferred_.pop_front();
    call();
  }
}

// ---- feedback
// ------------------------------------------------------------------------------------

std::vector<spott_msgs::PlanTask> RplBinding::Tasks() const {
  std::vector<spott_msgs::PlanTask> tasks = conv::ToMsgs(executive_.TaskTree(), file_);
  tasks.insert(tasks.end(), ended_.begin(), ended_.end());
  return tasks;
}

std::vector<spott_msgs::Fluent> RplBinding::Fluents() const {
  std::vector<spott_msgs::Fluent> out;
  for (const rpl::FluentState& f : executive_.Fluents()) out.push_back(conv::ToMsg(f));
  return out;
}

std::vector<std::string> RplBinding::TakeEvents() {
  std::vector<std::string> out;
  out.swap(events_);
  return out;
}

}  // namespace rpl_executive
