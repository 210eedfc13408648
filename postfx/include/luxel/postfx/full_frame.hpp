#pragma once
// _rt_FullFrameFB: the finished frame copied once into a texture (UpdateScreenEffectTexture;
// docs/fidelity.md#auto-exposure, #bloom), which every post pass of the frame then reads:
// the luminance histogram with sRGB read on (its luminance is linear), bloom's downsample
// and Engine_Post with it off (gamma values). D3D9 made sRGB decode a sampler state
// (rasterizer::Sampler::srgb_read, D3DSAMP_SRGBTEXTURE), so one RGBA8 copy serves them all.

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/rasterizer/texture.hpp"

#include <optional>

namespace luxel::postfx {

class FullFrameTexture {
 public:
  /// Copies `frame` (the finished 8-bit image, sRGB-encoded) in: once per frame, before the
  /// passes that read it. Throws std::invalid_argument when its pixels do not match its size.
  void update(const rasterizer::Image& frame);
  /// Resolves `frame` (the finished frame's target) straight into the copy
  /// (rasterizer::resolve_into): no image in between. Flushes the context.
  void resolve(rasterizer::Context& ctx, const rasterizer::ColorTarget& frame, rasterizer::ResolveAlpha alpha);
  /// The copy: one RGBA8 level the frame's size. Throws std::logic_error before any update.
  const rasterizer::Texture& texture() const;

 private:
  std::optional<rasterizer::Texture> texture_;
};

/// Throws std::invalid_argument, naming `pass`, unless `frame` can be a frame's copy: an RGBA8 2D
/// texture of one level.
void check_frame_copy(const rasterizer::Texture& frame, const char* pass);

/// Level 0 of a 2D RGBA8 texture into `image` (resized to fit): a copy read back.
void read_into(const rasterizer::Texture& texture, rasterizer::Image& image);

}  // namespace luxel::postfx
