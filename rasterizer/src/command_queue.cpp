#include "luxel/rasterizer/detail/command_queue.hpp"

#include "luxel/rasterizer/draw.hpp"

#include <algorithm>

namespace luxel::rasterizer::detail {

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
