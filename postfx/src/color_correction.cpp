// The color-correction pass, the engine's way and exactly (color_correction.hpp).

#include "luxel/postfx/color_correction.hpp"

#include "counted_draw.hpp"

#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/shading/source/color_correction.hpp"

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

namespace luxel::postfx {

namespace {

namespace src = shading::source;

/// Two triangles covering the target; varying 0 is the frame's texture coordinate, so each pixel
/// center reads its own texel.
struct FullScreenVS {
  static constexpr int kVaryings = 1;
  void operator()(uint32_t i, rasterizer::VertexOutput<1>& out) const {
    static constexpr int kCorner[6][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {0, 1}};
    const float u = float(kCorner[i][0]), v = float(kCorner[i][1]);
    out.position = glm::vec4(2.0f * u - 1.0f, 1.0f - 2.0f * v, 0.5f, 1.0f);
    out.varyings[0] = glm::vec4(u, v, 0.0f, 0.0f);
  }
};

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

rasterizer::Image color_correct(rasterizer::Context& ctx, const rasterizer::Image& frame,
                                std::span<const WeightedLut> luts, const ShaderTally& tally) {
  const std::vector<float> weights = checked_weights(luts);
  check_frame(frame);
  for (const WeightedLut& l : luts)
    if (l.lut == nullptr) throw std::invalid_argument("color correction: a weighted LUT without its LUT");

  rasterizer::Texture frame_texture =
      rasterizer::Texture::create_2d(frame.width, frame.height, rasterizer::TextureFormat::RGBA8, 1);
  frame_texture.upload(0, frame.rgba);
  std::vector<rasterizer::Texture> volumes;
  src::ColorCorrectionParams params;
  params.frame.texture = &frame_texture;
  volumes.reserve(luts.size());  // the params point into it
  for (size_t k = 0; k < luts.size(); ++k) {
    volumes.push_back(lut_volume(*luts[k].lut));
    params.luts[k].texture = &volumes.back();
    params.lut_weights[int(k)] = weights[k];
  }
  params.default_weight = default_weight(weights);

  rasterizer::PipelineState state;
  state.rasterizer.cull = rasterizer::CullMode::None;
  state.depth_stencil.depth_enable = false;
  rasterizer::ColorTarget target(frame.width, frame.height);
  const FullScreenVS vs;
  src::for_each_color_correction_combo([&]<src::ColorCorrectionCombo C>() {
    if (C.luts != int(luts.size())) return;
    counted_draw<src::ColorCorrectionPixelShader<C>>(
        tally, C.name(), src::measure_color_correction<C>, [&](std::atomic<uint64_t>* pixels) {
          rasterizer::draw(ctx, rasterizer::Framebuffer{&target, nullptr}, state, rasterizer::Geometry::non_indexed(6), vs,
                           src::ColorCorrectionPixelShader<C>{&params, pixels});
          ctx.flush();  // the draw reads `params` and `pixels`
        });
  });
  return rasterizer::resolve(ctx, target);
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
