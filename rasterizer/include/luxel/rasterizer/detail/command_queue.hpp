#pragma once
// Private: the deferred frame. Draws run their front end (vertex functor, clip, setup, binning)
// when they are issued; everything that touches render-target memory (clears, rasterization,
// resolves) is queued as per-tile commands and runs at the next flush, tile by tile, in issue
// order. A tile's samples then stay in cache across all the draws of a frame instead of
// streaming through memory once per draw (llvmpipe's "scene").

#include "luxel/rasterizer/detail/triangle_setup.hpp"
#include "luxel/rasterizer/framebuffer.hpp"

#include <memory>
#include <span>
#include <vector>

namespace luxel::rasterizer {
struct DrawStats;
class OcclusionQuery;
}

namespace luxel::rasterizer::detail {

/// What the tiles one thread runs accumulate while they run their commands; summed over the
/// threads after the flush (integer sums: the totals do not depend on which thread ran which tile).
/// Each thread's counters lie on cache lines that no other thread writes: counters per tile, side
/// by side and written tile after tile by every thread, made the threads wait on each other's
/// lines (bench/README.md).
struct ThreadCounters {
  uint64_t* query_samples = nullptr;  ///< per query slot (owned by the queue)
  DrawStats* stats = nullptr;         ///< owned by the queue
};

class Command {
 public:
  virtual ~Command() = default;
  /// Runs the command on one tile. Called once per tile, from any thread, with that thread's
  /// counters.
  virtual void execute(int tile, ThreadCounters& counters) = 0;
};

class CommandQueue {
 public:
  CommandQueue();
  ~CommandQueue();

  /// Makes `layout` the tiling of the pending frame; returns false when a different tiling is
  /// pending (the caller must flush first).
  bool accepts(const SurfaceLayout& layout) const { return commands_.empty() || layout_ == layout; }
  void set_layout(const SurfaceLayout& layout) { layout_ = layout; }
  const SurfaceLayout& layout() const { return layout_; }
  bool empty() const { return commands_.empty(); }

  /// Chunks for a draw's front end, reset and stable until the flush.
  std::vector<ChunkBins*> allocate_chunks(int count);
  /// Bytes the chunks of the pending frame hold (ChunkBins::bytes).
  size_t pending_record_bytes() const { return pending_record_bytes_; }
  void add_pending_record_bytes(size_t n) { pending_record_bytes_ += n; }

  void push(std::unique_ptr<Command> command) { commands_.push_back(std::move(command)); }

  /// Slot of `query` among the queries counted in this frame.
  int query_slot(OcclusionQuery* query);

  std::vector<std::unique_ptr<Command>>& commands() { return commands_; }
  std::vector<OcclusionQuery*>& queries() { return queries_; }
  /// Zeroed counters for each of `threads` threads, with a slot for each of queries().
  std::span<ThreadCounters> thread_counters(int threads);
  DrawStats& front_end_stats() { return *front_end_stats_; }

  /// The targets the pending frame refers to (Context::refer), for tile memory.
  std::vector<const ColorTarget*>& color_targets() { return color_targets_; }
  std::vector<const DepthStencilTarget*>& depth_targets() { return depth_targets_; }
  /// Thread `thread`'s tile memory, at least `bytes` long (kept from flush to flush).
  std::byte* tile_memory(int thread, size_t bytes);
  /// Forgets the executed frame, keeping the memory.
  void reset();

 private:
  SurfaceLayout layout_;
  std::vector<std::unique_ptr<Command>> commands_;
  std::vector<std::unique_ptr<ChunkBins>> chunk_pool_;
  size_t chunks_used_ = 0;
  size_t pending_record_bytes_ = 0;
  std::vector<OcclusionQuery*> queries_;
  struct ThreadStats;  // a DrawStats on cache lines of its own
  std::vector<ThreadCounters> thread_counters_;
  std::vector<ThreadStats> thread_stats_;
  std::vector<uint64_t, xsimd::aligned_allocator<uint64_t, 64>> query_samples_;  ///< a line-aligned run per thread
  std::unique_ptr<DrawStats> front_end_stats_;
  std::vector<const ColorTarget*> color_targets_;
  std::vector<const DepthStencilTarget*> depth_targets_;
  std::vector<SurfaceBuffer<std::byte>> tile_memory_;  ///< per thread
};

}  // namespace luxel::rasterizer::detail
