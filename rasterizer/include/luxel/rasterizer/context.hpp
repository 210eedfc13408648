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
class DepthStencilTarget;
class Context;
struct Image;

namespace detail {
class CommandQueue;

/// Which Context's pending frame refers to the object holding this (see "The deferred frame"
/// below), if any. The holder declares it first among its members, so that copying or moving the
/// holder (or assigning to it) runs that frame before the holder's other members change, and calls
/// release() from its destructor, before any member is destroyed.
class PendingUse {
 public:
  PendingUse() = default;
  /// A copy is referred to by no frame; the original's pending frame runs first.
  PendingUse(const PendingUse& other) { other.flush(); }
  PendingUse& operator=(const PendingUse& other) {
    flush();
    other.flush();
    return *this;
  }
  ~PendingUse() = default;

  /// Runs the pending frame that refers to the holder (Context::flush), if any.
  void flush() const;
  /// The same, and the context forgets the holder (an occlusion query it counts into ends).
  void release() const;

 private:
  friend class luxel::rasterizer::Context;
  mutable Context* context_ = nullptr;
};
}  // namespace detail

/// Counts the samples that pass every test (coverage, discard, alpha, stencil, depth) in the
/// draws made between Context::begin_query and Context::end_query. Exact, like D3D9's
/// D3DQUERYTYPE_OCCLUSION, and in samples (not pixels). Read it with Context::query_result.
/// Destroying a query flushes the context that counts into it, if any, and ends it there (see
/// "The deferred frame"); copying one flushes first.
class OcclusionQuery {
 public:
  OcclusionQuery() = default;
  OcclusionQuery(const OcclusionQuery&) = default;
  OcclusionQuery& operator=(const OcclusionQuery&) = default;
  ~OcclusionQuery() { use_.release(); }

 private:
  friend class Context;
  detail::PendingUse use_;  // first: see PendingUse
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
  /// Each thread starts on a home block of consecutive items (thread t on the t-th of
  /// thread_count() equal blocks) and, that done, takes items from the far ends of the others':
  /// a thread meets the same items from call to call, and the data they write stays in its caches
  /// (the tiles of a flush, the chunks of a draw). Denormals are flushed to zero on every thread
  /// while fn runs. Not reentrant.
  void parallel_for(int count, const std::function<void(int item, int thread)>& fn);

  // --- The deferred frame ------------------------------------------------------------------
  // Draws, clears and resolves are recorded and run tile by tile at the next flush. Reading a
  // target's samples directly (ColorTarget::sample...) needs a flush() first; resolve() and
  // query_result() flush by themselves. Data a pixel functor points to must stay alive until then.
  //
  // Render targets and occlusion queries know which context's pending frame refers to them (one
  // pointer, set when a draw, clear or begin_query records them: nothing per triangle or sample).
  // Destroying, moving, copying or assigning to one that a pending frame refers to flushes that
  // context first, in every build: the frame's effects on it and on every other target are then
  // complete, and nothing refers to freed memory. A destroyed query also ends if it was active.
  // A target or query is referred to by one context at a time: recording it in a second context
  // flushes the first (so the frames run in the order they were recorded). resolve() flushes at
  // once, so no frame keeps referring to an Image. Flushing from a destructor is flushing: it must
  // happen on the thread that drives the context.

  /// Runs everything recorded so far. This and the flushes that resolve() and query_result()
  /// make end a frame: they apply discard() (framebuffer.hpp). The flushes the context makes by
  /// itself (a target of another size, the record budget, a target or query released) keep
  /// every sample for the rest of the frame.
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
  /// A flush the context makes by itself (see flush()): used by draw() and the commands.
  void flush_within_frame();
  /// What a recorded command does with a target.
  enum class Access {
    use,          ///< draws into it, or clears part of it
    whole_clear,  ///< gives every sample a value (clear_color, clear_depth_stencil, load_image)
    resolve,      ///< reads it for a resolve, which discard() allows before the flush
  };
  /// Notes that the frame being recorded refers to `target` (used by the same), flushing the
  /// context whose frame referred to it until now, if another. Throws std::logic_error for a
  /// use that discard() forbids.
  void refer(const ColorTarget& target, Access access = Access::use);
  void refer(const DepthStencilTarget& target, Access access = Access::use);
  /// discard() (framebuffer.hpp).
  void discard(const ColorTarget& target);
  void discard(const DepthStencilTarget& target);

 private:
  friend class detail::PendingUse;
  static ContextOptions with_threads(int threads) {
    ContextOptions options;
    options.threads = threads;
    return options;
  }
  void worker_main(int thread);
  void run_items(int thread);
  /// Runs the pending frame and forgets what it referred to; `ends_frame` for flush() (see there).
  void flush_frame(bool ends_frame);
  void run_frame(bool ends_frame);
  /// Forgets the frame that ran, keeping the discard()s a frame that does not end carries on.
  void end_frame(bool ends_frame);
  void refer(const detail::PendingUse& use);
  template <class Target>
  void refer_target(const Target& target, Access access);
  template <class Target>
  void discard_target(const Target& target);
  /// PendingUse::release: flushes, and the holder is no longer the active query.
  void release(const detail::PendingUse& use);

  ContextOptions options_;
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const std::function<void(int, int)>* job_ = nullptr;
  // Written under mutex_; atomic so that threads can spin on them before blocking.
  std::atomic<uint64_t> generation_{0};
  std::atomic<int> busy_workers_{0};
  bool stopping_ = false;
  struct ItemBlock;  // a home block of parallel_for's items (context.cpp)
  std::unique_ptr<ItemBlock[]> item_blocks_;  ///< one per thread
  OcclusionQuery* active_query_ = nullptr;
  uint64_t flush_count_ = 0;
  std::unique_ptr<detail::CommandQueue> queue_;
  std::vector<const detail::PendingUse*> pending_uses_;  ///< the objects this context refers to
  std::unique_ptr<DrawStats> stats_;
};

}  // namespace luxel::rasterizer
