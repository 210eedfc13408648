#pragma once
// Color correction of a finished 8-bit frame (docs/fidelity.md#color-correction), two ways:
//  - color_correct(): the engine's way. The frame becomes an RGBA8 texture, each LUT a 32^3 RGBA8
//    volume (lut.hpp), and one full-screen draw of colorcorrection_ps2x
//    (shading/source/color_correction.hpp) through the rasterizer writes the result with sRGB
//    write off: 8 bits in, 8 bits out, trilinear between the lattice's 32 points per axis. Its
//    bytes do not depend on the context's thread count (rasterizer/draw.hpp).
//  - color_correct_exact(): the same blend in float, each transform applied at its own precision
//    (a LUT file at its own resolution and interpolation through OpenColorIO, a grade exactly),
//    so that the error of the engine's way can be measured.
//
// How far apart the two are depends on the LUT: the engine resamples it on 32 points per axis,
// clamps and rounds the entries to 8 bits, and interpolates again. Measured over every 8-bit color
// (tests/postfx/color_correction_test.cpp checks every third level): a smooth 17^3 LUT within 4
// steps, the built-in presets within 2; real looks with steep or out-of-range regions much further
// in those regions (a 16^3 teal-and-orange look with negative entries up to 19 steps, more than 2
// in 1.2% of the channels), which `luxel grade --exact` shows.
//
// Weights. The engine blends out = frame * defaultWeight + sum_k LUT_k(frame) * w_k with up to
// four lookups; how it derives defaultWeight from the entities' weights is closed (NOT IN SDK).
// luxel's choice, the obvious reading: defaultWeight = 1 - sum_k w_k,
// clamped at 0, so weights summing to 1 or more leave none of the ungraded frame (and above 1
// brighten it, as the shader's sum would).

#include "luxel/postfx/bloom.hpp"
#include "luxel/postfx/color_transform.hpp"
#include "luxel/postfx/lut.hpp"
#include "luxel/postfx/shader_tally.hpp"
#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/image.hpp"

#include <span>
#include <vector>

namespace luxel::postfx {

/// Most lookups one pass blends.
inline constexpr int kMaxLuts = shading::source::kMaxColorCorrectionLuts;

struct WeightedLut {
  const Lut* lut = nullptr;
  float weight = 0.0f;  ///< finite, >= 0
  /// lut_volume(*lut), when the caller keeps it from pass to pass (a sequence's frames blend the
  /// same LUTs); the pass makes it otherwise.
  const rasterizer::Texture* volume = nullptr;
};

struct WeightedTransform {
  const ColorTransform* transform = nullptr;
  float weight = 0.0f;  ///< finite, >= 0
};

/// The frame's own weight beside lookups of these weights: max(0, 1 - sum).
float default_weight(std::span<const float> weights);

/// The engine's pass over `frame` (RGBA8, alpha kept); the draw's shader goes to `tally`. Throws
/// std::invalid_argument for no LUT or more than kMaxLuts, a missing LUT, or a weight that is
/// negative or not finite.
rasterizer::Image color_correct(rasterizer::Context& ctx, const rasterizer::Image& frame,
                                std::span<const WeightedLut> luts, const ShaderTally& tally = {});
/// The same reading the frame's copy (full_frame.hpp: an RGBA8 2D texture of one level).
rasterizer::Image color_correct(rasterizer::Context& ctx, const rasterizer::Texture& frame,
                                std::span<const WeightedLut> luts, const ShaderTally& tally = {});

/// The engine's pass when the frame also has a bloom (docs/fidelity.md#bloom; Engine_Post,
/// shading/source/engine_post.hpp): `bloom` has blurred the frame (Bloom::blur), and one draw adds
/// the bloom to the frame and color-corrects the sum, unrounded in between. Returns the finished
/// frame; the draw's shader goes to `tally`. Same argument checks as above; std::logic_error when
/// `bloom` has blurred no frame.
rasterizer::Image color_correct(rasterizer::Context& ctx, const Bloom& bloom, std::span<const WeightedLut> luts,
                                const ShaderTally& tally = {});

/// The two passes above (the frame's copy, or it with its bloom) into `out`, whose pixels they
/// replace: an image of the frame's size keeps its memory (a sequence's frames), where a new one
/// is allocated and zeroed first.
void color_correct_into(rasterizer::Context& ctx, const rasterizer::Texture& frame, std::span<const WeightedLut> luts,
                        rasterizer::Image& out, const ShaderTally& tally = {});
void color_correct_into(rasterizer::Context& ctx, const Bloom& bloom, std::span<const WeightedLut> luts,
                        rasterizer::Image& out, const ShaderTally& tally = {});

/// The same blend in float: width * height * 4 floats, RGBA, rows top first, alpha the frame's
/// (over 255). Same argument checks as color_correct.
std::vector<float> color_correct_exact(const rasterizer::Image& frame, std::span<const WeightedTransform> transforms);

}  // namespace luxel::postfx
