// A pool of helper threads that sleep between jobs (the multi-threaded golden's helpers, and the
// second thread of its benchmark's ceilings, tools/bench_golden.cpp).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace trirast {

// The helper threads of one engine: started by its first parallel run, asleep between runs, and
// joined when the engine is destroyed. Starting a thread per run and joining it cost the writer
// a few percent of a 3 ms run on 100,000 triangles here (clone and exit on a virtual machine, seen
// with a timestamped build); waking a sleeping helper costs the writer only the notify, and at the
// end of a run the writer waits only for helpers to leave the job, not for threads to exit.
class HelperPool {
 public:
  using Job = std::function<void(size_t)>;  // called with the helper's id, 1..count

  HelperPool() = default;
  HelperPool(const HelperPool&) = delete;
  HelperPool& operator=(const HelperPool&) = delete;
  ~HelperPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      quit_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
  }

  // Starts helpers until there are `count` (fewer if the system gives no more threads); returns
  // how many there are.
  size_t reserve(size_t count) {
    while (threads_.size() < count) {
      try {
        const size_t id = threads_.size() + 1;
        threads_.emplace_back([this, id] { serve(id); });
      } catch (const std::system_error&) {
        break;  // the writer takes whatever the helpers there are leave
      }
    }
    return threads_.size();
  }

  // Runs job(id) on helpers 1..count (count <= reserve()'s answer) and returns at once; finish()
  // must be called before `job` or anything it refers to goes away.
  void start(const Job& job, size_t count) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = &job;
      active_ = count;
      finished_.store(0, std::memory_order_relaxed);
      ++generation_;
    }
    wake_.notify_all();
  }

  // Waits until every helper of the job has returned from it.
  void finish() {
    while (finished_.load(std::memory_order_acquire) < active_) std::this_thread::yield();
  }

 private:
  void serve(size_t id) {
    uint64_t seen = 0;
    for (;;) {
      const Job* job = nullptr;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return quit_ || generation_ != seen; });
        if (quit_) return;
        seen = generation_;
        if (id > active_) continue;  // not needed for this job
        job = job_;
      }
      (*job)(id);
      finished_.fetch_add(1, std::memory_order_release);
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<std::thread> threads_;
  const Job* job_ = nullptr;
  size_t active_ = 0;
  uint64_t generation_ = 0;
  bool quit_ = false;
  std::atomic<size_t> finished_{0};
};

}  // namespace trirast
