// Speed of the TR+ interpreter against a hand-written C++ if-chain of the same logic (the floor;
// BehaviorTree.CPP, the peer ROS users reach for, is not packaged in Debian). Answers the
// README's questions:
//  - per-condition evaluation cost (paper, SPOTT III-E: 25 us per condition per cycle; target
//    < 20 ns),
//  - cycle time (one full scan) of a 1,000-rule program (target < 20 us),
//  - latency from a condition change to the new rule's action starting (target: median
//    < 10 us, 99th percentile < 100 us),
//  - parse and check time of a 10,000-rule program.
// Counters: per_condition_ns, ratio_to_if_chain, median_us / p99_us.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "spott_tr_plus/checker.h"
#include "spott_tr_plus/interpreter.h"
#include "spott_tr_plus/parser.h"

namespace spott_tr_plus {
namespace {

// n rules `c_i -> a_i` above `true -> idle`: with every c_i FALSE a scan evaluates all n.
std::string ChainProgram(int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += "condition c" + std::to_string(i) + ";\n";
  for (int i = 0; i < n; ++i) s += "action a" + std::to_string(i) + ";\n";
  s += "action idle;\nmain m {\n";
  for (int i = 0; i < n; ++i) s += "  c" + std::to_string(i) + " -> a" + std::to_string(i) + ";\n";
  s += "  true -> idle;\n}\n";
  return s;
}

struct Setup {
  std::vector<char> values;
  int64_t started = -1;  // index of the last action started (n = idle)
  std::chrono::steady_clock::time_point started_at;
  std::unique_ptr<Interpreter> in;
};

// external: values pushed from outside (the interpreter reads its cached value);
// otherwise synchronous condition functions reading `values` on every scan.
std::unique_ptr<Setup> Make(int n, bool external) {
  auto s = std::make_unique<Setup>();
  s->values.assign(n, 0);
  Setup* raw = s.get();
  Registry r;
  for (int i = 0; i < n; ++i) {
    const std::string c = "c" + std::to_string(i);
    if (external) {
      r.ExternalCondition(c);
    } else {
      r.Condition(
          c, [raw, i](const ConditionCall&, std::vector<Value>&) { return raw->values[i] != 0; });
    }
    r.InstantAction("a" + std::to_string(i), [raw, i](const std::vector<Value>&, double) {
      raw->started = i;
      raw->started_at = std::chrono::steady_clock::now();
    });
  }
  // `idle` runs until stopped, as driving actions do (an instant energized action would be
  // re-run, and the program re-scanned, on every Scan() call).
  r.Action("idle", [raw, n](const ActionCall&) { raw->started = n; });
  const ParseResult p = ParseProgramText(ChainProgram(n), "bench.tr");
  std::vector<Diagnostic> d;
  s->in = Interpreter::Create(p.program, r, &d);
  if (!s->in) std::abort();
  s->in->Start(0.0);
  return s;
}

// The floor: the same rules as a hand-written if-chain over the same condition values.
int IfChain(const std::vector<char>& values) {
  const int n = static_cast<int>(values.size());
  for (int i = 0; i < n; ++i) {
    if (values[i]) return i;
  }
  return n;
}

double IfChainNsPerCondition(int n) {
  std::vector<char> v(n, 0);
  const int reps = 20000;
  int sink = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < reps; ++k) {
    benchmark::DoNotOptimize(v.data());
    sink += IfChain(v);
    benchmark::ClobberMemory();
  }
  const auto t1 = std::chrono::steady_clock::now();
  benchmark::DoNotOptimize(sink);
  return std::chrono::duration<double, std::nano>(t1 - t0).count() / reps / n;
}

void BM_IfChainScan(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<char> v(n, 0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(v.data());
    benchmark::DoNotOptimize(IfChain(v));
    benchmark::ClobberMemory();
  }
  state.counters["per_condition_ns"] = IfChainNsPerCondition(n);
}
BENCHMARK(BM_IfChainScan)->Arg(10)->Arg(1000);

// One full scan (cycle) of an n-rule program; all conditions FALSE, so all n are evaluated.
void ScanBench(benchmark::State& state, bool external) {
  const int n = static_cast<int>(state.range(0));
  auto s = Make(n, external);
  double now = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    now += 1e-3;
    s->in->Scan(now);
  }
  const auto t1 = std::chrono::steady_clock::now();
  if (s->started != n) std::abort();  // the scans fired `true -> idle`
  const double ours =
      std::chrono::duration<double, std::nano>(t1 - t0).count() / state.iterations() / n;
  const double floor = IfChainNsPerCondition(n);
  state.counters["per_condition_ns"] = ours;
  state.counters["if_chain_per_condition_ns"] = floor;
  state.counters["ratio_to_if_chain"] = ours / floor;
  state.counters["paper_per_condition_ns"] = 25000;
}
void BM_ScanExternalConditions(benchmark::State& state) { ScanBench(state, true); }
void BM_ScanSyncConditions(benchmark::State& state) { ScanBench(state, false); }
BENCHMARK(BM_ScanExternalConditions)->Arg(10)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScanSyncConditions)->Arg(10)->Arg(1000)->Unit(benchmark::kMicrosecond);

// Latency: the condition of rule k is pushed TRUE (then FALSE); measured from just before
// SetCondition to the start of that rule's action, event-driven (no tick). The interpreter acts
// as soon as it reaches the highest true rule, so the latency grows with the rules above it:
// k = n/2 is the typical case, k = n-1 (the bottom rule) the worst.
void BM_ChangeToActionLatency(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  auto s = Make(n, true);
  const std::string name = "c" + std::to_string(k);
  std::vector<double> samples;
  samples.reserve(1 << 16);
  double now = 0;
  for (auto _ : state) {
    now += 1e-3;
    const auto t0 = std::chrono::steady_clock::now();
    s->in->SetCondition(name, true, now);
    if (s->started != k) std::abort();
    samples.push_back(std::chrono::duration<double, std::micro>(s->started_at - t0).count());
    state.PauseTiming();
    s->in->SetCondition(name, false, now + 5e-4);
    state.ResumeTiming();
  }
  std::sort(samples.begin(), samples.end());
  state.counters["median_us"] = samples[samples.size() / 2];
  state.counters["p99_us"] = samples[std::min(samples.size() - 1, samples.size() * 99 / 100)];
}
BENCHMARK(BM_ChangeToActionLatency)
    ->Args({10, 5})
    ->Args({1000, 500})
    ->Args({1000, 999})
    ->Unit(benchmark::kMicrosecond);

void BM_ParseAndCheck(benchmark::State& state) {
  const std::string text = ChainProgram(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const ParseResult p = ParseProgramText(text, "big.tr");
    const CheckReport r = CheckProgram(p.program);
    if (!p.ok() || !r.ok() || !r.programs[0].complete) std::abort();
    benchmark::DoNotOptimize(r);
  }
  state.counters["bytes"] = static_cast<double>(text.size());
}
BENCHMARK(BM_ParseAndCheck)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace spott_tr_plus

BENCHMARK_MAIN();
