// Conversions between interpreter states / condition messages and spott_msgs.
#include <gtest/gtest.h>

#include "spott_tr_plus/parser.h"
#include "spott_tr_plus/ros/conversions.h"
#include "spott_tr_plus/value.h"

namespace spott_tr_plus {
namespace {

namespace conv = ros_conversions;

ProgramFile Program() {
  const ParseResult r = ParseProgramText(
      "condition goal; condition near(place, out distance); action approach(p, d); action "
      "wander;\n"
      "main m { goal -> nil; near(\"door\", d) -> approach(\"door\", d); true -> SUB(2); }\n"
      "sub SUB(x) { goal -> nil; true -> wander; }",
      "c.tr");
  EXPECT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  return r.program;
}

TEST(Conversions, ValuesRoundTripThroughText) {
  for (const Value& v : {Value{}, Value{true}, Value{false}, Value{1.5},
                         Value{std::string("a,\"b")}, Value{std::vector<double>{1, -2.5}}}) {
    EXPECT_EQ(ValueFromText(ValueToString(v)), v) << ValueToString(v);
  }
  EXPECT_EQ(ValueFromText("kitchen"), Value{std::string("kitchen")});
  // condition_state_fuzz: 15 digits lost the value of a 30-digit input (4.44444444444444e+29).
  for (const double d : {444444444444444444444444444444.0, 1.0 / 3.0, -2.0 / 7.0e-200}) {
    EXPECT_EQ(ValueFromText(ValueToString(Value{d})), Value{d}) << ValueToString(Value{d});
    EXPECT_EQ(ValueFromText(ValueToString(Value{std::vector<double>{d, 1.0}})),
              (Value{std::vector<double>{d, 1.0}}));
  }
  EXPECT_EQ(ValueToString(Value{0.1}), "0.1") << "the shortest text that reads back";
}

TEST(Conversions, StateNamesTheDeepestFiringRuleAndEveryProcess) {
  const ProgramFile file = Program();
  InterpreterState s;
  s.main = "m";
  FrameState main;
  main.program = "m";
  main.firing_rule = 2;
  FrameState sub;
  sub.program = "SUB";
  sub.args = {"2"};
  sub.depth = 1;
  sub.caller = 0;
  sub.firing_rule = 1;
  sub.action_running = true;
  s.frames = {main, sub};
  ProcessState p;
  p.name = "near(\"door\")";
  p.value = true;
  p.active = true;
  p.semantics = Semantics::kBallistic;
  p.frequency_hz = 2;
  p.last_update = 3.5;
  p.outputs = {{"distance", "1.25"}};
  s.processes = {p};
  const spott_msgs::TRProgramState m = conv::ToMsg(s, file, ros::Time(10.0));
  EXPECT_EQ(m.program, "m");
  EXPECT_EQ(m.call_chain, (std::vector<std::string>{"m", "SUB(2)"}));
  EXPECT_EQ(m.firing_program, "SUB");
  EXPECT_EQ(m.firing_rule, 1u);
  EXPECT_EQ(m.firing_action, "wander");
  EXPECT_TRUE(m.action_running);
  ASSERT_EQ(m.conditions.size(), 1u);
  EXPECT_EQ(m.conditions[0].semantics, spott_msgs::ConditionState::BALLISTIC);
  EXPECT_DOUBLE_EQ(m.conditions[0].last_update.toSec(), 3.5);
  EXPECT_EQ(m.conditions[0].outputs[0].key, "distance");
  EXPECT_EQ(m.conditions[0].outputs[0].value, "1.25");
}

TEST(Conversions, ConditionMessageWithInputsAndOutputs) {
  const ProgramFile file = Program();
  spott_msgs::ConditionState msg;
  msg.name = "near(\"door\")";
  msg.value = true;
  spott_msgs::Attribute a;
  a.key = "distance";
  a.value = "0.75";
  msg.outputs.push_back(a);
  conv::ConditionUpdate u;
  std::string error;
  ASSERT_TRUE(conv::FromMsg(msg, file, &u, &error)) << error;
  EXPECT_EQ(u.name, "near");
  EXPECT_EQ(u.inputs, std::vector<Value>{Value{std::string("door")}});
  EXPECT_EQ(u.outputs, std::vector<Value>{Value{0.75}});
  EXPECT_TRUE(u.value);
}

TEST(Conversions, BadConditionMessagesAreRefusedWithAReason) {
  const ProgramFile file = Program();
  conv::ConditionUpdate u;
  std::string error;
  spott_msgs::ConditionState msg;
  msg.name = "flying";
  EXPECT_FALSE(conv::FromMsg(msg, file, &u, &error));
  EXPECT_EQ(error, "no condition named 'flying' in the running program");
  msg.name = "near";
  EXPECT_FALSE(conv::FromMsg(msg, file, &u, &error));
  EXPECT_EQ(error, "condition 'near' takes 1 input(s), the message gives 0");
  msg.name = "goal";
  spott_msgs::Attribute a;
  a.key = "x";
  msg.outputs.push_back(a);
  EXPECT_FALSE(conv::FromMsg(msg, file, &u, &error));
  EXPECT_EQ(error, "condition 'goal' has no output named 'x'");
}

}  // namespace
}  // namespace spott_tr_plus
