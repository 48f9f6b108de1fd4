#include "worker_pool.h"

#include <atomic>

namespace markov_localization {

namespace {
std::atomic<bool>& Enabled() {
  static std::atomic<bool> enabled{std::thread::hardware_concurrency() >= 2};
  return enabled;
}
}  // namespace

bool WorkerThreadsEnabled() { return Enabled().load(); }
void EnableWorkerThreads(bool enable) { Enabled().store(enable); }

WorkerPool::WorkerPool() : worker_([this] { Loop(); }) {}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  worker_.join();
}

void WorkerPool::Run(int count, const std::function<void(int)>& task) {
  std::lock_guard<std::mutex> serial(serial_);
  std::unique_lock<std::mutex> lock(mutex_);
  task_ = &task;
  count_ = count;
  next_ = 0;
  finished_ = 0;
  ++generation_;
  lock.unlock();
  wake_.notify_one();
  lock.lock();
  while (next_ < count_) {
    const int i = next_++;
    lock.unlock();
    task(i);
    lock.lock();
    ++finished_;
  }
  done_.wait(lock, [&] { return finished_ == count_; });
  task_ = nullptr;
}

void WorkerPool::Loop() {
  std::uint64_t seen = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    while (task_ && next_ < count_) {
      const int i = next_++;
      const auto* task = task_;
      lock.unlock();
      (*task)(i);
      lock.lock();
      if (++finished_ == count_) done_.notify_one();
    }
  }
}

}  // namespace markov_localization
