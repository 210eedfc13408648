// The parts of a draw that do not depend on the shaders: validating the framebuffer and turning
// pipeline state into per-draw constants.

#include "luxel/rasterizer/draw.hpp"

#include "luxel/rasterizer/detail/draw_plan.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace luxel::rasterizer {

DrawStats& DrawStats::operator+=(const DrawStats& o) {
  triangles += o.triangles;
  bad_index += o.bad_index;
  non_finite += o.non_finite;
  outside += o.outside;
  clipped += o.clipped;
  clip_overflow += o.clip_overflow;
  culled += o.culled;
  degenerate += o.degenerate;
  rasterized += o.rasterized;
  small_walks += o.small_walks;
  constant_depth += o.constant_depth;
  tile_memory_targets += o.tile_memory_targets;
  blocks_full += o.blocks_full;
  stamps_full += o.stamps_full;
  stamps_partial += o.stamps_partial;
  stamps_wide_edges += o.stamps_wide_edges;
  stamps_shaded += o.stamps_shaded;
  return *this;
}

namespace detail {

DrawPlan plan_draw(const Framebuffer& fb, const PipelineState& state, int varyings, FastPaths fast_paths) {
  DrawPlan plan;
  plan.state = &state;
  plan.color = fb.color;
  plan.depth_stencil = fb.depth_stencil;
  if (fb.color) plan.layout = fb.color->layout();
  if (fb.depth_stencil) {
    if (fb.color && !(fb.depth_stencil->layout() == fb.color->layout()))
      throw std::invalid_argument("draw: color and depth-stencil targets differ in size or sample count");
    plan.layout = fb.depth_stencil->layout();
  }
  if (!fb.color && !fb.depth_stencil) throw std::invalid_argument("draw: the framebuffer has no target");
  plan.float_color = fb.color && fb.color->format() == ColorFormat::rgba32f;
  if (plan.float_color && state.blend.enable)
    throw std::invalid_argument("draw: blending into an rgba32f color target is not supported");
  if (plan.float_color && state.blend.srgb_write)
    throw std::invalid_argument("draw: an rgba32f color target holds linear values: no sRGB write");

  DrawConstants& dc = plan.constants;
  const Viewport& vp = state.viewport;
  // Only an exact 0 stands for the target's size (state.hpp): a negative or NaN size is a bug in
  // the caller, not a request for the whole target.
  if (!(vp.width >= 0 && vp.width <= kMaxTargetSize) || !(vp.height >= 0 && vp.height <= kMaxTargetSize))
    throw std::invalid_argument("draw: viewport width and height must be 0 (the target's) or in (0, " +
                                std::to_string(kMaxTargetSize) + "]");
  const float vp_w = vp.width > 0 ? vp.width : static_cast<float>(plan.layout.width);
  const float vp_h = vp.height > 0 ? vp.height : static_cast<float>(plan.layout.height);
  if (!std::isfinite(vp.x) || !std::isfinite(vp.y) || std::abs(vp.x) > kMaxTargetSize ||
      std::abs(vp.y) > kMaxTargetSize)
    throw std::invalid_argument("draw: viewport out of range");
  if (!(vp.min_depth >= 0 && vp.max_depth <= 1 && vp.min_depth <= vp.max_depth))
    throw std::invalid_argument("draw: viewport depth range must satisfy 0 <= min_depth <= max_depth <= 1");
  dc.vp_x = vp.x;
  dc.vp_y = vp.y;
  dc.half_w = vp_w * 0.5f;
  dc.half_h = vp_h * 0.5f;
  dc.min_depth = vp.min_depth;
  dc.max_depth = vp.max_depth;
  // Guard band in NDC, one pixel inside kGuardBand (what rounding in clipping can still do:
  // setup_and_bin).
  const float g = static_cast<float>(kGuardBand - 1);
  dc.guard_min_x = (-g - dc.vp_x) / dc.half_w - 1.0f;
  dc.guard_max_x = (g - dc.vp_x) / dc.half_w - 1.0f;
  dc.guard_max_y = 1.0f - (-g - dc.vp_y) / dc.half_h;
  dc.guard_min_y = 1.0f - (g - dc.vp_y) / dc.half_h;
  // Writable pixels: target, the pixels the viewport rectangle overlaps, and scissor. (D3D9 and
  // D3D10 viewports are whole pixels; a fractional origin only shifts the mapping, see state.hpp.)
  dc.clip_x0 = std::max(0, static_cast<int>(std::floor(vp.x)));
  dc.clip_y0 = std::max(0, static_cast<int>(std::floor(vp.y)));
  dc.clip_x1 = std::min(plan.layout.width, static_cast<int>(std::ceil(vp.x + vp_w)));
  dc.clip_y1 = std::min(plan.layout.height, static_cast<int>(std::ceil(vp.y + vp_h)));
  if (state.scissor.enable) {
    dc.clip_x0 = std::max(dc.clip_x0, state.scissor.x0);
    dc.clip_y0 = std::max(dc.clip_y0, state.scissor.y0);
    dc.clip_x1 = std::min(dc.clip_x1, state.scissor.x1);
    dc.clip_y1 = std::min(dc.clip_y1, state.scissor.y1);
  }
  dc.reject_min_x = (static_cast<float>(dc.clip_x0) - dc.vp_x) / dc.half_w - 1.0f;
  dc.reject_max_x = (static_cast<float>(dc.clip_x1) - dc.vp_x) / dc.half_w - 1.0f;
  dc.reject_max_y = 1.0f - (static_cast<float>(dc.clip_y0) - dc.vp_y) / dc.half_h;
  dc.reject_min_y = 1.0f - (static_cast<float>(dc.clip_y1) - dc.vp_y) / dc.half_h;
  dc.tiles_x = plan.layout.tiles_x;
  dc.tiles_y = plan.layout.tiles_y;
  dc.samples = plan.layout.samples;
  dc.varyings = varyings;
  dc.rasterizer = state.rasterizer;
  dc.fast_paths = fast_paths;
  const SampleOffset* offsets = standard_sample_offsets(plan.layout.samples);
  for (int s = 0; s < plan.layout.samples; ++s) plan.sample_offsets[s] = offsets[s];

  const DepthStencilState& ds = state.depth_stencil;
  const bool has_ds = fb.depth_stencil != nullptr;
  plan.depth_test = has_ds && ds.depth_enable;
  plan.depth_write = plan.depth_test && ds.depth_write;
  plan.stencil = has_ds && ds.stencil_enable;
  plan.alpha_test = state.alpha_test.enable;
  const uint8_t m = state.blend.write_mask;
  plan.color_write_mask = (m & kWriteRed ? 0xffu : 0u) | (m & kWriteGreen ? 0xff00u : 0u) |
                          (m & kWriteBlue ? 0xff0000u : 0u) | (m & kWriteAlpha ? 0xff000000u : 0u);
  return plan;
}

}  // namespace detail
}  // namespace luxel::rasterizer
