// Conversions of the node's ROS layer: the belief grid for rviz, map -> odom, the pose, the
// modes and the Navigate goal of a target.
#include <gtest/gtest.h>

#include <cmath>

#include <tf2/utils.h>

#include "markov_localization/ros/conversions.h"
#include "markov_localization/ros/pose_messages.h"
#include "spott_map/pose_algebra.h"

namespace markov_localization {
namespace {

namespace conv = ros_conversions;

// 3 x 2 cells of 0.5 m at origin (10, 20), two heading bins; hand-placed masses.
BeliefSnapshot SmallBelief() {
  BeliefSnapshot b;
  b.nx = 3;
  b.ny = 2;
  b.nt = 2;
  b.origin = Vec2(10.0, 20.0);
  b.resolution = 0.5;
  b.p.assign(12, 0.0f);
  b.p[b.Index(0, 0, 0)] = 0.1f;
  b.p[b.Index(0, 0, 1)] = 0.1f;    // marginal 0.2
  b.p[b.Index(2, 1, 1)] = 0.4f;    // marginal 0.4: the maximum
  b.p[b.Index(1, 1, 0)] = 0.3f;    // 0.3
  b.p[b.Index(1, 0, 1)] = 0.001f;  // 0.001 -> 0.25 % of the maximum: rounds to 0
  b.num_states = 12;
  return b;
}

// SPOTT's dense scan turns the Nomad's turret (and its sonar ring) in 2.5-degree steps: such a
// ring must not be read as the model's beams.
TEST(Conversions, ARingReadWithTheTurretTurnedIsTheModelsRingTurned) {
  spott_msgs::RangeRing ring;
  std::vector<double> beams;
  for (int i = 0; i < 16; ++i) {
    geometry_msgs::Pose2D m;
    m.theta = spott_map::NormalizeAngle(i * M_PI / 8);
    m.x = 0.23 * std::cos(m.theta);
    m.y = 0.23 * std::sin(m.theta);
    ring.mounts.push_back(m);
    beams.push_back(m.theta);
  }
  std::string why;
  EXPECT_EQ(conv::RingTurn(ring, beams, 0.01, &why), 0.0);
  for (auto& m : ring.mounts) m.theta = spott_map::NormalizeAngle(m.theta + 2.5 * M_PI / 180);
  const auto turned = conv::RingTurn(ring, beams, 0.01, &why);
  ASSERT_TRUE(turned) << why;
  EXPECT_NEAR(*turned, 2.5 * M_PI / 180, 1e-9);
  ring.mounts[3].theta += 0.05;  // one transducer elsewhere: not a turn of the ring
  EXPECT_FALSE(conv::RingTurn(ring, beams, 0.01, &why));
  EXPECT_NE(why.find("mount 3 points"), std::string::npos) << why;
  ring.mounts[3].theta = std::nan("");
  EXPECT_FALSE(conv::RingTurn(ring, beams, 0.01, &why));
  ring.mounts[3].theta = 1e17;  // finite, but no angle: refused by name
  EXPECT_FALSE(conv::RingTurn(ring, beams, 0.01, &why));
  EXPECT_NE(why.find("mounts[].theta 3 is"), std::string::npos) << why;
  ring.mounts[3].theta = beams[3];
  // sensor_messages_fuzz's crash: a beam of -1.5e308 rad "turned" every mount within the
  // tolerance once its difference had lost the angle to rounding.
  std::vector<double> absurd = beams;
  absurd[0] = -1.52302e308;
  EXPECT_FALSE(conv::RingTurn(ring, absurd, 0.01, &why));
  EXPECT_NE(why.find("the model's beam 0 is"), std::string::npos) << why;
  ring.mounts.pop_back();
  EXPECT_FALSE(conv::RingTurn(ring, beams, 0.01, &why));
  EXPECT_NE(why.find("15 mounts, the model has 16 beams"), std::string::npos) << why;
  ring.mounts.clear();  // a ring without mounts: the configured geometry holds
  EXPECT_EQ(conv::RingTurn(ring, beams, 0.01, &why), 0.0);
}

TEST(Conversions, BeliefGridIsTheMarginalOverThetaScaledToAMaximumOf100) {
  const auto grid = conv::BeliefGrid(SmallBelief(), {}, "map", ros::Time(5.0));
  EXPECT_EQ(grid.header.frame_id, "map");
  EXPECT_EQ(grid.header.stamp, ros::Time(5.0));
  EXPECT_EQ(grid.info.width, 3u);
  EXPECT_EQ(grid.info.height, 2u);
  EXPECT_FLOAT_EQ(grid.info.resolution, 0.5f);
  EXPECT_DOUBLE_EQ(grid.info.origin.position.x, 10.0);
  EXPECT_DOUBLE_EQ(grid.info.origin.position.y, 20.0);
  ASSERT_EQ(grid.data.size(), 6u);
  // Row-major, row 0 at the bottom, like the belief's layers.
  const std::vector<int> expected = {50, 0, 0, 0, 75, 100};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(grid.data[i], expected[i]) << "cell " << i;
}

TEST(Conversions, BeliefGridMarksCellsThatAreNoStateUnknown) {
  const std::vector<std::uint8_t> mask = {1, 0, 1, 1, 1, 1};
  const auto grid = conv::BeliefGrid(SmallBelief(), mask, "map", ros::Time(0));
  EXPECT_EQ(grid.data[1], -1);
  EXPECT_EQ(grid.data[0], 50);
  EXPECT_EQ(grid.data[5], 100);
}

TEST(Conversions, BeliefGridOfAnEmptyBeliefIsZero) {
  BeliefSnapshot b = SmallBelief();
  std::fill(b.p.begin(), b.p.end(), 0.0f);
  const auto grid = conv::BeliefGrid(b, {}, "map", ros::Time(0));
  for (auto v : grid.data) EXPECT_EQ(v, 0);
}

TEST(Conversions, MapToOdomComposedWithOdomGivesTheEstimate) {
  const Pose2 estimate{5.0, -2.0, 2.5};
  const Pose2 odom{1.0, 3.0, -0.7};
  const Pose2 t = spott_map::MapToOdom(estimate, odom);  // what the node publishes
  // t * odom
  const double x = t.x + std::cos(t.yaw) * odom.x - std::sin(t.yaw) * odom.y;
  const double y = t.y + std::sin(t.yaw) * odom.x + std::cos(t.yaw) * odom.y;
  EXPECT_NEAR(x, 5.0, 1e-12);
  EXPECT_NEAR(y, -2.0, 1e-12);
  EXPECT_NEAR(std::remainder(t.yaw + odom.yaw - estimate.yaw, 2 * M_PI), 0.0, 1e-12);
  // Hand-computed: yaw 3.2 wraps to 3.2 - 2 pi.
  EXPECT_NEAR(t.yaw, 3.2 - 2 * M_PI, 1e-12);

  const auto msg = conv::ToTransform(t, "map", "odom", ros::Time(7.0));
  EXPECT_EQ(msg.header.frame_id, "map");
  EXPECT_EQ(msg.child_frame_id, "odom");
  EXPECT_DOUBLE_EQ(msg.transform.translation.x, t.x);
  EXPECT_NEAR(tf2::getYaw(msg.transform.rotation), t.yaw, 1e-12);
}

TEST(Conversions, PoseCarriesTheModesCovarianceInRowsXYYaw) {
  Eigen::Matrix3d cov;
  cov << 0.04, 0.01, 0.002, 0.01, 0.09, 0.003, 0.002, 0.003, 0.05;
  const auto pose = conv::ToPoseWithCovariance(Pose2{1, 2, -1.0}, cov, "map", ros::Time(1));
  EXPECT_DOUBLE_EQ(pose.pose.pose.position.x, 1.0);
  EXPECT_NEAR(tf2::getYaw(pose.pose.pose.orientation), -1.0, 1e-12);
  EXPECT_DOUBLE_EQ(pose.pose.covariance[0], 0.04);          // x x
  EXPECT_DOUBLE_EQ(pose.pose.covariance[1], 0.01);          // x y
  EXPECT_DOUBLE_EQ(pose.pose.covariance[5], 0.002);         // x yaw
  EXPECT_DOUBLE_EQ(pose.pose.covariance[7], 0.09);          // y y
  EXPECT_DOUBLE_EQ(pose.pose.covariance[5 * 6 + 5], 0.05);  // yaw yaw
  EXPECT_DOUBLE_EQ(pose.pose.covariance[2 * 6 + 2], 0.0);   // z z: not estimated
}

TEST(Conversions, ModesBecomePosesHeaviestFirst) {
  Mode a, b;
  a.mean = Pose2{1, 2, 0.5};
  b.mean = Pose2{26, 18, 0.5 - M_PI};
  const auto pa = conv::ToPoseArray({a, b}, "map", ros::Time(2));
  ASSERT_EQ(pa.poses.size(), 2u);
  EXPECT_DOUBLE_EQ(pa.poses[1].position.x, 26.0);
  EXPECT_NEAR(tf2::getYaw(pa.poses[1].orientation), 0.5 - M_PI, 1e-12);
}

TEST(Conversions, NavigateGoalIsAPointWithoutHeading) {
  const auto g = conv::NavigateGoalTo(Vec2(17.5, 4.0), 0.4, "map", ros::Time(3));
  EXPECT_EQ(g.target.header.frame_id, "map");
  EXPECT_DOUBLE_EQ(g.target.pose.position.x, 17.5);
  EXPECT_DOUBLE_EQ(g.target.pose.position.y, 4.0);
  EXPECT_TRUE(g.ignore_heading);
  EXPECT_DOUBLE_EQ(g.position_tolerance, 0.4);
  EXPECT_EQ(g.speed_mode, spott_msgs::NavigateGoal::NORMAL);
  EXPECT_TRUE(std::isnan(g.direction_bias));
}

TEST(Conversions, BeliefModesCarryMassAndSpread) {
  Mode m;
  m.mean = Pose2{1.0, 2.0, 0.5};
  m.mass = 0.7;
  m.covariance << 0.01, 0.002, 0.0, 0.002, 0.04, 0.001, 0.0, 0.001, 0.09;
  const spott_msgs::BeliefModes msg = conv::ToBeliefModes({m}, "map", ros::Time(3.0));
  ASSERT_EQ(msg.modes.size(), 1u);
  EXPECT_EQ(msg.header.frame_id, "map");
  EXPECT_DOUBLE_EQ(msg.modes[0].mass, 0.7);
  EXPECT_DOUBLE_EQ(msg.modes[0].mean.theta, 0.5);
  EXPECT_DOUBLE_EQ(msg.modes[0].covariance[1], 0.002);  // row-major (x, y)
  EXPECT_DOUBLE_EQ(msg.modes[0].covariance[4], 0.04);   // (y, y)
  EXPECT_DOUBLE_EQ(msg.modes[0].covariance[7], 0.001);  // (theta, y)
  EXPECT_DOUBLE_EQ(msg.modes[0].covariance[8], 0.09);
}

TEST(Conversions, AMapMessageKeepsItsCornerOriginResolutionAndRows) {
  nav_msgs::OccupancyGrid g;
  g.info.resolution = 0.05f;
  g.info.width = 3;
  g.info.height = 2;
  g.info.origin.position.x = -1.0;
  g.info.origin.position.y = 4.0;
  g.info.origin.orientation.z = std::sin(0.1);
  g.info.origin.orientation.w = std::cos(0.1);
  g.data = {0, 100, -1, 0, 0, 100};
  const OccupancyMap m = conv::FromOccupancyGrid(g);
  EXPECT_EQ(m.width, 3);
  EXPECT_EQ(m.height, 2);
  EXPECT_NEAR(m.resolution_m, 0.05, 1e-7);
  EXPECT_DOUBLE_EQ(m.origin.x(), -1.0);
  EXPECT_NEAR(m.origin_yaw, 0.2, 1e-12);
  EXPECT_EQ(m.at(1, 0), 100);  // row 0 at the bottom, as the message
  EXPECT_EQ(m.at(2, 1), 100);
}

// A head 0.1 m ahead of the centre and 0.9 m up, panned 90 degrees left (its x along the base's
// y), three samples: a return 2 m along the head's x, one on the floor (seen 1 m ahead, 0.85 m
// below the head, so at 0.05 m), one without return 30 degrees to the head's right.
TEST(Conversions, AProfileBecomesReadingsOfTheBeamsNearestItsSamplesDirections) {
  spott_msgs::RangeProfile msg;
  msg.orientation = spott_msgs::RangeProfile::HORIZONTAL;
  msg.max_range = 4.0f;
  const auto sample = [&](double angle, double range, double x, double y, double z) {
    msg.angles.push_back(angle);
    msg.ranges.push_back(range);
    geometry_msgs::Point32 p;
    p.x = x;
    p.y = y;
    p.z = z;
    msg.points.push_back(p);
  };
  sample(0.0, 2.0, 2.0, 0.0, 0.0);
  sample(0.0, 1.3, 1.0, 0.0, -0.85);
  sample(-M_PI / 6, INFINITY, NAN, NAN, NAN);
  geometry_msgs::Transform t;
  t.translation.x = 0.1;
  t.translation.z = 0.9;
  t.rotation.z = std::sin(M_PI / 4);
  t.rotation.w = std::cos(M_PI / 4);
  std::string why;
  const std::vector<double> z = conv::ProfileReadings(msg, t, 180, 0.1, 2.0, &why);
  ASSERT_EQ(z.size(), 180u) << why;
  // The return: at (0.1, 2.0, 0.9) in the base frame, seen from the centre at 87.1 degrees:
  // beam 44 (88 degrees), 2.0025 m.
  EXPECT_NEAR(z[44], std::hypot(0.1, 2.0), 1e-6);
  // No return 30 degrees right of the head's x: 60 degrees, beam 30.
  EXPECT_TRUE(std::isinf(z[30]));
  // The floor sample is left out, and every other beam has no reading.
  int readings = 0;
  for (double r : z) readings += std::isnan(r) ? 0 : 1;
  EXPECT_EQ(readings, 2);
  // Not a usable profile: refused with the reason.
  msg.orientation = spott_msgs::RangeProfile::VERTICAL;
  EXPECT_TRUE(conv::ProfileReadings(msg, t, 180, 0.1, 2.0, &why).empty());
  EXPECT_EQ(why, "not horizontal");
  msg.orientation = spott_msgs::RangeProfile::HORIZONTAL;
  msg.angles.pop_back();
  EXPECT_TRUE(conv::ProfileReadings(msg, t, 180, 0.1, 2.0, &why).empty());
  EXPECT_EQ(why, "angles, ranges and points differ in size");
}

TEST(Conversions, LaserBeamsAreSubsampledAsAmclDoes) {
  // 181 readings, laser_max_beams 30: step (181 - 1) / 29 = 6, beams 0, 6, ..., 180 (31).
  const std::vector<int> beams = conv::LaserBeams(181, 30);
  ASSERT_EQ(beams.size(), 31u);
  EXPECT_EQ(beams[1], 6);
  EXPECT_EQ(beams.back(), 180);
  EXPECT_EQ(conv::LaserBeams(10, 30).size(), 10u);
  sensor_msgs::LaserScan scan;
  scan.angle_min = -1.5f;
  scan.angle_increment = 0.5f;
  scan.range_min = 0.1f;
  scan.range_max = 10.0f;
  scan.ranges = {1.0f, NAN, 0.05f, 10.0f, INFINITY, 3.0f, 9.99f};
  const std::vector<int> all = conv::LaserBeams(7, 7);
  const std::vector<double> angles = conv::LaserBeamAngles(scan, all);
  EXPECT_NEAR(angles[3], 0.0, 1e-7);
  const std::vector<double> r = conv::LaserRanges(scan, all);
  EXPECT_DOUBLE_EQ(r[0], 1.0);
  EXPECT_TRUE(std::isnan(r[1])) << "REP 117: NaN is erroneous, left out (not no echo)";
  for (int i : {2, 3, 4}) EXPECT_TRUE(std::isinf(r[i])) << i;  // < min, >= max, inf
  EXPECT_NEAR(r[6], 9.99, 1e-5);
}

TEST(PoseMessages, AnInitialPoseIsRefusedByFieldWhenNotFiniteOrInAnotherFrame) {
  geometry_msgs::PoseWithCovarianceStamped msg;
  msg.pose.pose.orientation.w = 1.0;
  msg.pose.pose.position.x = 2.0;
  std::string field, why;
  auto pose = conv::InitialPoseOf(msg, "map", &field, &why);  // empty frame_id: the map's
  ASSERT_TRUE(pose.has_value());
  EXPECT_EQ(pose->x, 2.0);
  msg.header.frame_id = "odom";
  EXPECT_FALSE(conv::InitialPoseOf(msg, "map", &field, &why).has_value());
  EXPECT_EQ(field, "header.frame_id");
  EXPECT_EQ(why, "'odom' is not 'map'");
  msg.header.frame_id = "map";
  msg.pose.pose.position.y = std::nan("");
  EXPECT_FALSE(conv::InitialPoseOf(msg, "map", &field, &why).has_value());
  EXPECT_EQ(field, "pose.pose");
}

}  // namespace
}  // namespace markov_localization
