// Fuzzes the TR+ interpreter: the input is a program, a line "%%", then events, one byte each
// (condition index and value, action completions, time steps). Every declared condition is
// external or asynchronous, every action long-running or instant, chosen from the name's
// length, so the interpreter meets calls, sequences, ballistic runs, timeouts and re-entrant
// completions; subroutines whose name length is a multiple of 3 are switched off. Properties: no
// crash or sanitizer report; the state stays consistent (at most one firing rule per frame,
// frames' callers precede them, no frame of a switched-off subroutine).
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "spott_tr_plus/interpreter.h"
#include "spott_tr_plus/parser.h"

using namespace spott_tr_plus;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 4096) return 0;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const size_t split = input.find("%%");
  const std::string text = input.substr(0, split);
  const std::string events = split == std::string::npos ? "" : input.substr(split + 2);
  const ParseResult parsed = ParseProgramText(text, "fuzz.tr");
  if (!parsed.ok()) return 0;
  Interpreter* self = nullptr;
  std::vector<Ticket> running;
  std::vector<Ticket> pending_conditions;
  Registry r;
  for (const auto& c : parsed.program.conditions) {
    if (c.name.size() % 2 == 0) {
      r.ExternalCondition(c.name);
    } else {
      r.AsyncCondition(
          c.name, [&](const ConditionCall& call) { pending_conditions.push_back(call.ticket); });
    }
  }
  for (const auto& a : parsed.program.actions) {
    if (a.name.size() % 2 == 0) {
      r.Action(
          a.name, [&](const ActionCall& call) { running.push_back(call.ticket); }, [](Ticket) {});
    } else {
      r.InstantAction(a.name, [](const std::vector<Value>&, double) {});
    }
  }
  Interpreter::Options options;
  options.max_call_depth = 8;
  options.max_events_per_advance = 200;
  const Program* main = parsed.program.Main();
  for (const Program& p : parsed.program.programs)
    if (p.name.size() % 3 == 0 && main && p.name != main->name)
      options.off_subroutines.push_back(p.name);
  std::vector<Diagnostic> d;
  auto in = Interpreter::Create(parsed.program, r, &d, "", options);
  if (!in) return 0;
  self = in.get();
  (void)self;
  double now = 0;
  in->Start(now);
  const auto& conds = parsed.program.conditions;
  for (unsigned char e : events) {
    now += 0.05 * (e & 7);
    switch (e >> 6) {
      case 0:
        if (!conds.empty()) {
          const auto& c = conds[(e >> 3) % conds.size()];
          std::vector<Value> inputs(c.NumInputs(), Value{1.0});
          in->SetCondition(c.name, (e & 1) != 0, now, {}, inputs);
        }
        break;
      case 1:
        if (!running.empty()) {
          const Ticket t = running[(e >> 3) % running.size()];
          in->CompleteAction(t, true, now);
        }
        break;
      case 2:
        if (!pending_conditions.empty()) {
          const Ticket t = pending_conditions.back();
          pending_conditions.pop_back();
          in->CompleteCondition(t, (e & 8) != 0, now, {Value{2.0}});
        }
        break;
      default:
        in->Advance(now);
        break;
    }
    const InterpreterState s = in->State();
    for (size_t i = 0; i < s.frames.size(); ++i) {
      const FrameState& f = s.frames[i];
      if (f.caller >= static_cast<int>(i)) std::abort();
      if (f.firing_rule >= static_cast<int>(f.rule_values.size())) std::abort();
      if (f.firing_rule >= 0 && !f.rule_values[f.firing_rule]) std::abort();
      for (const std::string& off : options.off_subroutines)
        if (f.program == off) std::abort();  // a switched-off subroutine was entered
      for (int k = 0; k < f.firing_rule; ++k) {
        if (f.rule_values[k]) std::abort();  // the firing rule is the highest true one
      }
    }
  }
  in->Stop(now);
  return 0;
}
