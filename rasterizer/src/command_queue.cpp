#include "luxel/rasterizer/detail/command_queue.hpp"

#include "luxel/rasterizer/draw.hpp"

#include <algorithm>

namespace luxel::rasterizer::detail {

struct CommandQueue::ThreadStats {
  alignas(64) DrawStats stats;  // alignas rounds the size up to whole lines too
};

CommandQueue::CommandQueue() : front_end_stats_(std::make_unique<DrawStats>()) {}
CommandQueue::~CommandQueue() = default;

std::vector<ChunkBins*> CommandQueue::allocate_chunks(int count) {
  std::vector<ChunkBins*> chunks;
  for (int i = 0; i < count; ++i) {
    if (chunks_used_ == chunk_pool_.size()) chunk_pool_.push_back(std::make_unique<ChunkBins>());
    ChunkBins* c = chunk_pool_[chunks_used_++].get();
    c->reset(layout_.tile_count());
    chunks.push_back(c);
  }
  return chunks;
}

int CommandQueue::query_slot(OcclusionQuery* query) {
  if (!query) return -1;
  const auto it = std::find(queries_.begin(), queries_.end(), query);
  if (it != queries_.end()) return static_cast<int>(it - queries_.begin());
  queries_.push_back(query);
  return static_cast<int>(queries_.size()) - 1;
}

std::span<ThreadCounters> CommandQueue::thread_counters(int threads) {
  constexpr size_t kPerLine = 64 / sizeof(uint64_t);
  const size_t stride = (queries_.size() + kPerLine - 1) / kPerLine * kPerLine;
  query_samples_.assign(stride * size_t(threads), 0);
  thread_stats_.assign(size_t(threads), {});
  thread_counters_.resize(size_t(threads));
  for (size_t t = 0; t < size_t(threads); ++t)
    thread_counters_[t] = {query_samples_.data() + t * stride, &thread_stats_[t].stats};
  return thread_counters_;
}

std::byte* CommandQueue::tile_memory(int thread, size_t bytes) {
  if (tile_memory_.size() <= size_t(thread)) tile_memory_.resize(size_t(thread) + 1);
  SurfaceBuffer<std::byte>& memory = tile_memory_[size_t(thread)];
  if (memory.size() < bytes) memory = SurfaceBuffer<std::byte>(bytes);
  return memory.data();
}

void CommandQueue::reset() {
  commands_.clear();
  color_targets_.clear();
  depth_targets_.clear();
  chunks_used_ = 0;
  pending_record_bytes_ = 0;
  queries_.clear();
  *front_end_stats_ = {};
}

}  // namespace luxel::rasterizer::detail
