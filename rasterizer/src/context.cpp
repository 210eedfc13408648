#include "luxel/rasterizer/context.hpp"

#include "luxel/rasterizer/detail/command_queue.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/simd.hpp"

#include "tile_memory.hpp"

#include <xmmintrin.h>
#include <pmmintrin.h>

#include <algorithm>
#include <atomic>
#include <chrono>

namespace luxel::rasterizer {

namespace simd {
ScopedFlushDenormals::ScopedFlushDenormals() : saved_(_mm_getcsr()) {
  _mm_setcsr(saved_ | _MM_FLUSH_ZERO_ON | _MM_DENORMALS_ZERO_ON);
}
ScopedFlushDenormals::~ScopedFlushDenormals() { _mm_setcsr(saved_); }
}  // namespace simd

/// The items of one thread's home block not yet taken: [front, back), packed into one word so that
/// the owner (taking the front) and the others (taking the back) claim items with one CAS each.
/// On a line of its own: every claim writes it.
struct Context::ItemBlock {
  alignas(64) std::atomic<uint64_t> range{0};

  static uint64_t pack(uint32_t front, uint32_t back) { return uint64_t(back) << 32 | front; }
  void set(int front, int back) { range.store(pack(uint32_t(front), uint32_t(back)), std::memory_order_relaxed); }
  /// The next item from the front (the owner's end), or -1 when none is left.
  int take_front() { return take(true); }
  /// The next item from the back (the other threads' end), or -1 when none is left.
  int take_back() { return take(false); }

 private:
  int take(bool front_end) {
    uint64_t r = range.load(std::memory_order_relaxed);
    for (;;) {
      const uint32_t front = uint32_t(r), back = uint32_t(r >> 32);
      if (front >= back) return -1;
      const uint64_t next = front_end ? pack(front + 1, back) : pack(front, back - 1);
      if (range.compare_exchange_weak(r, next, std::memory_order_relaxed)) return int(front_end ? front : back - 1);
    }
  }
};

Context::Context(const ContextOptions& options)
    : options_(options), queue_(std::make_unique<detail::CommandQueue>()), stats_(std::make_unique<DrawStats>()) {
  int threads = options.threads;
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  options_.threads = threads;
  item_blocks_ = std::make_unique<ItemBlock[]>(size_t(threads));
  workers_.reserve(threads - 1);
  for (int t = 1; t < threads; ++t) workers_.emplace_back([this, t] { worker_main(t); });
}

namespace detail {
void PendingUse::flush() const {
  if (context_) context_->flush_within_frame();
}
void PendingUse::release() const {
  if (context_) context_->release(*this);
}
}  // namespace detail

Context::~Context() {
  active_query_ = nullptr;  // so that flush() leaves nothing referring to this context
  flush();
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& w : workers_) w.join();
}

void Context::refer(const detail::PendingUse& use) {
  if (use.context_ == this) return;
  if (use.context_) use.context_->release(use);
  use.context_ = this;
  pending_uses_.push_back(&use);
}

namespace {
void list(detail::CommandQueue& q, const ColorTarget& t) { q.color_targets().push_back(&t); }
void list(detail::CommandQueue& q, const DepthStencilTarget& t) { q.depth_targets().push_back(&t); }
}  // namespace

template <class Target>
void Context::refer_target(const Target& target, Access access) {
  refer(target.pending_);
  detail::FrameUse& use = target.use_;
  if (access == Access::whole_clear) {
    use.discarded = use.discard = false;  // new samples, to be kept unless discarded again
    if (!use.recorded) use.starts_cleared = true;
  } else {
    use.check_kept(access == Access::resolve ? "resolved" : "drawn into");
    if (use.discard && access != Access::resolve)
      throw std::logic_error("a render target was drawn into after discard() in the same frame (only a resolve may follow it)");
  }
  use.recorded = true;
  if (!use.listed) {
    use.listed = true;
    list(*queue_, target);
  }
}

template <class Target>
void Context::discard_target(const Target& target) {
  refer(target.pending_);
  detail::FrameUse& use = target.use_;
  use.discard = true;  // applies when the frame ends (flush)
  if (!use.listed) {
    use.listed = true;
    list(*queue_, target);
  }
}

void Context::refer(const ColorTarget& target, Access access) { refer_target(target, access); }
void Context::refer(const DepthStencilTarget& target, Access access) { refer_target(target, access); }
void Context::discard(const ColorTarget& target) { discard_target(target); }
void Context::discard(const DepthStencilTarget& target) { discard_target(target); }

void Context::release(const detail::PendingUse& use) {
  if (active_query_ && &active_query_->use_ == &use) active_query_ = nullptr;
  flush_frame(false);
  // A target whose discard() the frame carries on stays listed: not one that goes away (or to
  // another context, which lists it anew).
  auto drop = [&](auto& targets) {
    std::erase_if(targets, [&](const auto* t) {
      if (&t->pending_ != &use) return false;
      detail::FrameUseAccess::of(*t).listed = false;
      return true;
    });
  };
  drop(queue_->color_targets());
  drop(queue_->depth_targets());
  std::erase(pending_uses_, &use);
  use.context_ = nullptr;
}

void Context::begin_query(OcclusionQuery& query) {
  const auto& pending = queue_->queries();
  if (std::find(pending.begin(), pending.end(), &query) != pending.end()) flush_within_frame();
  refer(query.use_);
  query.samples_ = 0;
  active_query_ = &query;
}

void Context::end_query() { active_query_ = nullptr; }

uint64_t Context::query_result(const OcclusionQuery& query) {
  flush();
  return query.samples_;
}

void Context::reset_stats() { *stats_ = {}; }

void Context::flush() { flush_frame(true); }
void Context::flush_within_frame() { flush_frame(false); }

void Context::flush_frame(bool ends_frame) {
  run_frame(ends_frame);
  // Nothing pending refers to anything now; the active query stays referred to, and so do the
  // targets whose discard() the frame carries on (run_frame left them listed).
  for (const detail::PendingUse* use : pending_uses_) use->context_ = nullptr;
  pending_uses_.clear();
  if (active_query_) refer(active_query_->use_);
  for (const ColorTarget* t : queue_->color_targets()) refer(t->pending_);
  for (const DepthStencilTarget* t : queue_->depth_targets()) refer(t->pending_);
}

namespace {
/// Whether a frame keeps `target` in tile memory: it clears the target whole first and
/// discards it at its end.
bool in_tile_memory(const detail::FrameUse& use, bool tile_memory_ends_frame) {
  return tile_memory_ends_frame && use.starts_cleared && use.discard;
}

/// Allocates the own memory of the targets the frame's commands use there, before the threads
/// touch it.
template <class Target>
void allocate_outside_tile_memory(const std::vector<const Target*>& targets, bool tile_memory_ends_frame) {
  for (const Target* t : targets) {
    const detail::FrameUse& use = detail::FrameUseAccess::of(*t);
    if (use.recorded && !in_tile_memory(use, tile_memory_ends_frame)) t->allocate_memory();
  }
}

/// Places the frame's tile-memory targets one after another; returns a thread's bytes.
template <class Target>
size_t place_in_tile_memory(const std::vector<const Target*>& targets, bool tile_memory_ends_frame, size_t bytes,
                            uint64_t& count) {
  for (const Target* t : targets) {
    detail::FrameUse& use = detail::FrameUseAccess::of(*t);
    if (!in_tile_memory(use, tile_memory_ends_frame)) continue;
    use.tile_memory_offset = bytes;
    bytes += (t->tile_bytes() + 63) / 64 * 64;
    ++count;
  }
  return bytes;
}

/// What a frame leaves of its targets: those it discarded when it ends the frame; no tile memory.
/// A discard() that a frame the context flushed by itself carries on keeps its target listed
/// (returned in `carried`), to be applied when the frame ends.
template <class Target>
void end_frame_use(const std::vector<const Target*>& targets, bool ends_frame, std::vector<const Target*>& carried) {
  for (const Target* t : targets) {
    detail::FrameUse& use = detail::FrameUseAccess::of(*t);
    if (ends_frame && use.discard) use.discarded = true, use.discard = false;
    use.recorded = use.starts_cleared = false;
    use.tile_memory_offset = detail::kNoTileMemory;
    use.listed = use.discard;
    if (use.listed) carried.push_back(t);
  }
}
}  // namespace

void Context::end_frame(bool ends_frame) {
  detail::CommandQueue& q = *queue_;
  std::vector<const ColorTarget*> colors;
  std::vector<const DepthStencilTarget*> depths;
  end_frame_use(q.color_targets(), ends_frame, colors);
  end_frame_use(q.depth_targets(), ends_frame, depths);
  q.reset();
  q.color_targets() = std::move(colors);
  q.depth_targets() = std::move(depths);
}

void Context::run_frame(bool ends_frame) {
  detail::CommandQueue& q = *queue_;
  if (q.empty()) return end_frame(ends_frame);
  ++flush_count_;
  const bool tile_memory_ends_frame = ends_frame && options_.fast_paths.on(FastPath::TileMemory);
  allocate_outside_tile_memory(q.color_targets(), tile_memory_ends_frame);
  allocate_outside_tile_memory(q.depth_targets(), tile_memory_ends_frame);
  uint64_t in_tile_memory = 0;
  size_t tile_memory_bytes = place_in_tile_memory(q.color_targets(), tile_memory_ends_frame, 0, in_tile_memory);
  tile_memory_bytes = place_in_tile_memory(q.depth_targets(), tile_memory_ends_frame, tile_memory_bytes, in_tile_memory);
  std::vector<std::byte*> tile_memory(size_t(thread_count()), nullptr);
  if (tile_memory_bytes > 0)
    for (int t = 0; t < thread_count(); ++t) tile_memory[size_t(t)] = q.tile_memory(t, tile_memory_bytes);
  const int tiles = q.layout().tile_count();
  const std::span<detail::ThreadCounters> counters = q.thread_counters(thread_count());
  parallel_for(tiles, [&](int tile, int thread) {
    detail::tile_memory_base = tile_memory[size_t(thread)];
    for (const auto& command : q.commands()) command->execute(tile, counters[size_t(thread)]);
  });
  for (const detail::ThreadCounters& c : counters) {
    for (size_t slot = 0; slot < q.queries().size(); ++slot) q.queries()[slot]->samples_ += c.query_samples[slot];
    *stats_ += *c.stats;
  }
  *stats_ += q.front_end_stats();
  stats_->tile_memory_targets += in_tile_memory;
  end_frame(ends_frame);
}

void Context::run_items(int thread) {
  simd::ScopedFlushDenormals ftz;
  const int threads = thread_count();
  for (int item; (item = item_blocks_[size_t(thread)].take_front()) >= 0;) (*job_)(item, thread);
  for (int k = 1; k < threads; ++k) {
    ItemBlock& other = item_blocks_[size_t((thread + k) % threads)];
    for (int item; (item = other.take_back()) >= 0;) (*job_)(item, thread);
  }
}

namespace {
/// How long an idle thread spins before it blocks. The front end runs one parallel_for per draw,
/// and waking a blocked thread takes tens of microseconds: a sizable share of a small draw's
/// front end (bench/README.md).
constexpr auto kSpinTime = std::chrono::microseconds(50);

/// Spins until done() or kSpinTime has passed; true if done.
template <class Done>
bool spin_until(Done done) {
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    for (int i = 0; i < 64; ++i) {
      if (done()) return true;
      simd::spin_pause();
    }
    if (std::chrono::steady_clock::now() - start > kSpinTime) return false;
  }
}
}  // namespace

void Context::worker_main(int thread) {
  uint64_t seen = 0;
  for (;;) {
    spin_until([&] { return generation_.load(std::memory_order_acquire) != seen; });
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
    }
    run_items(thread);
    {
      std::lock_guard lock(mutex_);
      if (--busy_workers_ == 0) done_.notify_one();
    }
  }
}

void Context::parallel_for(int count, const std::function<void(int, int)>& fn) {
  if (count <= 0) return;
  if (workers_.empty() || count == 1) {
    simd::ScopedFlushDenormals ftz;
    for (int i = 0; i < count; ++i) fn(i, 0);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    job_ = &fn;
    const int threads = thread_count();
    for (int t = 0; t < threads; ++t)
      item_blocks_[size_t(t)].set(int(int64_t(count) * t / threads), int(int64_t(count) * (t + 1) / threads));
    busy_workers_ = static_cast<int>(workers_.size());
    ++generation_;
  }
  wake_.notify_all();
  run_items(0);
  spin_until([&] { return busy_workers_.load(std::memory_order_acquire) == 0; });
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return busy_workers_ == 0; });
  job_ = nullptr;
}

}  // namespace luxel::rasterizer
