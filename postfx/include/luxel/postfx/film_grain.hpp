#pragma once
// Film grain on the finished 8-bit frame: the SDK's filmgrain shader and blend
// (shading/source/film_grain.hpp, docs/fidelity.md#film-grain) over a grain texture that luxel makes.
//
// The SDK reads its grain from a texture file and the effect class that draws it is not in the
// SDK, so the texture is ours: a tile_size x tile_size RGBA8 tile of uniform noise, each texel's
// bytes the low bits of a counter-based hash (SplitMix64's finaliser) of (seed, frame index,
// texel index), never of a thread or of a sequence of earlier draws. The same seed and frame give
// the same tile on any machine and thread count; each frame of a sequence has its own tile, so
// the grain moves. Monochrome grain (the default) puts one byte in r, g and b; otherwise each
// channel has its own. The tile repeats across the frame one texel per pixel (point sampling,
// wrap addressing), texel (x mod tile, y mod tile) on pixel (x, y).
//
// The default noise scale, (0.1, 0.1, 0.1, 0.9), is our choice: it adds up to 0.1 and keeps
// 0.9 to 1 of the frame, a light grain that lifts the blacks a little as film does.

#include "luxel/postfx/shader_tally.hpp"
#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/rasterizer/texture.hpp"

#include <glm/vec4.hpp>

#include <cstdint>
#include <optional>

namespace luxel::postfx {

struct FilmGrainOptions {
  uint64_t seed = 0;
  glm::vec4 noise_scale{0.1f, 0.1f, 0.1f, 0.9f};  ///< the shader's c0 (see shading/source/film_grain.hpp)
  int tile_size = 256;                            ///< texels on a side of the grain tile
  bool monochrome = true;                         ///< one noise value in r, g and b
};

/// The grain tile of one frame (alpha 255). Throws std::invalid_argument for a tile size outside
/// 1..rasterizer::kMaxTextureSize.
rasterizer::Image grain_tile(const FilmGrainOptions& options, uint64_t frame_index);

class FilmGrain {
 public:
  explicit FilmGrain(FilmGrainOptions options = {}) : options_(options) {}

  /// Blends frame `frame_index`'s grain onto the frame (any sample count); the draw's shader goes
  /// to `tally`.
  void apply(rasterizer::Context& ctx, rasterizer::ColorTarget& frame, uint64_t frame_index, const ShaderTally& tally = {});
  /// The same on a resolved frame held as an image.
  void apply(rasterizer::Context& ctx, rasterizer::Image& frame, uint64_t frame_index, const ShaderTally& tally = {});

 private:
  FilmGrainOptions options_;
  std::optional<rasterizer::Texture> grain_;
  std::optional<rasterizer::ColorTarget> image_target_;  ///< apply(Image&)'s frame as a target
};

}  // namespace luxel::postfx
