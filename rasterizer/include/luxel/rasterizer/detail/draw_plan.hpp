#pragma once
// The plan of a draw: what the tile rasterizer (detail/tile_rasterizer.hpp) reads about it,
// decided once per draw from the framebuffer and the pipeline state. Apart from the tile
// rasterizer because it does not depend on the pixel functor: plan_draw (rasterizer/src/draw.cpp)
// compiles without the draw's templates.

#include "luxel/rasterizer/detail/triangle_setup.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/limits.hpp"
#include "luxel/rasterizer/msaa.hpp"
#include "luxel/rasterizer/state.hpp"

#include <cstdint>

namespace luxel::rasterizer::detail {

/// Everything about a draw the tile rasterizer needs, decided once per draw.
struct DrawPlan {
  DrawConstants constants;
  const PipelineState* state = nullptr;
  ColorTarget* color = nullptr;
  DepthStencilTarget* depth_stencil = nullptr;
  SurfaceLayout layout;
  SampleOffset sample_offsets[kMaxSamples];
  bool depth_test = false, depth_write = false, stencil = false, alpha_test = false;
  bool float_color = false;       ///< the color target is rgba32f (one sample, no blending)
  uint32_t color_write_mask = 0;  ///< RGBA8 bits to write (of an rgba32f target: its channels')
};

DrawPlan plan_draw(const Framebuffer& fb, const PipelineState& state, int varyings, FastPaths fast_paths);

}  // namespace luxel::rasterizer::detail
