// What do 10,000 wait-blocked threads of control cost while nothing changes (issue 17: memory,
// and CPU, target 0)? Beside the peers' design (a monitor thread per condition that polls every
// 0.1 s, as PyCRAM's Monitor does), measured in the same run at 100 and 1,000 monitors.
//
// Run: ./spott bench rpl_idle (or the built rpl_executive_bench_rpl_idle).
#include <benchmark/benchmark.h>
#include <malloc.h>
#include <time.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include "rpl_executive/rpl/executive.h"
#include "rpl_executive/rpl/office_robot.h"

// Live heap bytes, counted by replacing the global allocation functions (malloc-based, so free
// matches them; GCC cannot see that through the replacement).
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
static std::atomic<long long> g_live_bytes{0};
void* operator new(std::size_t n) {
  void* p = std::malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  g_live_bytes += static_cast<long long>(malloc_usable_size(p));
  return p;
}
void operator delete(void* p) noexcept {
  if (!p) return;
  g_live_bytes -= static_cast<long long>(malloc_usable_size(p));
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

namespace {

using rpl_executive::rpl::Executive;
using rpl_executive::rpl::ExecutiveParameters;
using rpl_executive::rpl::Value;

double ProcessCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}

long ResidentKiB() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  return resident * 4;  // pages of 4 KiB
}

// N threads, each wait-blocked in WAIT-FOR (> X* 1000) (one condition node shared by all) or in
// WHENEVER over a condition of its own variable (a node each). Loaded, not started.
std::unique_ptr<Executive> Loaded(int n, bool per_thread) {
  ExecutiveParameters p;
  p.event_log_capacity = 0;
  auto e = std::make_unique<Executive>(p);
  for (const auto& f : rpl_executive::rpl::office::Fluents()) e->DeclareFluent(f);
  std::string plan =
      "(DEFUN SHARED () (WAIT-FOR (> X* 1000)))\n"
      "(DEFUN OWN (LIMIT) (WHENEVER (> X* LIMIT) (SETF LIMIT (+ LIMIT 1))))\n(PAR";
  for (int i = 0; i < n; ++i) {
    plan += per_thread ? " (OWN " + std::to_string(2000 + i) + ")" : " (SHARED)";
  }
  plan += n == 0 ? " (WAIT-FOR (> X* 1000)))" : ")";
  if (rpl_executive::rpl::HasErrors(e->Load(plan, "bench.rpl"))) std::abort();
  return e;
}

std::unique_ptr<Executive> Blocked(int n, bool per_thread) {
  auto e = Loaded(n, per_thread);
  if (!e->Start(0).empty()) std::abort();
  e->Step(0);
  return e;
}

// Heap of the running threads: after Start and the first Step (every thread wait-blocked) minus
// before Start (the loaded plan, whose text grows with N here, is not counted).
void BM_MemoryOfBlockedThreads(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bool per_thread = state.range(1) != 0;
  long long bytes = 0;
  for (auto _ : state) {
    auto e = Loaded(n, per_thread);
    const long long before = g_live_bytes.load();
    if (!e->Start(0).empty()) std::abort();
    e->Step(0);
    bytes = g_live_bytes.load() - before;
    if (e->NumLiveTasks() < static_cast<size_t>(n)) std::abort();
    state.counters["tasks"] = static_cast<double>(e->NumLiveTasks());
  }
  state.counters["threads"] = n;
  state.counters["bytes_per_thread"] = static_cast<double>(bytes) / n;
  state.counters["MiB_total"] = bytes / 1048576.0;
}
BENCHMARK(BM_MemoryOfBlockedThreads)
    ->ArgNames({"threads", "per_thread"})
    ->Args({10000, 0})
    ->Args({10000, 1})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// The node calls Step when a message came; a Step with nothing to do, with N threads blocked.
void BM_StepWhileNothingChanges(benchmark::State& state) {
  auto e = Blocked(static_cast<int>(state.range(0)), false);
  double now = 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(e->Step(now).instructions);
    now += 1e-6;
  }
}
BENCHMARK(BM_StepWhileNothingChanges)->ArgName("threads")->Arg(0)->Arg(10000);

// A fluent no waiting condition reads changes (O*, 10 Hz from the localization): no thread runs.
void BM_UnrelatedFluentChange(benchmark::State& state) {
  auto e = Blocked(static_cast<int>(state.range(0)), state.range(1) != 0);
  const int o = e->FluentIndex("O*");
  double now = 1, value = 0;
  for (auto _ : state) {
    e->SetFluent(o, Value::Number(value += 0.001), now);
    benchmark::DoNotOptimize(e->Step(now).instructions);
    now += 1e-6;
  }
}
BENCHMARK(BM_UnrelatedFluentChange)
    ->ArgNames({"threads", "per_thread"})
    ->Args({0, 0})
    ->Args({10000, 0})
    ->Args({10000, 1});

// CPU used by the process while 10,000 threads of control are wait-blocked and nothing happens
// for one second: there is no OS thread and no timer behind them.
void BM_IdleCpuOfTenThousandBlockedThreads(benchmark::State& state) {
  auto e = Blocked(10000, false);
  double cpu = 0;
  for (auto _ : state) {
    const double c0 = ProcessCpuSeconds();
    std::this_thread::sleep_for(std::chrono::seconds(1));
    cpu = ProcessCpuSeconds() - c0;
  }
  state.counters["cpu_s_per_s"] = cpu;
}
BENCHMARK(BM_IdleCpuOfTenThousandBlockedThreads)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The peers' design: a monitor thread per condition, polling every 100 ms (PyCRAM's Monitor),
// here in C++ (as fast as that design allows): CPU and resident memory of N monitors, 2 s.
void BM_PollingPeerIdle(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  double cpu_per_s = 0;
  long kib = 0;
  for (auto _ : state) {
    std::atomic<bool> stop{false};
    std::atomic<int> fired{0};
    volatile double certainty = 0.95;
    const long rss0 = ResidentKiB();
    const double c0 = ProcessCpuSeconds();
    std::vector<std::thread> monitors;
    monitors.reserve(n);
    for (int i = 0; i < n; ++i) {
      monitors.emplace_back([&] {
        while (!stop.load(std::memory_order_relaxed)) {
          std::this_thread::sleep_for(std::chrono::milliseconds(100));
          if (certainty <= 0.8) fired++;
        }
      });
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    kib = ResidentKiB() - rss0;
    const double c1 = ProcessCpuSeconds();
    std::this_thread::sleep_for(std::chrono::seconds(2));
    cpu_per_s = (ProcessCpuSeconds() - c1) / 2.0;
    stop = true;
    for (auto& m : monitors) m.join();
    (void)c0;
  }
  state.counters["monitors"] = n;
  state.counters["cpu_s_per_s"] = cpu_per_s;
  state.counters["cpu_s_per_s_per_10k"] = cpu_per_s * 10000.0 / n;
  state.counters["rss_KiB_per_monitor"] = static_cast<double>(kib) / n;
}
BENCHMARK(BM_PollingPeerIdle)
    ->ArgName("monitors")
    ->Arg(100)
    ->Arg(1000)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
