// rostest of tr_plus_node: the live state follows pushed conditions at once, actions are
// announced with bound output variables, bad programs and tasks are refused with located errors
// while the running program keeps running.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <spott_msgs/ConditionState.h>
#include <spott_msgs/LoadTRProgram.h>
#include <spott_msgs/ParseTask.h>
#include <spott_msgs/TRProgramState.h>
#include <std_msgs/String.h>

#include "spott_ros/testing/node_process.h"

#include <functional>
#include <optional>

namespace {

template <class Msg>
class Latest {
 public:
  Latest(ros::NodeHandle& nh, const std::string& topic)
      : sub_(nh.subscribe(topic, 100, &Latest::On, this)) {}
  bool WaitFor(const std::function<bool(const Msg&)>& ok, double seconds = 10.0) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && ros::WallTime::now() < end) {
      ros::spinOnce();
      for (const Msg& m : all_) {
        if (ok(m)) return true;
      }
      ros::WallDuration(0.01).sleep();
    }
    return false;
  }
  const Msg& msg() const { return all_.back(); }
  void Clear() { all_.clear(); }

 private:
  void On(const Msg& m) { all_.push_back(m); }
  ros::Subscriber sub_;
  std::vector<Msg> all_;
};

class TrPlusNodeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService("/tr_plus_node/load", ros::Duration(20)));
    conditions_ = nh_.advertise<spott_msgs::ConditionState>("/tr_plus_node/set_condition", 10);
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(10);
    while (conditions_.getNumSubscribers() == 0 && ros::WallTime::now() < end) {
      ros::WallDuration(0.01).sleep();
    }
  }
  void Push(const std::string& name, bool value, const std::string& distance = "") {
    spott_msgs::ConditionState c;
    c.name = name;
    c.value = value;
    if (!distance.empty()) {
      spott_msgs::Attribute a;
      a.key = "distance";
      a.value = distance;
      c.outputs.push_back(a);
    }
    conditions_.publish(c);
  }
  static std::function<bool(const spott_msgs::TRProgramState&)> Firing(uint32_t rule) {
    return [rule](const spott_msgs::TRProgramState& s) {
      return s.firing_program == "m" && s.firing_rule == rule;
    };
  }
  ros::NodeHandle nh_;
  ros::Publisher conditions_;
};

TEST_F(TrPlusNodeTest, StateFollowsConditionsAndActionsGetOutputVariables) {
  Latest<spott_msgs::TRProgramState> state(nh_, "/tr_plus_node/state");
  Latest<std_msgs::String> events(nh_, "/tr_plus_node/action_events");
  Latest<std_msgs::String> dot(nh_, "/tr_plus_node/tree_dot");
  ASSERT_TRUE(state.WaitFor(Firing(2)));
  EXPECT_EQ(state.msg().firing_action, "wander");
  EXPECT_EQ(state.msg().call_chain, std::vector<std::string>{"m"});
  Push("near(\"door\")", true, "1.5");
  ASSERT_TRUE(state.WaitFor(Firing(1)));
  ASSERT_TRUE(events.WaitFor([](const std_msgs::String& s) {
    return s.data.find("approach(\"door\", 1.5)") != std::string::npos;
  })) << "no start of approach with the bound distance";
  ASSERT_TRUE(dot.WaitFor([](const std_msgs::String& s) {
    return s.data.find("K2 -> K1 [label=\"a2: approach(\\\"door\\\", dist)\", color=red") !=
           std::string::npos;
  }));
  // The node survives a message naming no condition and keeps its state.
  Push("flying", true);
  Push("goal", true);
  ASSERT_TRUE(state.WaitFor(Firing(0)));
  ASSERT_TRUE(events.WaitFor([](const std_msgs::String& s) {
    return s.data.find("stop") == 0 && s.data.find("approach") != std::string::npos;
  }));
  Push("goal", false);
  ASSERT_TRUE(state.WaitFor(Firing(1)));
}

TEST_F(TrPlusNodeTest, BadProgramIsRefusedWithLocatedErrorsAndTheOldOneKeepsRunning) {
  spott_msgs::LoadTRProgram srv;
  srv.request.text = "condition a;\nmain m {\n  a -> ;\n}\n";
  ASSERT_TRUE(ros::service::call("/tr_plus_node/load", srv));
  EXPECT_FALSE(srv.response.success);
  ASSERT_FALSE(srv.response.errors.empty());
  EXPECT_EQ(srv.response.errors[0].rfind("<request>:3:8: expected an action", 0), 0u)
      << srv.response.errors[0];
  srv.request.text = "condition a;\nmain m {\n  a -> fly;\n}\n";
  ASSERT_TRUE(ros::service::call("/tr_plus_node/load", srv));
  EXPECT_FALSE(srv.response.success);
  EXPECT_EQ(srv.response.errors[0], "<request>:3:8: undefined action or subroutine 'fly'");
  // The running program still reacts.
  Latest<spott_msgs::TRProgramState> state(nh_, "/tr_plus_node/state");
  Push("goal", false);
  Push("near(\"door\")", false);
  ASSERT_TRUE(state.WaitFor(Firing(2)));
  Push("goal", true);
  ASSERT_TRUE(state.WaitFor(Firing(0)));
}

TEST_F(TrPlusNodeTest, GoodProgramReplacesTheRunningOneAndReportsItsVerdict) {
  spott_msgs::LoadTRProgram srv;
  srv.request.text =
      "condition a;\naction x;\nmain n {\n  a -> nil;\n  not a -> x effects { a };\n}\n";
  ASSERT_TRUE(ros::service::call("/tr_plus_node/load", srv));
  EXPECT_TRUE(srv.response.success);
  EXPECT_EQ(srv.response.verdict, "n: universal\n");
  Latest<spott_msgs::TRProgramState> state(nh_, "/tr_plus_node/state");
  ASSERT_TRUE(state.WaitFor([](const spott_msgs::TRProgramState& s) {
    return s.program == "n" && s.firing_rule == 1 && s.firing_action == "x";
  }));
  // Back to the test program for the other tests.
  srv.request.text.clear();
  ros::NodeHandle pnh("~");
  ASSERT_TRUE(pnh.getParam("program_file", srv.request.path));
  ASSERT_TRUE(ros::service::call("/tr_plus_node/load", srv));
  EXPECT_TRUE(srv.response.success);
}

TEST_F(TrPlusNodeTest, ParseTaskInterpretsOrReportsTheColumn) {
  spott_msgs::ParseTask srv;
  srv.request.command = "go near door(3.2, 1.0) quickly";
  ASSERT_TRUE(ros::service::call("/tr_plus_node/parse_task", srv));
  EXPECT_TRUE(srv.response.success);
  EXPECT_EQ(srv.response.interpretation.rfind("go to; goal region within", 0), 0u)
      << srv.response.interpretation;
  srv.request.command = "go near table(1, 2)";
  ASSERT_TRUE(ros::service::call("/tr_plus_node/parse_task", srv));
  EXPECT_FALSE(srv.response.success);
  EXPECT_EQ(srv.response.message.rfind("task:1:9: expected a target after 'near'", 0), 0u)
      << srv.response.message;
}

TEST(TrPlusNodeParameters, BadParametersAreRefusedByName) {
  std::string program;
  ros::NodeHandle("~").getParam("program_file", program);
  const auto run = spott_ros::testing::RunNode(
      TR_PLUS_NODE_EXE, "__name:=bad_tr_plus _program_file:=" + program +
                            " _task/near_distnce_m:=1.0 _max_call_depth:=0 _main:=7");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  for (const char* key :
       {"~task/near_distnce_m is not a parameter", "~max_call_depth must be >= 1", "~main"}) {
    EXPECT_NE(run.output.find(key), std::string::npos) << key << " in:\n" << run.output;
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "tr_plus_node_rostest");
  return RUN_ALL_TESTS();
}
