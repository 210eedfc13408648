#pragma once
// Private: the deferred frame. Draws run their front end (vertex functor, clip, setup, binning)
// when they are issued; everything that touches render-target memory (clears, rasterization,
// resolves) is queued as per-tile commands and runs at the next flush, tile by tile, in issue
// order. A tile's samples then stay in cache across all the draws of a frame instead of
// streaming through memory once per draw (llvmpipe's "scene").

#include "luxel/rasterizer/detail/triangle_setup.hpp"
#include "luxel/rasterizer/framebuffer.hpp"

#include <memory>
#include <vector>

namespace luxel::rasterizer {
struct DrawStats;
class OcclusionQuery;
}

namespace luxel::rasterizer::detail {

/// What a tile accumulates while it runs its commands; summed in tile order after the flush.
struct TileCounters {
  std::vector<uint64_t> query_samples;  ///< per query slot
  DrawStats* stats = nullptr;           ///< per-tile stats (owned by the queue)
};

class Command {
 public:
  virtual ~Command() = default;
  /// Runs the command on one tile. Called once per tile, from any thread.
  virtual void execute(int tile, TileCounters& counters) = 0;
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
  uint64_t pending_triangles() const { return pending_triangles_; }
  void add_pending_triangles(uint64_t n) { pending_triangles_ += n; }

  void push(std::unique_ptr<Command> command) { commands_.push_back(std::move(command)); }

  /// Slot of `query` among the queries counted in this frame.
  int query_slot(OcclusionQuery* query);

  std::vector<std::unique_ptr<Command>>& commands() { return commands_; }
  std::vector<OcclusionQuery*>& queries() { return queries_; }
  std::vector<TileCounters>& tile_counters() { return tile_counters_; }
  std::vector<DrawStats>& tile_stats() { return tile_stats_; }
  DrawStats& front_end_stats() { return *front_end_stats_; }

  /// Forgets the executed frame, keeping the memory.
  void reset();

 private:
  SurfaceLayout layout_;
  std::vector<std::unique_ptr<Command>> commands_;
  std::vector<std::unique_ptr<ChunkBins>> chunk_pool_;
  size_t chunks_used_ = 0;
  uint64_t pending_triangles_ = 0;
  std::vector<OcclusionQuery*> queries_;
  std::vector<TileCounters> tile_counters_;
  std::vector<DrawStats> tile_stats_;
  std::unique_ptr<DrawStats> front_end_stats_;
};

/// Most triangles binned before the queue flushes on its own, in the middle of a draw if need be.
/// Small enough that the binned records (~100 bytes a triangle) are still in the cache when the
/// tiles read them, large enough that the tiles' samples are not fetched too often: on W2
/// (1 M triangles in one draw) 2^16 took 92-99 ms a frame, 2^21 (never flushing) 110 ms, 2^18
/// 100 ms, 2^15 106 ms, 2^14 124 ms.
inline constexpr uint64_t kMaxPendingTriangles = uint64_t(1) << 16;

}  // namespace luxel::rasterizer::detail
