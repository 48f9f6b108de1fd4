// The RPL executive on the stack (Beetz et al. section 3, issue 17): the office robot's behaviour
// modules (office_modules.h) bound to Navigate, markov_localization's ActiveLocalize and
// /global_localization, the wheels arbiter, world_server's room/door graph and places, and the
// fluents X*, Y*, O*, POS-CERTAINTY* from /localization_status. Glue only: the decisions are the
// core's. Single-threaded: every callback and Tick run in the node's one spinner thread.
//
// WHEELS: while a thread of the plan holds the valve, the arbiter's wheels are taken as the
// executive's source (take_wheels). The modules that hold WHEELS drive through the stack's other
// sources (NAVIGATION's and ACTIVE-LOCALIZATION's Navigate goals are descended by the harmonic
// planner on cmd_vel/planner, the random motion of ACTIVE-LOCALIZATION is on cmd_vel/wander), all
// of lower priority than the executive's: so the executive forwards the motion of the module that
// holds WHEELS onto cmd_vel/executive, and nothing else moves the robot. A source of higher
// priority that takes the wheels (a reflex, tele-operation) pre-empts the plan's holder
// (SeizeValve) until it releases them (ReturnValve).
#pragma once

#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <spott_msgs/ActiveLocalizeAction.h>
#include <spott_msgs/ArbiterStatus.h>
#include <spott_msgs/Fluent.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/NavigateAction.h>
#include <spott_msgs/PlanTask.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <spott_msgs/WorldPlaces.h>

#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "parameters.h"
#include "rpl_executive/rpl/executive.h"
#include "rpl_executive/rpl/office_modules.h"
#include "spott_ros/goal_resend.h"
#include "spott_ros/input_refusals.h"

namespace rpl_executive {

class RplBinding : public rpl::office::NavigateClient,
                   public rpl::office::ActiveLocalizeClient,
                   public rpl::office::TravelModeSwitch {
 public:
  /// `changed` is called after every Tick that ran a step or logged an event.
  /// `refusals` counts the input refused at the node's edge (the node's; outlives this).
  RplBinding(ros::NodeHandle& nh, const ros_parameters::NodeParameters& params,
             spott_ros::InputRefusals* refusals, std::function<void()> changed);
  ~RplBinding() override;

  /// Reads and checks a plan; "" or every error with file:line:column. Refused while one runs.
  std::string Load(const std::string& text, const std::string& file,
                   const std::vector<std::string>& bindings);
  /// Starts the loaded plan with the bindings of Load; "" or why not.
  std::string Start();
  /// Evaporates the plan (cleanups run in the following ticks).
  void Abort();
  /// Runs the executive: Step, the modules' deferred work, the wheels, the service calls.
  void Tick();

  rpl::PlanState state() const { return executive_.state(); }
  bool running() const { return executive_.state() == rpl::PlanState::kRunning; }
  /// Why the plan failed ("" when it did not).
  std::string FailureText() const;
  const std::string& file() const { return file_; }

  // ---- what the feedback and the state topic carry ----
  /// The live task tree, then the most recent threads that ended.
  std::vector<spott_msgs::PlanTask> Tasks() const;
  std::vector<spott_msgs::Fluent> Fluents() const;
  /// Events since the last call.
  std::vector<std::string> TakeEvents();
  std::string travel_mode() const;

  // ---- module clients (called by the core's modules inside Step) ----
  void SendGoal(const rpl::office::Point& target, double tolerance_m, double now_s) override;
  void CancelGoal(double now_s) override;
  void Start(bool uniform_start, double certainty_threshold, double timeout_s,
             double now_s) override;
  void Cancel(double now_s) override;
  void SetTravelMode(rpl::office::TravelMode mode, const std::string& region,
                     double now_s) override;

 private:
  using NavigateClientT = actionlib::SimpleActionClient<spott_msgs::NavigateAction>;
  using ActiveClientT = actionlib::SimpleActionClient<spott_msgs::ActiveLocalizeAction>;

  double Now() const { return ros::Time::now().toSec(); }
  void OnStatus(const spott_msgs::LocalizationStatus& status);
  void OnGraph(const spott_msgs::RoomDoorGraph& graph);
  void OnPlaces(const spott_msgs::WorldPlaces& places);
  void OnArbiter(const spott_msgs::ArbiterStatus& status);
  void OnNavigateDone(int generation, const actionlib::SimpleClientGoalState& state,
                      const spott_msgs::NavigateResultConstPtr& result);
  void OnActiveDone(int generation, const actionlib::SimpleClientGoalState& state,
                    const spott_msgs::ActiveLocalizeResultConstPtr& result);
  void Relay(const geometry_msgs::Twist& cmd, bool wander);
  void SyncWheels();
  /// The localization's sonar readings on or off (the doorway travel mode).
  void SwitchSonars(bool on);
  void RunDeferred();
  void ArmWakeUp();
  /// Runs `fn` from the spinner once the current callback has returned. A SimpleActionClient's
  /// done callback must not lead to a new goal on that client: this actionlib version marks the
  /// client DONE after the callback, so a goal sent inside it would never report its result
  /// ("BUG: Got a transition to CommState [ACTIVE] when in SimpleGoalState [DONE]").
  void Post(std::function<void()> fn);
  /// Sends nav_goal_ for generation nav_generation_ (again, when actionlib lost it).
  void PublishNavigate();

  ros_parameters::NodeParameters params_;
  std::function<void()> changed_;
  ros::NodeHandle nh_;
  spott_ros::InputRefusals* refusals_;
  bool have_graph_ = false;  // a non-empty room/door graph was taken
  rpl::Executive executive_;
  std::shared_ptr<rpl::office::NavigationModule> navigation_;
  std::shared_ptr<rpl::office::ActiveLocalizationModule> localization_;
  std::shared_ptr<rpl::office::PositionTrackingModule> tracking_;
  std::string file_;
  std::vector<std::pair<std::string, rpl::Value>> globals_;

  NavigateClientT navigate_;
  ActiveClientT active_;
  int nav_generation_ = 0, active_generation_ = 0;
  spott_msgs::NavigateGoal nav_goal_;  ///< The last goal sent, kept to send it again.
  spott_ros::GoalAckWatch nav_ack_;
  ros::ServiceClient take_, release_, limits_, global_, sonar_;
  ros::Subscriber status_sub_, graph_sub_, places_sub_, arbiter_sub_, planner_sub_, wander_sub_;
  ros::Publisher cmd_pub_;
  ros::Timer wake_timer_, watchdog_timer_;
  ros::SteadyTimer post_timer_;
  std::deque<std::function<void()>> posted_;

  bool have_wheels_ = false;  // the arbiter's wheels are taken as wheels_source
  bool have_status_ = false;  // a localization status came: the plan's pose fluents hold values
  bool seized_ = false;       // a source above ours holds them: the plan's valve is seized
  std::deque<std::function<void()>> deferred_;  // service calls, after the Step that asked
  std::vector<std::string> events_;
  std::deque<spott_msgs::PlanTask> ended_;
  bool event_logged_ = false;
  std::vector<std::pair<std::string, rpl::office::Point>> places_;
  rpl::office::TravelMode mode_ = rpl::office::TravelMode::kNone;
  bool sonars_off_ = false;  // asked the localization to leave its sonar readings out
};

}  // namespace rpl_executive
