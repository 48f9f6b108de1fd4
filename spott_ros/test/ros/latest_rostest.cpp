// testing::Latest as the whole-stack rostests use it: an AsyncSpinner serves the global queue, so
// its callback runs on a spinner thread while the test thread takes messages out and, at the end
// of a test, destroys it with messages still arriving. Before the fix the callback's queue was
// unlocked and destroyed before the subscription: a process aborted as a test ended.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/UInt64.h>

#include <atomic>
#include <thread>

#include "spott_ros/testing/node_process.h"

namespace {

using spott_ros::testing::Latest;

class Flood {
 public:
  explicit Flood(ros::NodeHandle& nh) : pub_(nh.advertise<std_msgs::UInt64>("count", 10000)) {
    thread_ = std::thread([this] {
      std_msgs::UInt64 m;
      while (!stop_ && ros::ok()) {
        m.data = ++sent_;
        pub_.publish(m);
        if (m.data % 64 == 0) std::this_thread::yield();
      }
    });
  }
  ~Flood() {
    stop_ = true;
    thread_.join();
  }
  std::uint64_t sent() const { return sent_; }

 private:
  ros::Publisher pub_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> sent_{0};
  std::thread thread_;
};

TEST(Latest, SeesEveryMessageInOrderBesideAnAsyncSpinnerAndDiesWhileTheyArrive) {
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  Flood flood(nh);
  for (int round = 0; round < 300; ++round) {
    Latest<std_msgs::UInt64> latest(nh, "count", 10000);
    std::uint64_t last = 0, seen = 0;
    const bool ok = latest.WaitFor(
        [&](const std_msgs::UInt64& m) {
          // WaitFor asks again about the last message it looked at; every other one is new and
          // in order (a torn queue hands out garbage, a message again or one from before).
          if (m.data == last) return seen >= 200;
          EXPECT_GT(m.data, last) << "round " << round;
          last = m.data;
          return ++seen >= 200;
        },
        20.0);
    ASSERT_TRUE(ok) << "round " << round << ": " << seen << " messages of " << flood.sent();
    ASSERT_TRUE(latest.msg().has_value());
    EXPECT_EQ(latest.msg()->data, last);
    // `latest` is destroyed here with the flood still arriving on the spinner threads.
  }
  spinner.stop();
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "latest_rostest");
  return RUN_ALL_TESTS();
}
