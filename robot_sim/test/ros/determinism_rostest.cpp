// Same world, seed and (empty) command stream: bit-identical sensor streams; another seed:
// different noise. Readings are matched by their simulated-time stamps.
#include <gtest/gtest.h>

#include <cstring>
#include <map>

#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <spott_msgs/RangeRing.h>

namespace {

struct Stream {
  std::map<double, std::vector<float>> sonar, scan;
};

TEST(DeterminismTest, SameSeedGivesIdenticalStreamsOtherSeedDoesNot) {
  ros::NodeHandle nh;
  std::map<std::string, Stream> streams;
  std::vector<ros::Subscriber> subs;
  for (const std::string ns : {"a", "b", "c"}) {
    Stream* s = &streams[ns];
    subs.push_back(nh.subscribe<spott_msgs::RangeRing>(
        "/" + ns + "/sonar", 1000, [s](const spott_msgs::RangeRing::ConstPtr& m) {
          s->sonar[m->header.stamp.toSec()] = m->ranges;
        }));
    subs.push_back(nh.subscribe<sensor_msgs::LaserScan>(
        "/" + ns + "/scan", 1000, [s](const sensor_msgs::LaserScan::ConstPtr& m) {
          s->scan[m->header.stamp.toSec()] = m->ranges;
        }));
  }
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(60);
  auto common = [&](const std::string& x, const std::string& y) {
    int n = 0;
    for (const auto& [t, r] : streams[x].scan) n += streams[y].scan.count(t);
    return n;
  };
  while (ros::ok() && ros::WallTime::now() < end &&
         (common("a", "b") < 30 || common("a", "c") < 30)) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
  }
  ASSERT_GE(common("a", "b"), 30);
  auto same = [](const std::vector<float>& p, const std::vector<float>& q) {
    return p.size() == q.size() && std::memcmp(p.data(), q.data(), p.size() * sizeof(float)) == 0;
  };
  int compared = 0, differ_c = 0;
  for (const auto& [t, r] : streams["a"].scan) {
    auto b = streams["b"].scan.find(t);
    if (b != streams["b"].scan.end()) {
      EXPECT_TRUE(same(r, b->second)) << "scan at t = " << t;
      ++compared;
    }
    auto c = streams["c"].scan.find(t);
    if (c != streams["c"].scan.end()) differ_c += !same(r, c->second);
  }
  for (const auto& [t, r] : streams["a"].sonar) {
    auto b = streams["b"].sonar.find(t);
    if (b != streams["b"].sonar.end()) {
      EXPECT_TRUE(same(r, b->second)) << "sonar at t = " << t;
    }
  }
  EXPECT_GE(compared, 30);
  EXPECT_GT(differ_c, 0);  // another seed, other noise
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "determinism_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
