#pragma once
// Bloom on the tone-mapped 8-bit frame, as Source's INTEGER/LDR path draws it
// (docs/fidelity.md#bloom, Generate8BitBloomTexture in viewpostprocess.cpp):
//
//   1. copy      the frame -> _rt_FullFrameFB (resolved when multisampled), read as gamma values,
//                or the caller's copy of the frame (full_frame.hpp) read as it is;
//   2. downsample _rt_FullFrameFB -> _rt_SmallFB0, a quarter of the frame each way, with the
//                shaped 4-tap box (shading/source/bloom_downsample.hpp);
//   3. blur x    _rt_SmallFB0 -> _rt_SmallFB1, 13 taps (shading/source/bloom_blur.hpp);
//   4. blur y    _rt_SmallFB1 -> _rt_SmallFB0, 13 taps times the bloom amount (bloom_amount.hpp),
//                with the SDK's 1/width vertical step unless BloomOptions says otherwise;
//   5. add       _rt_SmallFB0 stretched over the frame, added with ONE/ONE on gamma values
//                (shading/source/bloom_add.hpp).
// Every pass is a screen rectangle drawn through the rasterizer (postfx/src/screen_rectangle.hpp)
// into an 8-bit target, and each intermediate is read back as an RGBA8 texture, bilinear and
// clamped, so every pass rounds to 8 bits as the SDK's render targets do. Output bytes do not
// depend on the context's thread count.
//
// Rectangles (DrawScreenSpaceRectangle's centre-to-centre mapping): the downsample shows source
// texels 0..W-2 x 0..H-2 on the W/4 x H/4 target (the "-2" leaves room for the taps reaching past
// the base texel); the blurs show the small target on itself; the add shows the small
// target's texels from (0, -0.5) to (w-1, h-1) on the whole frame (viewpostprocess.cpp's
// fullViewportPostSrcCorners, which bloomadd and Engine_Post share: the half texel up is Valve's,
// and unexplained there).
//
// Frame sizes: the SDK asserts that the small targets are exactly a quarter of the frame. Here a
// frame of any size from 4x4 up is accepted: the small targets are floor(W/4) x floor(H/4) and the
// same formulas place the rectangles. The downsample's 4x4 footprints then sit
// (W-2) / (floor(W/4)-1) source texels apart, as at every size (a little over 4: 4.006 at 1280),
// still from the first texel to the last; a small target one texel wide (W of 4 to 7) reads the
// first footprint only. Smaller frames throw std::invalid_argument.

#include "luxel/postfx/full_frame.hpp"
#include "luxel/postfx/shader_tally.hpp"
#include "luxel/postfx/texel_rect.hpp"
#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/rasterizer/texture.hpp"
#include "luxel/shading/source/bloom_blur.hpp"

#include <functional>
#include <optional>

namespace luxel::postfx {

struct BloomOptions {
  /// $bloomtintenable: shape the downsample's taps with the tint (0.3, 0.59, 0.11) and exponent
  /// 2.2; off: weights 0.333, exponent 1.
  bool tint = true;
  /// The vertical blur's texel step: the SDK's 1/width (the default) or 1/height.
  shading::source::BlurStep vertical_step = shading::source::BlurStep::sdk_width_quirk;
};

/// The size of the bloom's small targets for a frame: floor(W/4) x floor(H/4).
struct BloomSize {
  int width = 0, height = 0;
};
BloomSize bloom_size(int frame_width, int frame_height);

class Bloom {
 public:
  explicit Bloom(BloomOptions options = {}) : options_(options) {}

  /// All five passes: adds the bloom of `frame` (any sample count) onto it. `amount` is this
  /// frame's bloom amount (BloomAmount::advance); at 0 or below nothing runs, as in the SDK
  /// (bPerformBloom needs a bloom scale above 0). The draws' shaders go to `tally`.
  void apply(rasterizer::Context& ctx, rasterizer::ColorTarget& frame, float amount, const ShaderTally& tally = {});
  /// The same on a resolved frame held as an image.
  void apply(rasterizer::Context& ctx, rasterizer::Image& frame, float amount, const ShaderTally& tally = {});
  /// Every pass but the add, for the combine that adds the bloom itself when color correction
  /// runs (color_correction.hpp), or for add(Image&): afterwards frame_texture() and
  /// bloom_texture() hold what they read. Returns false, having run nothing, when `amount` is 0
  /// or below.
  bool blur(rasterizer::Context& ctx, const rasterizer::Image& frame, float amount, const ShaderTally& tally = {});
  /// The same reading `frame`, the frame's copy that the caller keeps for every post pass
  /// (full_frame.hpp), instead of a copy of its own; it must live as long as this Bloom reads it.
  bool blur(rasterizer::Context& ctx, const rasterizer::Texture& frame, float amount, const ShaderTally& tally = {});

  // The passes one by one, in this order (benchmarks time them; tests look between them). A pass
  // before any copy throws std::logic_error.
  void copy(rasterizer::Context& ctx, const rasterizer::ColorTarget& frame);
  void copy(const rasterizer::Image& frame);
  /// Instead of a copy: the passes read `frame` (see blur).
  void read_frame(const rasterizer::Texture& frame);
  void downsample(rasterizer::Context& ctx, const ShaderTally& tally = {});
  void blur_x(rasterizer::Context& ctx, const ShaderTally& tally = {});
  void blur_y(rasterizer::Context& ctx, float amount, const ShaderTally& tally = {});
  void add(rasterizer::Context& ctx, rasterizer::ColorTarget& frame, const ShaderTally& tally = {});
  /// The add onto a resolved frame held as an image.
  void add(rasterizer::Context& ctx, rasterizer::Image& frame, const ShaderTally& tally = {});

  /// The small target as the last pass left it (after blur_y: the bloom texture that add reads);
  /// empty before any.
  rasterizer::Image small_image() const;
  /// After a copy: the frame as the passes read it (_rt_FullFrameFB).
  const rasterizer::Texture& frame_texture() const;
  /// After blur_y: the bloom (_rt_SmallFB0) and the texels of it that the add stretches over the
  /// frame (from (0, -0.5) to the last texel, see above).
  const rasterizer::Texture& bloom_texture() const;
  TexelRect bloom_rectangle() const;

 private:
  /// Makes the small targets and textures fit a frame of this size.
  void fit(int frame_width, int frame_height);
  /// The passes between the copy and the add.
  void blur_passes(rasterizer::Context& ctx, float amount, const ShaderTally& tally);
  /// Throws std::logic_error naming `pass` when no frame has been copied yet.
  void require_copy(const char* pass) const;
  /// One pass on the small target: `draw` records its draw, and the result is resolved into
  /// small texture `index`, a render target that the next pass samples, as the SDK's targets are
  /// also textures.
  void small_pass(rasterizer::Context& ctx, int index, const std::function<void()>& draw);
  /// A blur with `params` drawn on the small target and kept in small texture `into`.
  void draw_blur(rasterizer::Context& ctx, const shading::source::BlurParams& params, int into, const ShaderTally& tally);

  BloomOptions options_;
  FullFrameTexture copy_;                          ///< _rt_FullFrameFB, when copied here
  const rasterizer::Texture* frame_ = nullptr;     ///< what the passes read: copy_ or the caller's
  std::optional<rasterizer::Texture> small_texture_[2];  ///< _rt_SmallFB0, _rt_SmallFB1
  std::optional<rasterizer::ColorTarget> small_target_;  ///< where each small pass draws
  std::optional<rasterizer::ColorTarget> image_target_;  ///< apply(Image&)'s frame as a target
  int last_small_ = 0;  ///< the small texture the last pass wrote
};

}  // namespace luxel::postfx
