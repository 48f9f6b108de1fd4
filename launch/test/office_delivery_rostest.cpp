// The office delivery of Beetz, Burgard, Fox and Cremers (section 4) end to end: the whole stack
// in bonn_department with the B21 and rpl_executive running plans/office_delivery.rpl. The robot
// starts at the east end of the hallway; the destination is in front of Wolfram's shelf in room B;
// shortly after the start it is turned about 70 degrees to the right (/sim/kidnap, which the
// odometry does not see). Asserted, on the simulator's ground truth where it matters: the tracker
// does not notice at once; its certainty falls to 0.8 or below; EXECUTION-INTERRUPTED? pulses and
// the navigation's target points are removed; active localization runs; a new navigation plan
// starts from the relocalized pose; the robot ends within 0.5 m of the destination (truth).
//
// Parameters (~): kidnap_after_s (sim s after the plan started, 5), kidnap_rad (-1.22),
// timeout_s (sim s for the whole mission, 600), report_file ("" = none): one line per run for
// rpl_executive/scripts/run_office_delivery.sh.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <spott_msgs/Kidnap.h>

#include <mutex>
#include <sstream>
#include <vector>

#include "executive_test_support.h"
#include "spott_ros/testing/node_process.h"

namespace {

using spott_launch::testing::ExecutiveEvents;
using spott_launch::testing::MissionClient;
using spott_launch::testing::Truth;
using spott_launch::testing::WaitUntil;

constexpr double kShelfX = 19.6, kShelfY = 6.0;  // wolframs_shelf_front

class Certainty {
 public:
  explicit Certainty(ros::NodeHandle& nh)
      : sub_(nh.subscribe("/localization_status", 50, &Certainty::On, this)) {}
  void WatchFrom(double t) {
    std::lock_guard<std::mutex> lock(mutex_);
    watch_from_ = t;
    fell_at_ = -1;
  }
  double fell_at() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return fell_at_;
  }
  double last() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_;
  }
  double minimum_after_watch() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return min_;
  }

 private:
  void On(const spott_msgs::LocalizationStatus& s) {
    std::lock_guard<std::mutex> lock(mutex_);
    last_ = s.certainty;
    const double t = s.header.stamp.toSec();
    if (watch_from_ >= 0 && t >= watch_from_) {
      min_ = std::min(min_, s.certainty);
      if (fell_at_ < 0 && s.certainty <= 0.8) fell_at_ = t;
    }
  }
  mutable std::mutex mutex_;
  double watch_from_ = -1, fell_at_ = -1, last_ = 0, min_ = 1.0;
  ros::Subscriber sub_;
};

TEST(OfficeDelivery, SurvivesA70DegreeTurnByRelocalizingAndReachesWolframsShelf) {
  ros::NodeHandle nh, pnh("~");
  double kidnap_after_s = 5.0, kidnap_rad = -1.22, timeout_s = 600.0;
  std::string report_file;
  int seed = 0;
  pnh.getParam("kidnap_after_s", kidnap_after_s);
  pnh.getParam("kidnap_rad", kidnap_rad);
  pnh.getParam("timeout_s", timeout_s);
  pnh.getParam("report_file", report_file);
  ros::param::get("/robot_sim/seed", seed);

  Truth truth(nh);
  Certainty certainty(nh);
  // amcl_pose comes with each of the localization's sensor updates, and only then.
  std::mutex updates_mutex;
  std::vector<double> updates;
  ros::Subscriber updates_sub = nh.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
      "/amcl_pose", 100, [&](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(updates_mutex);
        updates.push_back(m->header.stamp.toSec());
      });
  ExecutiveEvents events(nh);
  MissionClient mission("mission", true);
  ASSERT_TRUE(mission.waitForServer(ros::Duration(60.0))) << "no /mission server";
  ASSERT_TRUE(WaitUntil([&] { return truth.seen() && certainty.last() > 0.8; }, 60.0))
      << "the localization never became certain at the start (" << certainty.last() << ")";
  ros::ServiceClient kidnap = nh.serviceClient<spott_msgs::Kidnap>("/sim/kidnap");
  ASSERT_TRUE(kidnap.waitForExistence(ros::Duration(30.0)));

  spott_msgs::MissionGoal goal;
  goal.language = spott_msgs::MissionGoal::RPL;
  goal.name = "office_delivery";
  const ros::WallTime wall_start = ros::WallTime::now();
  const double start = ros::Time::now().toSec();
  mission.sendGoal(goal);

  // Shortly after the start: turned about 70 degrees to the right.
  while (ros::ok() && ros::Time::now().toSec() < start + kidnap_after_s &&
         !mission.getState().isDone()) {
    ros::WallDuration(0.01).sleep();
  }
  ASSERT_FALSE(mission.getState().isDone()) << mission.getState().getText();
  spott_msgs::Kidnap k;
  k.request.relative = true;
  k.request.pose.theta = kidnap_rad;
  const double kidnap_at = ros::Time::now().toSec();
  certainty.WatchFrom(kidnap_at);
  ASSERT_TRUE(kidnap.call(k) && k.response.success) << k.response.message;

  const bool done = mission.waitForResult(ros::Duration(timeout_s));
  const double end = ros::Time::now().toSec();
  const double wall = (ros::WallTime::now() - wall_start).toSec();
  const auto result = mission.getResult();

  // What happened, from the executive's events (times in simulated s).
  const double lost_at = certainty.fell_at();
  const double pulse_at = events.TimeOf("PULSE EXECUTION-INTERRUPTED?", kidnap_at);
  const double removed_at = events.TimeOf("MODULE-DEACTIVATED NAVIGATION", kidnap_at);
  const double active_at = events.TimeOf("MODULE-ACTIVATED ACTIVE-LOCALIZATION", kidnap_at);
  const double relocalized_at = events.TimeOf("MODULE-DEACTIVATED ACTIVE-LOCALIZATION", kidnap_at);
  const double replanned_at =
      relocalized_at < 0 ? -1 : events.TimeOf("MODULE-ACTIVATED NAVIGATION", relocalized_at);
  const int plans = events.Count("MODULE-ACTIVATED NAVIGATION");
  const double error_m = truth.DistanceTo(kShelfX, kShelfY);
  // Doorways crossed (travel mode "doorway", section 3.1) and the sonar updates inside them,
  // from 0.3 s after the mode changed (the switch's latency) to its end.
  int doorways = 0, updates_in_doorways = 0, updates_after_doorways = 0;
  double doorway_s = 0.0;
  {
    const auto modes = events.travel_modes();
    std::lock_guard<std::mutex> lock(updates_mutex);
    for (std::size_t i = 0; i < modes.size(); ++i) {
      if (modes[i].second != "doorway") continue;
      const double from = modes[i].first + 0.3;
      const double to = i + 1 < modes.size() ? modes[i + 1].first : end;
      ++doorways;
      doorway_s += to - modes[i].first;
      for (double t : updates) updates_in_doorways += t > from && t < to;
      if (i + 1 < modes.size())
        for (double t : updates) updates_after_doorways += t > to + 0.3;
    }
  }
  std::ostringstream line;
  line.precision(4);
  line << "seed=" << seed << " outcome=" << (done && result ? result->outcome : "timeout")
       << " success=" << (done && result && result->success) << " error_m=" << error_m
       << " sim_s=" << end - start << " wall_s=" << wall << " kidnap_s=" << kidnap_at - start
       << " lost_s=" << (lost_at < 0 ? -1 : lost_at - start)
       << " pulse_s=" << (pulse_at < 0 ? -1 : pulse_at - start)
       << " relocalized_s=" << (relocalized_at < 0 ? -1 : relocalized_at - start)
       << " replanned_s=" << (replanned_at < 0 ? -1 : replanned_at - start)
       << " navigation_plans=" << plans << " min_certainty=" << certainty.minimum_after_watch()
       << " contacts=" << truth.contacts() << " driven_m=" << truth.travelled_m()
       << " doorways=" << doorways << " doorway_s=" << doorway_s
       << " sonar_updates_in_doorways=" << updates_in_doorways << " message=\""
       << (result ? result->message.substr(0, 300) : "") << "\"";
  std::string report = line.str();
  for (char& c : report) {
    if (c == '\n') c = ' ';
  }
  spott_launch::testing::AppendReport(report_file, report);
  std::printf("%s\n", report.c_str());

  ASSERT_TRUE(done) << "the mission did not end in " << timeout_s << " s of simulated time";
  // The tracker did not notice at once; then its certainty fell to 0.8 or below.
  ASSERT_GT(lost_at, kidnap_at) << "POS-CERTAINTY* never fell to 0.8 after the turn";
  // The policy interrupted the navigation: target points removed, EXECUTION-INTERRUPTED? pulsed,
  // active localization started, in that order.
  EXPECT_GE(removed_at, lost_at - 0.5);
  EXPECT_GE(pulse_at, removed_at);
  EXPECT_GE(active_at, pulse_at);
  // Relocalized, then a new navigation plan from there.
  EXPECT_GT(relocalized_at, active_at);
  EXPECT_GE(replanned_at, relocalized_at);
  EXPECT_GE(plans, 2);
  ASSERT_TRUE(result);
  EXPECT_TRUE(result->success) << result->outcome << ": " << result->message;
  EXPECT_LT(error_m, 0.5) << "ground truth " << error_m << " m from the front of the shelf";
  EXPECT_EQ(truth.contacts(), 0) << "bumper contacts";
  // "switch off the sonars when driving through doorways": no sensor update in a doorway, and
  // updates again after it.
  EXPECT_GE(doorways, 1) << "the route to room B passes a doorway";
  EXPECT_EQ(updates_in_doorways, 0) << "the localization used sonar readings in a doorway";
  EXPECT_GT(updates_after_doorways, 0) << "the sonars were not switched on again";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "office_delivery_rostest");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
