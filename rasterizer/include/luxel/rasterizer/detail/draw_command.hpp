#pragma once
// The recorded stage of a draw: the command it pushes onto the context's queue (its binned
// triangles and copies of its state and pixel functor), which runs at the next flush, tile by
// tile, through the tile rasterizer of the draw's depth path and sample count. A header because
// it is templated on the pixel functor; that of a called functor (detail/called_shader.hpp) the
// library compiles once per varying count (rasterizer/src/called_draw.cpp.in).

#include "luxel/rasterizer/detail/called_shader.hpp"
#include "luxel/rasterizer/detail/command_queue.hpp"
#include "luxel/rasterizer/detail/tile_rasterizer.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/rasterizer/state.hpp"

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace luxel::rasterizer::detail {

/// A recorded draw: its binned triangles and a copy of everything its pixels need.
template <class PS, int N>
class DrawCommand final : public Command {
 public:
  DrawCommand(const DrawPlan& plan, const PipelineState& state, const PS& ps, std::vector<ChunkBins*> chunks,
              int query_slot)
      : plan_(plan), state_(state), ps_(ps), chunks_(std::move(chunks)), query_slot_(query_slot) {
    plan_.state = &state_;
    const CompareFunc depth_func = state_.depth_stencil.depth_func;
    const bool depth_only = kTrivialPixelFunctor<PS> && plan_.depth_stencil && plan_.depth_test && !plan_.stencil &&
                            plan_.constants.fast_paths.on(FastPath::FixedDepthPaths);
    depth_path_ = can_discard(ps_) || writes_depth(ps_) || plan_.alpha_test          ? DepthPath::Late
                   : depth_only && depth_func == CompareFunc::Less      ? DepthPath::EarlyLess
                   : depth_only && depth_func == CompareFunc::LessEqual ? DepthPath::EarlyLessEqual
                                                                        : DepthPath::Early;
    tile_active_.assign(plan_.layout.tile_count(), 0);
    for (const ChunkBins* c : chunks_)
      for (uint32_t t : c->touched_tiles) tile_active_[t] = 1;
  }

  void execute(int tile, ThreadCounters& counters) override {
    if (!tile_active_[tile]) return;
    switch (plan_.layout.samples) {
      case 1: return execute_with<1>(tile, counters);
      case 2: return execute_with<2>(tile, counters);
      case 4: return execute_with<4>(tile, counters);
      default: return execute_with<8>(tile, counters);
    }
  }

 private:
  template <int S>
  void execute_with(int tile, ThreadCounters& counters) {
    const bool count = query_slot_ >= 0;
    if constexpr ((PS::kCanDiscard || PS::kWritesDepth) && !kCalledPixelShader<PS>) {  // only the late path
      run(TileRasterizer<PS, N, DepthPath::Late, S>(plan_, ps_, tile, count), tile, counters);
    } else if constexpr (!kTrivialPixelFunctor<PS>) {  // no fixed paths (DepthPath)
      if (depth_path_ == DepthPath::Late)
        return run(TileRasterizer<PS, N, DepthPath::Late, S>(plan_, ps_, tile, count), tile, counters);
      return run(TileRasterizer<PS, N, DepthPath::Early, S>(plan_, ps_, tile, count), tile, counters);
    } else {
      switch (depth_path_) {
        case DepthPath::Late:
          return run(TileRasterizer<PS, N, DepthPath::Late, S>(plan_, ps_, tile, count), tile, counters);
        case DepthPath::Early:
          return run(TileRasterizer<PS, N, DepthPath::Early, S>(plan_, ps_, tile, count), tile, counters);
        case DepthPath::EarlyLess:
          return run(TileRasterizer<PS, N, DepthPath::EarlyLess, S>(plan_, ps_, tile, count), tile, counters);
        case DepthPath::EarlyLessEqual:
          return run(TileRasterizer<PS, N, DepthPath::EarlyLessEqual, S>(plan_, ps_, tile, count), tile, counters);
      }
    }
  }

  template <class Rasterizer>
  void run(Rasterizer rasterizer, int tile, ThreadCounters& counters) {
    for (const ChunkBins* bins : chunks_) {
      const RecordStream& records = bins->tile_records[tile];
      const auto* end = reinterpret_cast<const TriangleSetup*>(records.data() + records.size());
      for (auto* t = reinterpret_cast<const TriangleSetup*>(records.data()); t != end; t = t->next())
        rasterizer.triangle(*t);
    }
    if (query_slot_ >= 0) counters.query_samples[query_slot_] += rasterizer.samples_passed;
    *counters.stats += rasterizer.stats;
  }

  DrawPlan plan_;
  PipelineState state_;
  PS ps_;
  std::vector<ChunkBins*> chunks_;
  std::vector<uint8_t> tile_active_;
  int query_slot_;
  DepthPath depth_path_;
};

/// What a draw records of its pixel functor: a kTrivial one as it is, inlined into its own tile
/// rasterizers, any other behind a pointer (called_shader.hpp).
template <int N, class PS>
auto recorded_pixel_shader(const PS& ps) {
  if constexpr (kTrivialPixelFunctor<PS>) return ps;
  else return CalledPixelShader<N>::of(ps);
}

template <int N, class PS>
std::unique_ptr<Command> make_draw_command(const DrawPlan& plan, const PipelineState& state, const PS& ps,
                                           std::vector<ChunkBins*> chunks, int query_slot) {
  if constexpr (kCalledPixelShader<PS> && precompiled_varying_count(N))
    return make_called_draw_command<N>(plan, state, ps, std::move(chunks), query_slot);
  else return std::make_unique<DrawCommand<PS, N>>(plan, state, ps, std::move(chunks), query_slot);
}

}  // namespace luxel::rasterizer::detail
