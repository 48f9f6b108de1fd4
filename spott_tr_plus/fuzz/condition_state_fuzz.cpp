// tr_plus_node's external conditions: a spott_msgs/ConditionState built from the fuzzer's bytes
// (the name with its written inputs, any output attributes) through ros_conversions::FromMsg
// against a program that declares conditions with and without inputs and outputs. Properties:
// no crash or sanitizer report; a refusal says why; an accepted update names a declared
// condition with its number of inputs and one value per declared output, and every value
// survives a round trip through its text (what the node publishes back in TRProgramState).
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_values.h"
#include "spott_tr_plus/parser.h"
#include "spott_tr_plus/ros/conversions.h"
#include "spott_tr_plus/value.h"

namespace conv = spott_tr_plus::ros_conversions;

namespace {

void Check(bool ok, const char* what) { spott_fuzz::Check(ok, "condition_state_fuzz", what); }

const spott_tr_plus::ProgramFile& Program() {
  static const spott_tr_plus::ProgramFile program = [] {
    const auto r = spott_tr_plus::ParseProgramText(
        "condition goal; condition near(place, out distance); "
        "condition seen(a, b, out where, out size); action approach(p, d); action wander;\n"
        "main m { goal -> nil; near(\"door\", d) -> approach(\"door\", d); "
        "seen(1, \"x\", w, s) -> wander; true -> wander; }",
        "fuzz.tr");
    if (!r.ok()) std::abort();
    return r.program;
  }();
  return program;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 4096) return 0;
  FuzzedDataProvider in(data, size);
  spott_msgs::ConditionState msg;
  msg.name = in.ConsumeRandomLengthString(256);
  msg.value = in.ConsumeBool();
  const int n = in.ConsumeIntegralInRange<int>(0, 4);
  for (int i = 0; i < n; ++i) {
    spott_msgs::Attribute a;
    a.key = in.ConsumeBool() ? std::string(in.ConsumeBool() ? "distance" : "where")
                             : in.ConsumeRandomLengthString(16);
    a.value = in.ConsumeRandomLengthString(128);
    msg.outputs.push_back(a);
  }
  conv::ConditionUpdate u;
  std::string error;
  if (!conv::FromMsg(msg, Program(), &u, &error)) {
    Check(!error.empty(), "refused without a reason");
    return 0;
  }
  const spott_tr_plus::ConditionDecl* d = Program().FindCondition(u.name);
  Check(d != nullptr, "accepted an undeclared condition");
  Check(static_cast<int>(u.inputs.size()) == d->NumInputs(), "wrong number of inputs");
  int outputs = 0;
  for (const auto& p : d->params) outputs += p.is_output;
  Check(static_cast<int>(u.outputs.size()) == outputs, "not one value per declared output");
  for (const auto* values : {&u.inputs, &u.outputs}) {
    for (const spott_tr_plus::Value& v : *values) {
      const std::string text = spott_tr_plus::ValueToString(v);
      Check(spott_tr_plus::ValueFromText(text) == v, "a value that does not survive its text");
    }
  }
  return 0;
}
