// Bloom's passes (bloom.hpp): targets, textures and the five draws.

#include "luxel/postfx/bloom.hpp"

#include "counted_draw.hpp"
#include "screen_rectangle.hpp"

#include "luxel/shading/source/bloom_add.hpp"
#include "luxel/shading/source/bloom_downsample.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

namespace luxel::postfx {

namespace src = shading::source;

namespace {

/// How every bloom pass reads its source: bilinear, clamped, level 0 only.
rasterizer::Sampler bilinear_clamped() {
  rasterizer::Sampler s;
  s.min = s.mag = rasterizer::Filter::Linear;
  s.mip = rasterizer::MipFilter::None;
  s.u = s.v = rasterizer::Address::Clamp;
  return s;
}

/// An RGBA8 texture of one level, read as stored (no sRGB decode: gamma values).
rasterizer::Texture gamma_texture(int width, int height) {
  return rasterizer::Texture::create_2d(width, height, rasterizer::TextureFormat::RGBA8, 1);
}

}  // namespace

BloomSize bloom_size(int frame_width, int frame_height) {
  if (frame_width < 4 || frame_height < 4) {
    throw std::invalid_argument("bloom: a " + std::to_string(frame_width) + "x" + std::to_string(frame_height) +
                                " frame is smaller than 4x4");
  }
  return {frame_width / 4, frame_height / 4};
}

void Bloom::fit(int frame_width, int frame_height) {
  const BloomSize small = bloom_size(frame_width, frame_height);
  if (!small_target_ || small_target_->width() != small.width || small_target_->height() != small.height) {
    small_target_.emplace(small.width, small.height);
    for (auto& t : small_texture_) t = gamma_texture(small.width, small.height);
  }
}

void Bloom::require_copy(const char* pass) const {
  if (!frame_) throw std::logic_error(std::string("bloom: ") + pass + " before any copy of a frame");
}

void Bloom::small_pass(rasterizer::Context& ctx, int index, const std::function<void()>& draw) {
  // Invalidated (each draw writes every pixel) and discarded once resolved: the small target
  // lives in tile memory only, and is never filled (rasterizer/framebuffer.hpp).
  rasterizer::invalidate(ctx, *small_target_);
  draw();
  rasterizer::discard(ctx, *small_target_);
  rasterizer::resolve_into(ctx, *small_target_, *small_texture_[index]);
  last_small_ = index;
}

rasterizer::Image Bloom::small_image() const {
  rasterizer::Image image;
  if (small_texture_[last_small_]) read_into(*small_texture_[last_small_], image);
  return image;
}

void Bloom::copy(rasterizer::Context& ctx, const rasterizer::ColorTarget& frame) {
  fit(frame.width(), frame.height());
  copy_.resolve(ctx, frame, rasterizer::ResolveAlpha::samples);
  frame_ = &copy_.texture();
}

void Bloom::copy(const rasterizer::Image& frame) {
  fit(frame.width, frame.height);
  copy_.update(frame);
  frame_ = &copy_.texture();
}

void Bloom::read_frame(const rasterizer::Texture& frame) {
  check_frame_copy(frame, "bloom");
  fit(frame.width(), frame.height());
  frame_ = &frame;
}

void Bloom::downsample(rasterizer::Context& ctx, const ShaderTally& tally) {
  require_copy("downsample");
  const int W = frame_->width(), H = frame_->height();
  src::DownsampleParams params;
  params.frame = {0, frame_, bilinear_clamped()};
  params.tint = src::downsample_constant(options_.tint);
  std::array<glm::vec2, 4> taps;
  std::copy(std::begin(src::kDownsampleTapOffsets), std::end(src::kDownsampleTapOffsets), taps.begin());
  const TexelRect rect{0.0f, 0.0f, static_cast<float>(W - 2), static_cast<float>(H - 2), W, H};
  counted_draw<src::DownsamplePixelShader>(tally, src::kSingleCombo, src::measure_downsample, [&](std::atomic<uint64_t>* pixels) {
    small_pass(ctx, 0, [&] {
      draw_screen_rectangle(ctx, *small_target_, post_pass_state(),
                            screen_rectangle<4>(small_target_->width(), small_target_->height(), rect, taps),
                            src::DownsamplePixelShader{&params, pixels});
    });
  });
}

void Bloom::blur_x(rasterizer::Context& ctx, const ShaderTally& tally) {
  require_copy("blur_x");
  const int w = small_target_->width(), h = small_target_->height();
  src::BlurParams params = src::blur_constants(src::BlurAxis::horizontal, w, h, options_.vertical_step, 1.0f);
  params.source = {0, &*small_texture_[0], bilinear_clamped()};
  draw_blur(ctx, params, 1, tally);
}

void Bloom::blur_y(rasterizer::Context& ctx, float amount, const ShaderTally& tally) {
  require_copy("blur_y");
  const int w = small_target_->width(), h = small_target_->height();
  src::BlurParams params = src::blur_constants(src::BlurAxis::vertical, w, h, options_.vertical_step, amount);
  params.source = {0, &*small_texture_[1], bilinear_clamped()};
  draw_blur(ctx, params, 0, tally);
}

void Bloom::draw_blur(rasterizer::Context& ctx, const src::BlurParams& params, int into, const ShaderTally& tally) {
  const int w = small_target_->width(), h = small_target_->height();
  counted_draw<src::BlurPixelShader>(tally, src::kSingleCombo, src::measure_blur, [&](std::atomic<uint64_t>* pixels) {
    small_pass(ctx, into, [&] {
      draw_screen_rectangle(ctx, *small_target_, post_pass_state(), screen_rectangle(w, h, whole_texture(w, h)),
                            src::BlurPixelShader{&params, pixels});
    });
  });
}

const rasterizer::Texture& Bloom::frame_texture() const {
  require_copy("frame_texture");
  return *frame_;
}

const rasterizer::Texture& Bloom::bloom_texture() const {
  require_copy("bloom_texture");
  return *small_texture_[0];
}

TexelRect Bloom::bloom_rectangle() const {
  require_copy("bloom_rectangle");
  const int w = small_target_->width(), h = small_target_->height();
  return {0.0f, -0.5f, static_cast<float>(w - 1), static_cast<float>(h - 1), w, h};
}

void Bloom::add(rasterizer::Context& ctx, rasterizer::ColorTarget& frame, const ShaderTally& tally) {
  require_copy("add");
  src::BloomAddParams params;
  params.bloom = {0, &*small_texture_[0], bilinear_clamped()};
  counted_draw<src::BloomAddPixelShader>(tally, src::kSingleCombo, src::measure_bloom_add, [&](std::atomic<uint64_t>* pixels) {
    draw_screen_rectangle(ctx, frame, src::bloom_add_pipeline_state(),
                          screen_rectangle(frame.width(), frame.height(), bloom_rectangle()), src::BloomAddPixelShader{&params, pixels});
    ctx.flush();  // the draw reads `params` and `pixels`, which end here
  });
}

void Bloom::apply(rasterizer::Context& ctx, rasterizer::ColorTarget& frame, float amount, const ShaderTally& tally) {
  if (!(amount > 0.0f)) return;
  copy(ctx, frame);
  downsample(ctx, tally);
  blur_x(ctx, tally);
  blur_y(ctx, amount, tally);
  add(ctx, frame, tally);
}

void Bloom::apply(rasterizer::Context& ctx, rasterizer::Image& frame, float amount, const ShaderTally& tally) {
  if (blur(ctx, frame, amount, tally)) add(ctx, frame, tally);
}

void Bloom::add(rasterizer::Context& ctx, rasterizer::Image& frame, const ShaderTally& tally) {
  if (!image_target_ || image_target_->width() != frame.width || image_target_->height() != frame.height) {
    image_target_.emplace(frame.width, frame.height);
  }
  rasterizer::load_image(ctx, frame, *image_target_);
  add(ctx, *image_target_, tally);
  rasterizer::resolve_into(ctx, *image_target_, frame);
}

bool Bloom::blur(rasterizer::Context& ctx, const rasterizer::Image& frame, float amount, const ShaderTally& tally) {
  if (!(amount > 0.0f)) return false;
  copy(frame);
  blur_passes(ctx, amount, tally);
  return true;
}

bool Bloom::blur(rasterizer::Context& ctx, const rasterizer::Texture& frame, float amount, const ShaderTally& tally) {
  if (!(amount > 0.0f)) return false;
  read_frame(frame);
  blur_passes(ctx, amount, tally);
  return true;
}

void Bloom::blur_passes(rasterizer::Context& ctx, float amount, const ShaderTally& tally) {
  downsample(ctx, tally);
  blur_x(ctx, tally);
  blur_y(ctx, amount, tally);
}

}  // namespace luxel::postfx
