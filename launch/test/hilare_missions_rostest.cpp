// Noreils and Chatila's missions (section 6.2) end to end on HILARE in hilare_room: the stack
// (stack.launch world:=hilare_room, markov_localization on the 16 sonars, the arbiter) and
// rpl_executive running the shipped missions through /mission, judged on the simulator's ground
// truth. One case per branch, run in order on one stack; before each the robot is put at the
// case's start (/sim/kidnap, which the odometry does not see, and /initialpose for the
// localization, as an operator would) and the case's obstacle is placed (/sim/add_obstacle):
//
//   example1             Example 1: smooth-move to the east wall until the belt perceives it as a
//                        line 80 cm ahead, then wall following on the right at 25 cm until the
//                        goal line y = 7 m is crossed.
//   zone_first           Example 2, no obstacle: S1 (zone entered) slows to 20 cm/s, LOA off, the
//                        echoes are drawn while inside, S1-2 (zone left) speeds up; success.
//   zone_first_obstacle  Example 2, an obstacle on PATH inside ZONE109: S1, then the static S2
//                        with LOA NIL: FAIL, the mission aborts.
//   obstacle_first       Example 2, an obstacle across PATH at the zone's border: S2 first,
//                        avoid-obstacle (LOA T) carries the robot into the zone, S1 sets LOA NIL,
//                        the executive stops the avoidance (its ENV no longer holds), S2 fires
//                        again (static, the obstacle is still there): FAIL.
//   avoidance_before_zone  Example 2, someone on PATH who walks away once the robot stopped: S2,
//                        avoid-obstacle finishes before the zone, resume-order, S1, S1-2; success.
//   bad_messages         Issue 21: a sonar ring without a usable max range, one with a mount that
//                        is not finite, a localization status that is not finite and places with
//                        a path that is not are refused by rpl_executive (counted on
//                        /diagnostics); Example 2's zone mission then runs as before.
//
// ~report_file ("" = none): one line per case for rpl_executive/scripts/run_hilare_missions.sh.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <spott_msgs/AddObstacle.h>
#include <spott_msgs/Kidnap.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/RangeRing.h>
#include <spott_msgs/RemoveObstacle.h>
#include <spott_msgs/WorldPlaces.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "executive_test_support.h"
#include "node_refusals.h"
#include "spott_ros/pose_conversions.h"

namespace {

using spott_launch::testing::ExecutiveEvents;
using spott_launch::testing::MissionClient;
using spott_launch::testing::Truth;
using spott_launch::testing::WaitUntil;

constexpr double kEastWallFace = 7.925;  // x of the room's east wall face (wall 0.15 m at x = 8)
constexpr double kHilareRadius = 0.40;   // the belt (robot_sim/urdf/hilare.urdf)

const char* kIn = "(S_zone IN ZONE109)";
const char* kOut = "(S_zone OUT ZONE109)";
const char* kObstacle = "(S_us-threshold sensors-list)";

struct Obstacle {
  std::string kind;
  double x, y, yaw, sx, sy;
};

struct MissionRun {
  std::string outcome, message;
  bool success = false;
  std::vector<std::string> fired;  // conditions, in order
  std::vector<double> fired_at;    // sim s
  double start = 0, end = 0, wall = 0;
  int contacts = 0;
};

// Samples of the ground truth during a run: (sim s, x, y, speed m/s).
struct Sample {
  double t, x, y, speed;
};

class HilareMissions : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    spinner_ = new ros::AsyncSpinner(2);
    spinner_->start();
  }
  // Stopped before the process exits: a spinner thread still running while roscpp's statics
  // are destroyed aborted the process (boost::lock_error) after the results were written.
  static void TearDownTestSuite() {
    spinner_->stop();
    delete spinner_;
    spinner_ = nullptr;
  }

  void SetUp() override {
    pnh_.getParam("report_file", report_file_);
    ros::param::get("/robot_sim/seed", seed_);
    truth_ = std::make_unique<Truth>(nh_);
    events_ = std::make_unique<ExecutiveEvents>(nh_);
    mission_ = std::make_unique<MissionClient>("mission", true);
    status_sub_ = nh_.subscribe("/localization_status", 10, &HilareMissions::OnStatus, this);
    truth_sub_ = nh_.subscribe("/sim/ground_truth", 50, &HilareMissions::OnTruth, this);
    markers_sub_ = nh_.subscribe("/rpl_executive/markers", 100, &HilareMissions::OnMarkers, this);
    initial_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("/initialpose", 1, true);
    ASSERT_TRUE(mission_->waitForServer(ros::Duration(60.0)));
    ASSERT_TRUE(WaitUntil([&] { return truth_->seen(); }, 60.0));
    ASSERT_TRUE(WaitUntil(
        [&] {
          return events_->state() == "idle" || events_->state() == "succeeded" ||
                 events_->state() == "failed";
        },
        60.0))
        << "rpl_executive is not ready for missions: " << events_->state();
  }
  void TearDown() override {
    ros::ServiceClient remove =
        nh_.serviceClient<spott_msgs::RemoveObstacle>("/sim/remove_obstacle");
    for (const std::string& id : obstacles_) {
      spott_msgs::RemoveObstacle r;
      r.request.id = id;
      remove.call(r);
    }
  }

  // The robot to (x, y, yaw), in the simulator and, like an operator would, in the localization.
  void Place(double x, double y, double yaw) {
    ros::ServiceClient kidnap = nh_.serviceClient<spott_msgs::Kidnap>("/sim/kidnap");
    ASSERT_TRUE(kidnap.waitForExistence(ros::Duration(20.0)));
    spott_msgs::Kidnap k;
    k.request.relative = false;
    k.request.pose = spott_ros::MakePose2D(x, y, yaw);
    ASSERT_TRUE(kidnap.call(k) && k.response.success) << k.response.message;
    geometry_msgs::PoseWithCovarianceStamped p;
    p.header.frame_id = "map";
    p.header.stamp = ros::Time::now();
    p.pose.pose = spott_ros::ToPose(spott_ros::MakePose2D(x, y, yaw));
    p.pose.covariance[0] = p.pose.covariance[7] = 0.01;
    p.pose.covariance[35] = 0.01;
    initial_pub_.publish(p);
    // Settled: the localization certain within 10 cm of the place.
    ASSERT_TRUE(WaitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          return certainty_ > 0.8 && std::hypot(est_x_ - x, est_y_ - y) < 0.1;
        },
        60.0))
        << "the localization did not settle at (" << x << ", " << y << ")";
    ros::Duration(1.0).sleep();  // simulated: a few more scans
  }

  void Add(const Obstacle& o) {
    ros::ServiceClient add = nh_.serviceClient<spott_msgs::AddObstacle>("/sim/add_obstacle");
    ASSERT_TRUE(add.waitForExistence(ros::Duration(20.0)));
    spott_msgs::AddObstacle a;
    a.request.kind = o.kind;
    a.request.pose = spott_ros::MakePose2D(o.x, o.y, o.yaw);
    a.request.size.x = o.sx;
    a.request.size.y = o.sy;
    a.request.size.z = 1.0;  // above the belt (0.3 m)
    ASSERT_TRUE(add.call(a) && a.response.success) << a.response.message;
    obstacles_.push_back(a.response.id);
  }

  // `during` is called every 20 ms of wall time while the mission runs (a test's moving obstacle).
  MissionRun RunMission(const std::string& name, double timeout_s,
                        const std::function<void()>& during = {}) {
    MissionRun r;
    events_->Clear();
    truth_->ResetContacts();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      samples_.clear();
      markers_ = 0;
      max_estimate_error_ = 0;
    }
    spott_msgs::MissionGoal goal;
    goal.language = spott_msgs::MissionGoal::NOREILS_CHATILA;
    goal.name = name;
    const ros::WallTime wall = ros::WallTime::now();
    bool done = false;
    for (int attempt = 0; attempt < 30; ++attempt) {  // HILARE's modules wait for the first ring
      r.start = ros::Time::now().toSec();
      mission_->sendGoal(goal);
      const ros::Time until = ros::Time::now() + ros::Duration(timeout_s);
      while (ros::ok() && !(done = mission_->getState().isDone()) && ros::Time::now() < until) {
        if (during) during();
        ros::WallDuration(0.02).sleep();
      }
      const auto early = mission_->getResult();
      if (!done || !early || early->outcome != "rejected" ||
          early->message.find("not ready") == std::string::npos) {
        break;
      }
      ros::WallDuration(1.0).sleep();
    }
    r.end = ros::Time::now().toSec();
    r.wall = (ros::WallTime::now() - wall).toSec();
    ros::Duration(0.5).sleep();
    r.contacts = truth_->contacts();
    const auto result = mission_->getResult();
    if (!done || !result) {
      r.outcome = "timeout";
      r.message = "state: " + events_->last().text_view + " last events:";
      const auto lines = events_->lines();
      for (std::size_t i = lines.size() > 8 ? lines.size() - 8 : 0; i < lines.size(); ++i) {
        r.message += " | " + lines[i];
      }
      mission_->cancelGoal();
      return r;
    }
    r.outcome = result->outcome;
    r.success = result->success;
    r.message = result->message;
    for (const auto& e : result->events) {
      r.fired.push_back(e.condition);
      r.fired_at.push_back(e.header.stamp.toSec());
    }
    return r;
  }

  void Report(const std::string& branch, const MissionRun& r, const std::string& extra) {
    std::ostringstream line;
    line.precision(4);
    line << "branch=" << branch << " seed=" << seed_ << " outcome=" << r.outcome
         << " success=" << r.success << " sim_s=" << r.end - r.start << " wall_s=" << r.wall
         << " contacts=" << r.contacts << " max_estimate_error_m=" << max_estimate_error_
         << " fired=";
    for (std::size_t i = 0; i < r.fired.size(); ++i) {
      line << (i ? "," : "") << r.fired[i] << "@" << r.fired_at[i] - r.start;
    }
    line << " " << extra;
    std::string s = line.str();
    std::string msg = r.message.substr(0, r.outcome == "timeout" ? 2000 : 200);
    for (char& c : msg) {
      if (c == '\n') c = ' ';
    }
    s += " message=\"" + msg + "\"";
    spott_launch::testing::AppendReport(report_file_, s);
    std::printf("%s\n", s.c_str());
  }

  std::vector<Sample> Samples() {
    std::lock_guard<std::mutex> lock(mutex_);
    return samples_;
  }
  int markers() {
    std::lock_guard<std::mutex> lock(mutex_);
    return markers_;
  }

  static ros::AsyncSpinner* spinner_;
  ros::NodeHandle nh_, pnh_{"~"};
  std::unique_ptr<Truth> truth_;
  std::unique_ptr<ExecutiveEvents> events_;
  std::unique_ptr<MissionClient> mission_;
  std::string report_file_;
  int seed_ = 0;
  std::vector<std::string> obstacles_;

 private:
  void OnStatus(const spott_msgs::LocalizationStatus& s) {
    std::lock_guard<std::mutex> lock(mutex_);
    certainty_ = s.certainty;
    est_x_ = s.estimate.x;
    est_y_ = s.estimate.y;
    if (!samples_.empty()) {
      max_estimate_error_ = std::max(
          max_estimate_error_, std::hypot(est_x_ - samples_.back().x, est_y_ - samples_.back().y));
    }
  }
  void OnTruth(const nav_msgs::Odometry& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    samples_.push_back({m.header.stamp.toSec(), m.pose.pose.position.x, m.pose.pose.position.y,
                        std::fabs(m.twist.twist.linear.x)});
  }
  void OnMarkers(const visualization_msgs::MarkerArray& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& marker : m.markers) markers_ += marker.ns == "draw/G_echoes";
  }
  std::mutex mutex_;
  double certainty_ = 0, est_x_ = 0, est_y_ = 0;
  std::vector<Sample> samples_;
  int markers_ = 0;

 protected:
  double max_estimate_error_ = 0;  // the localization against the truth during the mission (m)

 private:
  ros::Subscriber status_sub_, truth_sub_, markers_sub_;
  ros::Publisher initial_pub_;
};
ros::AsyncSpinner* HilareMissions::spinner_ = nullptr;

TEST_F(HilareMissions, Example1SmoothMoveUntilTheWallIsPerceivedThenWallFollowingToTheGoalLine) {
  Place(6.0, 2.5, 0.0);  // wall_follow_start, heading east
  const MissionRun r = RunMission("example1_wall_following", 150.0);
  // The wall perceived: where the robot was when the perception monitor fired (ground truth).
  double perceived_m = -1;
  std::vector<double> gaps;
  for (const Sample& s : Samples()) {
    if (perceived_m < 0 && !r.fired_at.empty() && s.t >= r.fired_at[0]) {
      perceived_m = kEastWallFace - s.x;
    }
    // Followed: the belt's gap to the wall once the robot runs along it.
    if (r.fired_at.size() >= 1 && s.t > r.fired_at[0] && s.y > 4.0 && s.y < 6.5) {
      gaps.push_back(kEastWallFace - s.x - kHilareRadius);
    }
  }
  double mean = 0, worst = 0;
  for (double g : gaps) mean += g / gaps.size();
  for (double g : gaps) worst = std::max(worst, std::fabs(g - 0.25));
  double x, y, yaw;
  truth_->Pose(&x, &y, &yaw);
  std::ostringstream extra;
  extra.precision(3);
  const bool as_paper = r.outcome == "completed" && r.fired.size() == 2 && perceived_m > 0.7 &&
                        perceived_m < 0.93 && std::fabs(mean - 0.25) <= 0.03 && y > 6.9;
  extra << "as_paper=" << as_paper << " perceived_m=" << perceived_m << " gap_mean_m=" << mean
        << " gap_worst_dev_m=" << worst << " end_y=" << y;
  Report("example1", r, extra.str());
  ASSERT_EQ(r.outcome, "completed") << r.message;
  ASSERT_EQ(r.fired, (std::vector<std::string>{"(S_us-perception line (ρ θ))",
                                               "(S_straight-line (x y φ))"}));
  // rho = 80 cm within rho_tolerance_m (10 cm), plus up to one scan of travel (3 cm).
  EXPECT_GT(perceived_m, 0.7);
  EXPECT_LT(perceived_m, 0.93);
  ASSERT_GT(gaps.size(), 20u);
  EXPECT_NEAR(mean, 0.25, 0.03);
  EXPECT_LT(worst, 0.06);
  EXPECT_GT(y, 6.9);  // crossed the goal line y = 7 m (the estimate's), the robot stopped there
  EXPECT_EQ(r.contacts, 0);
}

TEST_F(HilareMissions, Example2ZoneEnteredFirstSlowsDrawsAndSpeedsUpOnLeaving) {
  Place(0.8, 5.2, 0.0);  // robot_start
  const MissionRun r = RunMission("example2_zone_surveillance", 150.0);
  // Speeds on the ground truth: inside the zone once the robot has slowed down (1.5 s after S1),
  // and after it left (S1-2). The tracking law adds k_x e_x to the set speed, so the maximum may
  // exceed it a little; the median is the set speed (the corner's turn slows it below).
  double in_zone_max = 0, after_max = 0;
  std::vector<double> in_zone;
  if (r.fired_at.size() >= 2) {
    for (const Sample& s : Samples()) {
      if (s.t > r.fired_at[0] + 1.5 && s.t < r.fired_at[1]) {
        in_zone_max = std::max(in_zone_max, s.speed);
        in_zone.push_back(s.speed);
      }
      if (s.t > r.fired_at[1]) after_max = std::max(after_max, s.speed);
    }
  }
  std::sort(in_zone.begin(), in_zone.end());
  const double in_zone_median = in_zone.empty() ? 0.0 : in_zone[in_zone.size() / 2];
  const int drawn = markers();
  std::ostringstream extra;
  extra.precision(3);
  const bool as_paper =
      r.outcome == "completed" && r.fired == std::vector<std::string>{kIn, kOut} &&
      std::fabs(in_zone_median - 0.2) < 0.02 && in_zone_max < 0.25 && after_max > 0.3 && drawn > 10;
  extra << "as_paper=" << as_paper << " in_zone_median_mps=" << in_zone_median
        << " in_zone_max_mps=" << in_zone_max << " after_max_mps=" << after_max
        << " echo_drawings=" << drawn;
  Report("zone_first", r, extra.str());
  ASSERT_EQ(r.outcome, "completed") << r.message;
  ASSERT_EQ(r.fired, (std::vector<std::string>{kIn, kOut}));
  EXPECT_NEAR(in_zone_median, 0.2, 0.02) << "set-speed 20";
  EXPECT_LT(in_zone_max, 0.25);
  EXPECT_GT(after_max, 0.3) << "set-speed 50 (HILARE's 0.4 m/s)";
  EXPECT_GT(drawn, 10) << "read-all-us-data and draw while in the zone";
  EXPECT_EQ(r.contacts, 0);
}

TEST_F(HilareMissions, Example2AnObstacleInTheZoneMakesTheMissionFail) {
  Place(0.8, 5.2, 0.0);
  Add({"cylinder", 2.8, 5.2, 0.0, 0.3, 0.3});
  const MissionRun r = RunMission("example2_zone_surveillance", 150.0);
  double x, y, yaw;
  truth_->Pose(&x, &y, &yaw);
  const double gap = std::hypot(x - 2.8, y - 5.2) - 0.15 - kHilareRadius;
  std::ostringstream extra;
  extra.precision(3);
  const bool as_paper =
      r.outcome == "failed" && r.fired == std::vector<std::string>{kIn, kObstacle} &&
      r.message.find("FAIL in the control action of MNTR STATIC") != std::string::npos;
  extra << "as_paper=" << as_paper << " stopped_gap_m=" << gap;
  Report("zone_first_obstacle", r, extra.str());
  ASSERT_EQ(r.outcome, "failed") << r.message;
  ASSERT_EQ(r.fired, (std::vector<std::string>{kIn, kObstacle}));
  EXPECT_NE(r.message.find("FAIL in the control action of MNTR STATIC (S_us-threshold "
                           "sensors-list)"),
            std::string::npos)
      << r.message;
  EXPECT_EQ(events_->Count("[operator (1)] avoid-obstacle"), 0);
  EXPECT_GT(gap, 0.05);
  EXPECT_EQ(r.contacts, 0);
}

TEST_F(HilareMissions, Example2ObstacleFirstAvoidanceIntoTheZoneIsStoppedAndTheStaticMonitorFails) {
  Place(0.8, 5.2, 0.0);
  // A partition across PATH at the zone's border, reaching further north than south: the
  // avoidance turns south (the freer side), the partition stays ahead and to the left.
  Add({"cuboid", 2.35, 5.55, 0.0, 0.2, 1.3});
  const MissionRun r = RunMission("example2_zone_surveillance", 150.0);
  const bool env_stop = events_->Count("does not hold") > 0;
  std::ostringstream extra;
  const bool as_paper =
      r.outcome == "failed" && r.fired == std::vector<std::string>{kObstacle, kIn, kObstacle} &&
      env_stop && r.message.find("FAIL in the control action of MNTR STATIC") != std::string::npos;
  extra << "as_paper=" << as_paper << " env_stop=" << env_stop
        << " avoid_obstacle=" << events_->Count("[operator (1)] avoid-obstacle");
  Report("obstacle_first", r, extra.str());
  ASSERT_EQ(r.outcome, "failed") << r.message;
  ASSERT_EQ(r.fired, (std::vector<std::string>{kObstacle, kIn, kObstacle}));
  EXPECT_TRUE(env_stop) << "the executive stopped avoid-obstacle (LOA T no longer holds)";
  EXPECT_NE(r.message.find("FAIL in the control action of MNTR STATIC"), std::string::npos)
      << r.message;
  EXPECT_EQ(r.contacts, 0);
}

TEST_F(HilareMissions, Example2AvoidanceFinishingBeforeTheZoneResumesTheOrderAndSucceeds) {
  // Someone stands on PATH just inside the zone and walks away once the robot has stopped for
  // them ("an obstacle avoidance has terminated, or the obstacle moved away", section 4.2): the
  // robot, still outside the zone, sees them first (S2), avoids, finds nothing left to avoid
  // before the zone, resumes the order, then enters and leaves the zone.
  Place(0.8, 5.2, 0.0);
  Add({"cylinder", 2.15, 5.2, 0.0, 0.3, 0.3});
  double seen_at = -1;
  bool removed = false;
  double removed_robot_x = 0;
  const MissionRun r = RunMission("example2_zone_surveillance", 150.0, [&] {
    if (removed) return;
    if (seen_at < 0) {
      for (const auto& m : events_->monitors()) {
        if (m.condition == kObstacle) seen_at = ros::Time::now().toSec();
      }
      return;
    }
    if (ros::Time::now().toSec() < seen_at + 1.0) return;  // the robot is avoiding them
    ros::ServiceClient remove =
        nh_.serviceClient<spott_msgs::RemoveObstacle>("/sim/remove_obstacle");
    spott_msgs::RemoveObstacle rm;
    rm.request.id = obstacles_.back();
    removed = remove.call(rm) && rm.response.success;
    double y, yaw;
    truth_->Pose(&removed_robot_x, &y, &yaw);
  });
  // Where the avoidance finished (ground truth): outside the zone (x < 1.5 m).
  const double resumed_at = events_->TimeOf("(resumed)");
  double resumed_x = -1;
  for (const Sample& s : Samples()) {
    if (resumed_at >= 0 && s.t >= resumed_at) {
      resumed_x = s.x;
      break;
    }
  }
  const bool as_paper = r.outcome == "completed" &&
                        r.fired == std::vector<std::string>{kObstacle, kIn, kOut} &&
                        resumed_at >= 0 && resumed_x < 1.5;
  std::ostringstream extra;
  extra.precision(3);
  extra << "as_paper=" << as_paper << " removed=" << removed << " removed_at_x=" << removed_robot_x
        << " resumed_at_x=" << resumed_x;
  Report("avoidance_before_zone", r, extra.str());
  ASSERT_EQ(r.outcome, "completed") << r.message;
  ASSERT_EQ(r.fired, (std::vector<std::string>{kObstacle, kIn, kOut}));
  EXPECT_GE(resumed_at, 0) << "resume-order";
  EXPECT_LT(resumed_x, 1.5) << "the avoidance finished before the zone";
  EXPECT_EQ(r.contacts, 0);
}

TEST_F(HilareMissions, BadMessagesAreRefusedAndTheNextMissionRunsAsBefore) {
  spott_launch::testing::NodeRefusals refusals(nh_, "rpl_executive");
  ros::Publisher sonar = nh_.advertise<spott_msgs::RangeRing>("/sonar", 5);
  ros::Publisher status = nh_.advertise<spott_msgs::LocalizationStatus>("/localization_status", 5);
  ros::Publisher places = nh_.advertise<spott_msgs::WorldPlaces>("/world_places", 5);
  ASSERT_TRUE(WaitUntil(
      [&] {
        return sonar.getNumSubscribers() > 0 && status.getNumSubscribers() > 0 &&
               places.getNumSubscribers() > 0;
      },
      20.0));
  spott_msgs::RangeRing blind = spott_launch::testing::BlindRing(0.44f, 0.15f, 16);
  spott_msgs::RangeRing skewed = blind;  // a mount that is not finite
  skewed.max_range = 6.5f;
  skewed.mounts[3].theta = std::nan("");
  spott_msgs::LocalizationStatus lost_in_nan;
  lost_in_nan.estimate.x = std::nan("");
  lost_in_nan.certainty = 0.99;
  spott_msgs::WorldPlaces bad_places;
  spott_msgs::NamedPath path;
  path.id = "PATH";
  path.points.resize(2);
  path.points[1].y = std::nan("");
  bad_places.paths.push_back(path);
  ASSERT_TRUE(WaitUntil(
      [&] {
        const ros::Time now = ros::Time::now();
        blind.header.stamp = skewed.header.stamp = lost_in_nan.header.stamp = now;
        sonar.publish(blind);
        sonar.publish(skewed);
        status.publish(lost_in_nan);
        places.publish(bad_places);
        return refusals.Has("sonar max_range") && refusals.Has("sonar mounts[3]") &&
               refusals.Has("localization_status estimate") &&
               refusals.Has("world_places paths[0].points");
      },
      30.0))
      << "rpl_executive did not count every bad message on /diagnostics";
  EXPECT_NE(refusals.Value("sonar max_range").find("is not in (0, 1000) m"), std::string::npos);
  // Nothing changed: the zone mission goes as in Example2ZoneEnteredFirst...
  Place(0.8, 5.2, 0.0);
  const MissionRun r = RunMission("example2_zone_surveillance", 150.0);
  Report("bad_messages", r, "");
  ASSERT_EQ(r.outcome, "completed") << r.message;
  EXPECT_EQ(r.fired, (std::vector<std::string>{kIn, kOut}));
  EXPECT_EQ(r.contacts, 0);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "hilare_missions_rostest");
  return RUN_ALL_TESTS();
}
