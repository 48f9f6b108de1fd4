// A pool of one worker thread besides the caller, for MarkovGrid's updates (private to the core).
// Run() hands out task indices to whichever thread is free, so a worker that the scheduler
// starts late (a loaded machine) only means the caller does more of the tasks itself. Tasks
// write their results to places of their own; the caller combines them in a fixed order, so
// results never depend on which thread ran what.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>

namespace markov_localization {

/// Whether grids built from now on get a worker thread (default: when the machine has at least
/// two cores). Tests switch it off to compare one thread with two.
bool WorkerThreadsEnabled();
void EnableWorkerThreads(bool enable);

class WorkerPool {
 public:
  WorkerPool();
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Runs task(i) for every i in [0, count), on the caller and the worker; returns when all
  /// have finished. One Run at a time (callers are serialized).
  void Run(int count, const std::function<void(int)>& task);

 private:
  void Loop();

  std::mutex serial_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int)>* task_ = nullptr;
  int count_ = 0, next_ = 0, finished_ = 0;
  std::uint64_t generation_ = 0;
  bool stop_ = false;
  std::thread worker_;
};

}  // namespace markov_localization
