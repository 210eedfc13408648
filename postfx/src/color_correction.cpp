// The color-correction pass, the engine's way and exactly (color_correction.hpp).

#include "luxel/postfx/color_correction.hpp"

#include "counted_draw.hpp"
#include "screen_rectangle.hpp"

#include "luxel/shading/source/registry.hpp"

#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/postfx/full_frame.hpp"
#include "luxel/shading/source/color_correction.hpp"
#include "luxel/shading/source/engine_post.hpp"

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

namespace luxel::postfx {

namespace {

namespace src = shading::source;

template <class Weighted>
std::vector<float> checked_weights(std::span<const Weighted> items) {
  if (items.empty() || items.size() > size_t(kMaxLuts)) {
    throw std::invalid_argument("color correction blends 1 to " + std::to_string(kMaxLuts) + " LUTs, not " +
                                std::to_string(items.size()));
  }
  std::vector<float> weights;
  for (const Weighted& item : items) {
    if (!(item.weight >= 0.0f) || !std::isfinite(item.weight)) {
      throw std::invalid_argument("color correction weight " + std::to_string(item.weight) + ": must be finite and >= 0");
    }
    weights.push_back(item.weight);
  }
  return weights;
}

void check_frame(const rasterizer::Image& frame) {
  if (frame.width <= 0 || frame.height <= 0 || frame.rgba.size() != size_t(frame.width) * frame.height * 4) {
    throw std::invalid_argument("color correction: the frame's pixels do not match its size");
  }
}

}  // namespace

float default_weight(std::span<const float> weights) {
  float sum = 0.0f;
  for (float w : weights) sum += w;
  return std::max(0.0f, 1.0f - sum);
}

namespace {

/// The LUTs as the engine's volumes, and their weights, set into a pass's parameters (`Params`:
/// ColorCorrectionParams or EnginePostParams); the volumes the caller did not keep live in the
/// returned vector, which the parameters point into.
template <class Params>
std::vector<rasterizer::Texture> set_lookups(std::span<const WeightedLut> luts, Params& params) {
  const std::vector<float> weights = checked_weights(luts);
  for (const WeightedLut& l : luts) {
    if (l.lut == nullptr) throw std::invalid_argument("color correction: a weighted LUT without its LUT");
    if (l.lut->size != luts[0].lut->size)
      throw std::invalid_argument("color correction: LUTs of " + std::to_string(luts[0].lut->size) + " and " +
                                  std::to_string(l.lut->size) + " points per axis blended in one pass");
  }
  std::vector<rasterizer::Texture> volumes;
  volumes.reserve(luts.size());
  for (size_t k = 0; k < luts.size(); ++k) {
    if (!luts[k].volume) volumes.push_back(lut_volume(*luts[k].lut));
    params.luts[k].texture = luts[k].volume ? luts[k].volume : &volumes.back();
    params.lut_weights[int(k)] = weights[k];
  }
  params.default_weight = default_weight(weights);
  if (!luts.empty()) params.lut_size = luts[0].lut->size;
  return volumes;
}

/// One full-frame draw of pixel functor `Shader<C>` for the combo C of `Combo` that blends `luts`
/// lookups, into a new target, counted into `tally`; its pixels resolved into `out`.
template <class Combo, template <Combo> class Shader, auto kSpace, class Params>
void draw_pass(rasterizer::Context& ctx, int width, int height, size_t luts, const auto& rectangle, const Params& params,
               const ShaderTally& tally, rasterizer::Image& out) {
  // Invalidated (the draw writes every pixel) and discarded once resolved: the target lives in
  // tile memory only, and is never filled (rasterizer/framebuffer.hpp).
  rasterizer::ColorTarget target(width, height);
  src::for_each_combo<kSpace>([&]<Combo C>() {
    if (C.luts != int(luts)) return;
    const auto measure = [](shading::ShaderModel binary) { return src::counted_cost(C, binary); };
    counted_draw<Shader<C>>(tally, C.name(), measure, [&](std::atomic<uint64_t>* pixels) {
      rasterizer::invalidate(ctx, target);
      draw_screen_rectangle(ctx, target, post_pass_state(), rectangle, Shader<C>{&params, pixels});
      rasterizer::discard(ctx, target);
      rasterizer::resolve_into(ctx, target, out);  // flushes: the draw reads `params` and `pixels`
    });
  });
}

}  // namespace

rasterizer::Image color_correct(rasterizer::Context& ctx, const rasterizer::Image& frame,
                                std::span<const WeightedLut> luts, const ShaderTally& tally) {
  check_frame(frame);
  FullFrameTexture copy;
  copy.update(frame);
  return color_correct(ctx, copy.texture(), luts, tally);
}

rasterizer::Image color_correct(rasterizer::Context& ctx, const rasterizer::Texture& frame,
                                std::span<const WeightedLut> luts, const ShaderTally& tally) {
  rasterizer::Image out;
  color_correct_into(ctx, frame, luts, out, tally);
  return out;
}

rasterizer::Image color_correct(rasterizer::Context& ctx, const Bloom& bloom, std::span<const WeightedLut> luts,
                                const ShaderTally& tally) {
  rasterizer::Image out;
  color_correct_into(ctx, bloom, luts, out, tally);
  return out;
}

void color_correct_into(rasterizer::Context& ctx, const rasterizer::Texture& frame, std::span<const WeightedLut> luts,
                        rasterizer::Image& out, const ShaderTally& tally) {
  src::ColorCorrectionParams params;
  const std::vector<rasterizer::Texture> volumes = set_lookups(luts, params);
  check_frame_copy(frame, "color correction");
  params.frame.texture = &frame;
  const int w = frame.width(), h = frame.height();
  draw_pass<src::ColorCorrectionCombo, src::ColorCorrectionPixelShader, src::kColorCorrectionSpace>(
      ctx, w, h, luts.size(), screen_rectangle(w, h, whole_texture(w, h)), params, tally, out);
}

void color_correct_into(rasterizer::Context& ctx, const Bloom& bloom, std::span<const WeightedLut> luts,
                        rasterizer::Image& out, const ShaderTally& tally) {
  const rasterizer::Texture& frame = bloom.frame_texture();
  src::EnginePostParams params;
  params.frame.texture = &frame;
  params.bloom.texture = &bloom.bloom_texture();
  const std::vector<rasterizer::Texture> volumes = set_lookups(luts, params);
  const int w = frame.width(), h = frame.height();
  const ScreenRectanglePair rectangle{screen_rectangle(w, h, whole_texture(w, h)), screen_rectangle(w, h, bloom.bloom_rectangle())};
  draw_pass<src::EnginePostCombo, src::EnginePostPixelShader, src::kEnginePostSpace>(ctx, w, h, luts.size(), rectangle,
                                                                                  params, tally, out);
}

std::vector<float> color_correct_exact(const rasterizer::Image& frame, std::span<const WeightedTransform> transforms) {
  const std::vector<float> weights = checked_weights(transforms);
  check_frame(frame);
  for (const WeightedTransform& t : transforms)
    if (t.transform == nullptr) throw std::invalid_argument("color correction: a weighted transform without its transform");

  const size_t pixels = size_t(frame.width) * frame.height;
  std::vector<glm::vec3> in(pixels);
  for (size_t i = 0; i < pixels; ++i)
    in[i] = glm::vec3(frame.rgba[4 * i], frame.rgba[4 * i + 1], frame.rgba[4 * i + 2]) / 255.0f;
  std::vector<glm::vec3> sum(pixels);
  const float own = default_weight(weights);
  for (size_t i = 0; i < pixels; ++i) sum[i] = in[i] * own;
  std::vector<glm::vec3> graded;
  for (size_t k = 0; k < transforms.size(); ++k) {
    graded = in;
    transforms[k].transform->apply(graded);
    for (size_t i = 0; i < pixels; ++i) sum[i] += graded[i] * weights[k];
  }
  std::vector<float> out(pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    out[4 * i] = sum[i].x, out[4 * i + 1] = sum[i].y, out[4 * i + 2] = sum[i].z;
    out[4 * i + 3] = frame.rgba[4 * i + 3] / 255.0f;
  }
  return out;
}

}  // namespace luxel::postfx
