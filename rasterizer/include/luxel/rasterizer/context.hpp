#pragma once
// A Context owns the worker threads (and nothing global exists besides it). Work is handed out
// as independent items (tiles, chunks of triangles) by index; which thread runs which item
// varies from run to run, so every item must write only memory that it alone owns. Output bytes
// then never depend on the thread count.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace luxel::rasterizer {

class Context {
 public:
  /// `threads` = 0 means one per hardware thread. The calling thread is one of them: a Context
  /// with 1 thread starts no worker.
  explicit Context(int threads = 0);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  int thread_count() const { return static_cast<int>(workers_.size()) + 1; }

  /// Runs fn(item, thread) for item in [0, count), spread over all threads, and returns when all
  /// are done. `thread` in [0, thread_count()) names the thread (for per-thread scratch memory).
  /// Denormals are flushed to zero on every thread while fn runs. Not reentrant.
  void parallel_for(int count, const std::function<void(int item, int thread)>& fn);

 private:
  void worker_main(int thread);
  void run_items(int thread);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const std::function<void(int, int)>* job_ = nullptr;
  int job_count_ = 0;
  uint64_t generation_ = 0;
  int busy_workers_ = 0;
  bool stopping_ = false;
  alignas(64) std::atomic<int> next_item_{0};
};

}  // namespace luxel::rasterizer
