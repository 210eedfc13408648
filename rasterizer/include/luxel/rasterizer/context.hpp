#pragma once
// A Context owns the worker threads (and nothing global exists besides it). Work is handed out
// as independent items (tiles, chunks of triangles) by index; which thread runs which item
// varies from run to run, so every item must write only memory that it alone owns. Output bytes
// then never depend on the thread count.

#include "luxel/rasterizer/fast_paths.hpp"

#include <atomic>
#include <cstddef>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace luxel::rasterizer {

struct DrawStats;
class ColorTarget;
struct Image;

namespace detail {
class CommandQueue;
}

/// Counts the samples that pass every test (coverage, discard, alpha, stencil, depth) in the
/// draws made between Context::begin_query and Context::end_query. Exact, like D3D9's
/// D3DQUERYTYPE_OCCLUSION, and in samples (not pixels). Read it with Context::query_result.
class OcclusionQuery {
 private:
  friend class Context;
  uint64_t samples_ = 0;
};

/// How a Context runs. None of it changes the bytes a frame produces.
struct ContextOptions {
  /// 0 means one per hardware thread. The calling thread is one of them: with 1 thread no worker
  /// starts.
  int threads = 0;
  /// The fast paths the rasterizer may take (see fast_paths.hpp).
  FastPaths fast_paths;
  /// The deferred frame flushes by itself, in the middle of a draw if need be, once the records
  /// of the triangles binned since the last flush take this many bytes (checked between parts
  /// of at most kTrianglesPerPart triangles, so one part may go beyond it). A flush reads and
  /// writes every touched tile's samples once, so the larger the budget, the fewer times a
  /// frame's samples travel through memory; the smaller, the more of the records are still
  /// cached when the tiles read them.
  size_t max_pending_record_bytes = size_t(128) << 20;
};

class Context {
 public:
  explicit Context(int threads = 0) : Context(with_threads(threads)) {}
  explicit Context(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  int thread_count() const { return static_cast<int>(workers_.size()) + 1; }
  const ContextOptions& options() const { return options_; }

  /// Runs fn(item, thread) for item in [0, count), spread over all threads, and returns when all
  /// are done. `thread` in [0, thread_count()) names the thread (for per-thread scratch memory).
  /// Denormals are flushed to zero on every thread while fn runs. Not reentrant.
  void parallel_for(int count, const std::function<void(int item, int thread)>& fn);

  // --- The deferred frame ------------------------------------------------------------------
  // Draws, clears and resolves are recorded and run tile by tile at the next flush. Reading a
  // target's samples directly (ColorTarget::sample...) needs a flush() first; resolve() and
  // query_result() flush by themselves. Data a pixel functor points to must stay alive until then.

  /// Runs everything recorded so far.
  void flush();
  /// How many flushes had work to run, the ones the queue made by itself included.
  uint64_t flush_count() const { return flush_count_; }

  /// Starts counting into `query` (resetting it). One query is active at a time.
  void begin_query(OcclusionQuery& query);
  /// Stops counting into the active query.
  void end_query();
  /// The query's count (flushes first).
  uint64_t query_result(const OcclusionQuery& query);
  /// The query draws count into right now, or nullptr.
  OcclusionQuery* active_query() const { return active_query_; }

  /// What the draws did since the last reset_stats() (complete after a flush).
  const DrawStats& stats() const { return *stats_; }
  void reset_stats();

  /// The frame being recorded (used by draw() and the clear/resolve commands).
  detail::CommandQueue& queue() { return *queue_; }

 private:
  static ContextOptions with_threads(int threads) {
    ContextOptions options;
    options.threads = threads;
    return options;
  }
  void worker_main(int thread);
  void run_items(int thread);

  ContextOptions options_;
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const std::function<void(int, int)>* job_ = nullptr;
  int job_count_ = 0;
  // Written under mutex_; atomic so that threads can spin on them before blocking.
  std::atomic<uint64_t> generation_{0};
  std::atomic<int> busy_workers_{0};
  bool stopping_ = false;
  alignas(64) std::atomic<int> next_item_{0};
  OcclusionQuery* active_query_ = nullptr;
  uint64_t flush_count_ = 0;
  std::unique_ptr<detail::CommandQueue> queue_;
  std::unique_ptr<DrawStats> stats_;
};

}  // namespace luxel::rasterizer
