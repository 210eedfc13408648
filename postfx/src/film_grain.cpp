// Film grain (film_grain.hpp): the grain tile and its blended draw.

#include "luxel/postfx/film_grain.hpp"

#include "counted_draw.hpp"
#include "screen_rectangle.hpp"

#include "luxel/shading/source/film_grain.hpp"

#include <atomic>
#include <span>
#include <stdexcept>
#include <string>

namespace luxel::postfx {

namespace {

/// SplitMix64's finaliser: a bijective mix of 64 bits (Steele, Lea, Flood 2014).
uint64_t mix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace

rasterizer::Image grain_tile(const FilmGrainOptions& options, uint64_t frame_index) {
  const int n = options.tile_size;
  if (n < 1 || n > rasterizer::kMaxTextureSize) {
    throw std::invalid_argument("film grain: tile size " + std::to_string(n) + " is outside 1.." +
                                std::to_string(rasterizer::kMaxTextureSize));
  }
  const uint64_t frame_key = mix64(mix64(options.seed) ^ frame_index);
  rasterizer::Image tile(n, n);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const uint64_t bits = mix64(frame_key ^ (static_cast<uint64_t>(y) * n + x));
      uint8_t* p = tile.pixel(x, y);
      p[0] = static_cast<uint8_t>(bits);
      p[1] = options.monochrome ? p[0] : static_cast<uint8_t>(bits >> 8);
      p[2] = options.monochrome ? p[0] : static_cast<uint8_t>(bits >> 16);
      p[3] = 255;
    }
  }
  return tile;
}

void FilmGrain::apply(rasterizer::Context& ctx, rasterizer::ColorTarget& frame, uint64_t frame_index, const ShaderTally& tally) {
  const rasterizer::Image tile = grain_tile(options_, frame_index);
  if (!grain_ || grain_->width() != tile.width) {
    grain_ = rasterizer::Texture::create_2d(tile.width, tile.height, rasterizer::TextureFormat::RGBA8, 1);
  }
  grain_->upload(0, std::span<const uint8_t>(tile.rgba));

  shading::source::FilmGrainParams params;
  params.noise_scale = options_.noise_scale;
  params.grain.texture = &*grain_;
  params.grain.state.min = params.grain.state.mag = rasterizer::Filter::Point;
  params.grain.state.mip = rasterizer::MipFilter::None;  // wrap addressing: the sampler's default
  // The tile's texels 0..W-1 x 0..H-1 (wrapping) on the frame's pixels, one to one.
  const TexelRect rect{0.0f, 0.0f, static_cast<float>(frame.width() - 1), static_cast<float>(frame.height() - 1),
                       tile.width, tile.height};
  namespace src = shading::source;
  counted_draw<src::FilmGrainPixelShader>(tally, src::kSingleCombo, src::measure_film_grain, [&](std::atomic<uint64_t>* pixels) {
    draw_screen_rectangle(ctx, frame, src::film_grain_pipeline_state(), screen_rectangle(frame.width(), frame.height(), rect),
                          src::FilmGrainPixelShader{&params, pixels});
    ctx.flush();  // the draw reads `params` and `pixels`, which end here
  });
}

void FilmGrain::apply(rasterizer::Context& ctx, rasterizer::Image& frame, uint64_t frame_index, const ShaderTally& tally) {
  if (!image_target_ || image_target_->width() != frame.width || image_target_->height() != frame.height) {
    image_target_.emplace(frame.width, frame.height);
  }
  rasterizer::load_image(ctx, frame, *image_target_);
  apply(ctx, *image_target_, frame_index, tally);
  rasterizer::resolve_into(ctx, *image_target_, frame);
}

}  // namespace luxel::postfx
