// rostest of robot_sim_node in hilare_room (8 x 9 m room, a 2.5 m wide corridor east of it from
// x = 8 to 10.5, door_room at (8, 1.2), 1.2 m wide; walls 0.15 m thick, so the corridor's
// north end face is at y = 8.925 and its west face at x = 8.075). Robot: Nomad 200, radius
// 0.2285 m, sonar_1 on the rim facing +x, sonar range 0.43 to 6.5 m, noise 0.01 + 0.01 / m.
#include <gtest/gtest.h>

#include <cmath>
#include <mutex>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/JointState.h>
#include <spott_msgs/AddObstacle.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/Door.h>
#include <spott_msgs/Kidnap.h>
#include <spott_msgs/LoadWorld.h>
#include <spott_msgs/RangeProfile.h>
#include <spott_msgs/RangeRing.h>
#include <spott_msgs/SensorFault.h>
#include <spott_msgs/SetDoorState.h>

#include "spott_ros/testing/node_process.h"

namespace {

constexpr double kRadius = 0.2285;

double Yaw(const geometry_msgs::Quaternion& q) {
  return std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
}

class SimFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    cmd_ = nh_.advertise<geometry_msgs::Twist>("cmd_vel", 10);
    subs_.push_back(nh_.subscribe("sonar", 10, &SimFixture::OnSonar, this));
    subs_.push_back(nh_.subscribe("bumper", 10, &SimFixture::OnBumper, this));
    subs_.push_back(nh_.subscribe("odom", 50, &SimFixture::OnOdom, this));
    subs_.push_back(nh_.subscribe("sim/ground_truth", 50, &SimFixture::OnTruth, this));
    subs_.push_back(nh_.subscribe("range_profile", 10, &SimFixture::OnProfile, this));
    head_ = nh_.advertise<sensor_msgs::JointState>("range_profile/point_head", 10);
    ASSERT_TRUE(ros::service::waitForService("sim/kidnap", ros::Duration(30)));
    ASSERT_TRUE(WaitFor([&] { return have_truth_ && have_sonar_; }, 30.0));
  }

  void OnSonar(const spott_msgs::RangeRing& m) {
    sonar_ = m;
    have_sonar_ = true;
    ++sonar_count_;
  }
  void OnBumper(const spott_msgs::BumperRing& m) { bumper_ = m; }
  void OnProfile(const spott_msgs::RangeProfile& m) {
    if (m.header.frame_id == "quadris_1" && m.orientation == spott_msgs::RangeProfile::HORIZONTAL) {
      profile_ = m;
    }
  }
  void OnOdom(const nav_msgs::Odometry& m) { odom_ = m; }
  void OnTruth(const nav_msgs::Odometry& m) {
    if (have_truth_) {
      const auto& a = truth_.pose.pose;
      const auto& b = m.pose.pose;
      travelled_ += std::hypot(b.position.x - a.position.x, b.position.y - a.position.y);
      turned_ += std::remainder(Yaw(b.orientation) - Yaw(a.orientation), 2 * M_PI);
    }
    truth_ = m;
    have_truth_ = true;
  }

  // Spins until `done` or `seconds` of wall time.
  template <typename F>
  bool WaitFor(F done, double seconds) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && ros::WallTime::now() < end) {
      ros::spinOnce();
      if (done()) return true;
      ros::WallDuration(0.002).sleep();
    }
    return false;
  }
  // Spins for `seconds` of simulated time, publishing `cmd` at 20 Hz of simulated time.
  void Drive(double v, double w, double seconds) {
    geometry_msgs::Twist t;
    t.linear.x = v;
    t.angular.z = w;
    const ros::Time end = ros::Time::now() + ros::Duration(seconds);
    ros::Time next_cmd(0);
    while (ros::ok() && ros::Time::now() < end) {
      if (ros::Time::now() >= next_cmd) {
        cmd_.publish(t);
        next_cmd = ros::Time::now() + ros::Duration(0.05);
      }
      ros::spinOnce();
      ros::WallDuration(0.001).sleep();
    }
  }
  void Stop() { Drive(0, 0, 1.5); }
  // Waits for sonar readings taken after `seconds` more of simulated time.
  spott_msgs::RangeRing FreshSonar(double seconds = 0.35) {
    const ros::Time after = ros::Time::now() + ros::Duration(seconds);
    WaitFor([&] { return sonar_.header.stamp > after; }, 30.0);
    return sonar_;
  }
  bool Kidnap(double x, double y, double yaw, bool relative, std::string* message = nullptr) {
    spott_msgs::Kidnap srv;
    srv.request.pose.x = x;
    srv.request.pose.y = y;
    srv.request.pose.theta = yaw;
    srv.request.relative = relative;
    EXPECT_TRUE(ros::service::call("sim/kidnap", srv));
    if (message) *message = srv.response.message;
    return srv.response.success;
  }

  ros::NodeHandle nh_;
  ros::Publisher cmd_, head_;
  spott_msgs::RangeProfile profile_;
  std::vector<ros::Subscriber> subs_;
  spott_msgs::RangeRing sonar_;
  spott_msgs::BumperRing bumper_;
  nav_msgs::Odometry odom_, truth_;
  bool have_sonar_ = false, have_truth_ = false;
  int sonar_count_ = 0;
  double travelled_ = 0.0, turned_ = 0.0;
};

TEST_F(SimFixture, SonarFacingWallAtOneMetreReadsOneMetre) {
  // sonar_1 1 m from the corridor's north end: centre at 8.925 - 1 - radius, facing north.
  ASSERT_TRUE(Kidnap(9.25, 8.925 - 1.0 - kRadius, M_PI / 2, false));
  const auto sonar = FreshSonar();
  EXPECT_NEAR(sonar.ranges[0], 1.0, 0.07);  // 3.5 sigma of 0.02 m
}

TEST_F(SimFixture, SonarAlongTheCorridorHearsNoEchoFromGrazingWalls) {
  // Looking up the 2.5 m corridor from its south end: the 30 degree cone meets the side walls
  // 4.5 m away at 75 degrees of incidence (specular: no echo) and the far end is beyond 6.5 m.
  ASSERT_TRUE(Kidnap(9.25, 1.0, M_PI / 2, false));
  const auto sonar = FreshSonar();
  EXPECT_FLOAT_EQ(sonar.ranges[0], 6.5f);
}

TEST_F(SimFixture, DoorServiceClosesTheDoorForTheSonar) {
  // Facing west through door_room from the corridor: open, the room behind is beyond range;
  // closed, the leaf (0.025 m east of x = 8) is 1 m away.
  ASSERT_TRUE(Kidnap(8.025 + 1.0 + kRadius, 1.2, M_PI, false));
  EXPECT_FLOAT_EQ(FreshSonar().ranges[0], 6.5f);
  spott_msgs::SetDoorState door;
  door.request.door_id = "door_room";
  door.request.state = spott_msgs::Door::CLOSED;
  ASSERT_TRUE(ros::service::call("sim/set_door_state", door));
  EXPECT_TRUE(door.response.success) << door.response.message;
  EXPECT_NEAR(FreshSonar().ranges[0], 1.0, 0.07);
  door.request.state = spott_msgs::Door::OPEN;
  ASSERT_TRUE(ros::service::call("sim/set_door_state", door));
  EXPECT_FLOAT_EQ(FreshSonar().ranges[0], 6.5f);
  door.request.door_id = "no_such_door";
  ASSERT_TRUE(ros::service::call("sim/set_door_state", door));
  EXPECT_FALSE(door.response.success);
  EXPECT_NE(door.response.message.find("no_such_door"), std::string::npos);
}

TEST_F(SimFixture, QuadrisProfilesFollowTheHead) {
  // Facing the corridor's north end as above: quadris_1 sits 0.05 m ahead of and 0.1 m left of
  // the centre, i.e. at (9.15, 7.7465), 1.1785 m from the end wall and 1.075 m from the west
  // wall (x = 8.075).
  ASSERT_TRUE(Kidnap(9.25, 8.925 - 1.0 - kRadius, M_PI / 2, false));
  const ros::Time after = ros::Time::now();
  ASSERT_TRUE(WaitFor([&] { return profile_.header.stamp > after; }, 30.0));
  EXPECT_NEAR(profile_.ranges[31], 1.1785, 0.02);
  // A message published before the simulator's subscription is connected is lost (a busy
  // machine makes the handshake slow): wait for it.
  ASSERT_TRUE(WaitFor([&] { return head_.getNumSubscribers() > 0; }, 30.0));
  sensor_msgs::JointState point;
  point.name = {"quadris_1_pan_joint"};
  point.position = {M_PI / 2};
  head_.publish(point);
  ASSERT_TRUE(WaitFor([&] { return std::abs(profile_.pan - M_PI / 2) < 1e-6; }, 30.0));
  EXPECT_NEAR(profile_.ranges[31], 1.075, 0.02);
  point.position = {0.0};
  head_.publish(point);
  ASSERT_TRUE(WaitFor([&] { return std::abs(profile_.pan) < 1e-6; }, 30.0));
}

TEST_F(SimFixture, DrivingIntoAWallStopsTheRobotAndFiresTheBumperFacingIt) {
  ASSERT_TRUE(Kidnap(9.25, 7.5, M_PI / 2, false));
  Drive(0.3, 0.0, 6.0);  // 1.2 m of gap, keeps pushing for 2 s
  EXPECT_NEAR(truth_.pose.pose.position.y, 8.925 - kRadius, 0.01);
  EXPECT_NEAR(truth_.twist.twist.linear.x, 0.0, 1e-9);
  ASSERT_EQ(bumper_.pressed.size(), 20u);
  EXPECT_TRUE(bumper_.pressed[0]);
  for (int i = 2; i < 19; ++i) EXPECT_FALSE(bumper_.pressed[i]) << "segment " << i;
  Drive(-0.2, 0.0, 2.0);
  Stop();
  for (bool b : bumper_.pressed) EXPECT_FALSE(b);
}

TEST_F(SimFixture, KidnapIsUnseenByOdometryAndBadKidnapsAreRefused) {
  ASSERT_TRUE(Kidnap(4.0, 4.0, 0.0, false));
  FreshSonar();
  const double odom_yaw = Yaw(odom_.pose.pose.orientation);
  // RHINO's experiment: turned about 70 degrees to the right.
  ASSERT_TRUE(Kidnap(0.0, 0.0, -70 * M_PI / 180, true));
  FreshSonar();
  EXPECT_NEAR(Yaw(truth_.pose.pose.orientation), -70 * M_PI / 180, 1e-3);
  EXPECT_NEAR(Yaw(odom_.pose.pose.orientation), odom_yaw, 1e-9);
  std::string message;
  EXPECT_FALSE(Kidnap(8.0, 5.0, 0.0, false, &message));  // into the wall between room and corridor
  EXPECT_NE(message.find("inside"), std::string::npos) << message;
  EXPECT_FALSE(Kidnap(-3.0, 4.0, 0.0, false, &message));
  EXPECT_NE(message.find("outside"), std::string::npos) << message;
  FreshSonar();
  EXPECT_NEAR(truth_.pose.pose.position.x, 4.0, 1e-9);  // nothing moved
}

TEST_F(SimFixture, DropoutServiceBlanksTheSensorForItsDuration) {
  ASSERT_TRUE(Kidnap(4.0, 4.0, 0.0, false));
  spott_msgs::SensorFault fault;
  fault.request.sensor = "sonar/1";
  fault.request.fault = spott_msgs::SensorFault::Request::DROPOUT;
  fault.request.duration = 2.0;
  ASSERT_TRUE(ros::service::call("sim/sensor_fault", fault));
  ASSERT_TRUE(fault.response.success) << fault.response.message;
  auto sonar = FreshSonar(0.2);
  EXPECT_TRUE(std::isnan(sonar.ranges[0]));
  EXPECT_FALSE(std::isnan(sonar.ranges[1]));
  sonar = FreshSonar(2.5);
  EXPECT_FALSE(std::isnan(sonar.ranges[0]));
  fault.request.sensor = "lidar";
  ASSERT_TRUE(ros::service::call("sim/sensor_fault", fault));
  EXPECT_FALSE(fault.response.success);
  spott_msgs::AddObstacle add;
  add.request.kind = "piano";
  ASSERT_TRUE(ros::service::call("sim/add_obstacle", add));
  EXPECT_FALSE(add.response.success);
}

TEST_F(SimFixture, BadWorldFileIsRefusedAndTheOldWorldStays) {
  ASSERT_TRUE(Kidnap(9.25, 8.925 - 1.0 - kRadius, M_PI / 2, false));
  spott_msgs::LoadWorld load;
  load.request.path = "/nonexistent/world.yaml";
  ASSERT_TRUE(ros::service::call("sim/load_world", load));
  EXPECT_FALSE(load.response.success);
  ASSERT_FALSE(load.response.errors.empty());
  EXPECT_NE(load.response.errors[0].find("/nonexistent/world.yaml"), std::string::npos);
  EXPECT_NEAR(FreshSonar().ranges[0], 1.0, 0.07);  // the corridor's end wall is still there
}

TEST_F(SimFixture, NanVelocityIsRefusedAndTheRobotStops) {
  ASSERT_TRUE(Kidnap(3.0, 3.0, 0.0, false));
  Drive(0.3, 0.0, 1.5);
  EXPECT_GT(truth_.twist.twist.linear.x, 0.25);
  Drive(std::nan(""), 0.0, 2.0);
  EXPECT_EQ(truth_.twist.twist.linear.x, 0.0);
  Drive(0.2, 0.0, 1.0);  // the node is still alive and obeys again
  EXPECT_GT(truth_.twist.twist.linear.x, 0.1);
  Stop();
}

TEST_F(SimFixture, OdometryDivergesByTheConfiguredDriftOverASquare) {
  // A square of 2.5 m sides (10 m of travel) in the room, open loop. Configured: 1 % too much
  // rotation and 2 mrad of heading per metre; no random error. So after the square the odometry
  // heading is off by 0.01 * rotation + 0.002 * distance, about 0.083 rad.
  ASSERT_TRUE(Kidnap(2.5, 2.5, 0.0, false));
  FreshSonar();
  const double odom0 = Yaw(odom_.pose.pose.orientation);
  const double truth0 = Yaw(truth_.pose.pose.orientation);
  travelled_ = turned_ = 0.0;
  for (int side = 0; side < 4; ++side) {
    Drive(0.4, 0.0, 2.5 / 0.4);
    Stop();
    Drive(0.0, 0.5, M_PI / 2 / 0.5);
    Stop();
  }
  FreshSonar();
  EXPECT_GT(travelled_, 9.5);
  EXPECT_GT(turned_, 5.5);
  const double odom_turn = std::remainder(Yaw(odom_.pose.pose.orientation) - odom0, 2 * M_PI);
  const double truth_turn = std::remainder(Yaw(truth_.pose.pose.orientation) - truth0, 2 * M_PI);
  const double expected = 0.01 * turned_ + 0.002 * travelled_;
  EXPECT_NEAR(std::remainder(odom_turn - truth_turn, 2 * M_PI), expected, 0.005);
  EXPECT_GT(expected, 0.075);
}

TEST(RobotSimParameters, BadParametersAreRefusedByName) {
  const auto run = spott_ros::testing::RunNode(
      ROBOT_SIM_EXE, "__name:=bad_sim _physics_rate_hz:=fast _sensor_rate_hetz:=10");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  for (const char* key : {"~physics_rate_hz", "~sensor_rate_hetz is not a parameter"}) {
    EXPECT_NE(run.output.find(key), std::string::npos) << key << " in:\n" << run.output;
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "robot_sim_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
