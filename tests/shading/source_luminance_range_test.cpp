// The luminance-range test of auto exposure: pass/fail at the exact float boundaries, the c0
// conventions (10000 for a max of 1.0, the FLOAT-only scale), SIMD vs scalar, budgets, and the
// shader drawn through the rasterizer: the occlusion query (directly, and through the stencil
// two-pass method) counts exactly the samples whose texel is in range.

#include "source_support.hpp"

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/draw_definition.hpp"
#include "luxel/shading/source/luminance_range.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace luxel::shading::source {
namespace {

using testing::compare_lanes;
using testing::Draw;

constexpr LuminanceRangeCombo kAlpha{LuminanceReject::alpha_test};
constexpr LuminanceRangeCombo kKill{LuminanceReject::texkill};

template <LuminanceRangeCombo C>
LuminanceRangeOutput<float> run(const glm::vec3& texel, float min, float max, float scale = 1.0f) {
  LuminanceRangeParams p;
  p.min_max_scale = glm::vec3(min, max, scale);
  return luminance_range_combine<C>(float3<float>(texel.x, texel.y, texel.z), p);
}

float shader_luminance(const glm::vec3& c) {
  // The shader's own dot product (same operations, same order): the boundary under test.
  return dot(float3<float>(c.x, c.y, c.z), float3<float>(kHistogramLuminance[0], kHistogramLuminance[1], kHistogramLuminance[2]));
}

TEST(SourceLuminanceRange, BothBoundsAreInclusiveToTheLastUlp) {
  for (const glm::vec3 c : {glm::vec3(0.3f, 0.6f, 0.1f), glm::vec3(1.0f), glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.02f)}) {
    const float lum = shader_luminance(c);
    const float above = std::nextafter(lum, 1e30f), below = std::nextafter(lum, -1e30f);
    EXPECT_EQ(run<kAlpha>(c, lum, lum).color.w, 1.0f) << "min = max = luminance passes";
    EXPECT_EQ(run<kAlpha>(c, above, 10.0f).color.w, 0.0f) << "min one ulp above fails";
    EXPECT_EQ(run<kAlpha>(c, 0.0f, below).color.w, 0.0f) << "max one ulp below fails";
    EXPECT_EQ(run<kAlpha>(c, below, above).color.x, 1.0f);
    EXPECT_FALSE(run<kKill>(c, lum, lum).discard);
    EXPECT_TRUE(run<kKill>(c, above, 10.0f).discard);
    EXPECT_EQ(run<kKill>(c, lum, lum).depth, 0.0f);
  }
}

TEST(SourceLuminanceRange, WeightsAreTheHistogramOnesAndScaleMultipliesFirst) {
  // Pure channels: luminance = the weight; x scale 4.
  EXPECT_EQ(run<kAlpha>(glm::vec3(1, 0, 0), 0.2125f, 0.2125f).color.w, 1.0f);
  EXPECT_EQ(run<kAlpha>(glm::vec3(0, 1, 0), 0.7154f, 0.7154f).color.w, 1.0f);
  EXPECT_EQ(run<kAlpha>(glm::vec3(0, 0, 1), 0.0721f, 0.0721f).color.w, 1.0f);
  EXPECT_EQ(run<kAlpha>(glm::vec3(0, 0.25f, 0), 0.7154f, 0.7154f, 4.0f).color.w, 1.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(run<kAlpha>(glm::vec3(nan, 0.5f, 0.5f), 0.0f, 100000.0f).color.w, 0.0f) << "NaN is never counted";
  EXPECT_TRUE(run<kKill>(glm::vec3(nan), 0.0f, 100000.0f).discard);
}

TEST(SourceLuminanceRange, ConstantSubstitutesTheTopBucketAndScalesOnlyInFloatMode) {
  EXPECT_EQ(luminance_range_constant(0.9077f, 1.0f).y, 10000.0f);
  // The original algorithm's top bound in float: no substitution, so white fails.
  const glm::vec3 original = luminance_range_constant(0.85599f, 0.99999982f);
  EXPECT_EQ(original.y, 0.99999982f);
  EXPECT_EQ(run<kAlpha>(glm::vec3(1.0f), original.x, original.y).color.w, 0.0f);
  EXPECT_EQ(run<kAlpha>(glm::vec3(1.0f), 0.9077f, 10000.0f).color.w, 1.0f);
  EXPECT_EQ(luminance_range_constant(0.1f, 0.2f, HdrType::integer, 3.0f).z, 1.0f);
  EXPECT_EQ(luminance_range_constant(0.1f, 0.2f, HdrType::none, 3.0f).z, 1.0f);
  EXPECT_EQ(luminance_range_constant(0.1f, 0.2f, HdrType::floating, 3.0f).z, 3.0f);
}

TEST(SourceLuminanceRange, SimdAgreesWithScalarExactly) {
  for (int hard_every : {0, 3}) {
    int worst = 0;
    for_each_combo<kLuminanceRangeSpace>([&]<LuminanceRangeCombo C>() {
      LuminanceRangeParams p;
      p.min_max_scale = glm::vec3(0.2f, 0.6f, 1.0f);
      auto shade = [&]<class L>(const auto& get) -> float4<L> {
        const LuminanceRangeOutput<L> out = luminance_range_combine<C>(float3<L>(get(0), get(1), get(2)), p);
        return float4<L>(out.color.xyz(), select(out.discard, L(0.5f), out.color.w));
      };
      const auto r = compare_lanes<3>(shade, {Draw{0.0f, 1.0f, hard_every}}, 512, 41u + hard_every);
      worst = std::max(worst, r.max_step);
    });
    EXPECT_EQ(worst, 0) << "a 0/1 decision: the lanes must agree exactly (hard_every " << hard_every << ")";
    std::printf("LuminanceRange simd-vs-scalar max %d step(s) (%s inputs)\n", worst, hard_every ? "hard" : "random");
  }
}

TEST(SourceLuminanceRange, EveryComboFitsEveryPixelShaderModel) {
  for_each_combo<kLuminanceRangeSpace>([&]<LuminanceRangeCombo C>() {
    for (ShaderModel m : kPixelModels) {
      const Cost cost = measure_luminance_range<C>(m);
      const Verdict v = fits(cost, caps(m));
      EXPECT_TRUE(v) << C.name() << ": " << v.reason;
      // texld; one more texture slot for texkill.
      EXPECT_EQ(cost.texture_slots, C.reject == LuminanceReject::texkill ? 2 : 1) << C.name() << " " << describe(cost);
      EXPECT_GE(cost.arithmetic_slots, 4) << "dot, two compares and the product at least";
    }
  });
}

// ---- Through the rasterizer ----------------------------------------------------------------------

/// A screen-space rectangle [x0, x1) x [y0, y1) as two triangles; varying 0 = texture coordinate of
/// a frame-sized texture, so pixel centers read texel centers.
struct RectVS {
  static constexpr int kVaryings = 1;
  int width, height;
  float x0, y0, x1, y1;
  void operator()(uint32_t i, rasterizer::VertexOutput<1>& out) const {
    static constexpr int kCorner[6][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {0, 1}};
    const float sx = kCorner[i][0] ? x1 : x0, sy = kCorner[i][1] ? y1 : y0;
    out.position = glm::vec4(2.0f * sx / width - 1.0f, 1.0f - 2.0f * sy / height, 0.5f, 1.0f);
    out.varyings[0] = glm::vec4(sx / width, sy / height, 0.0f, 0.0f);
  }
};

/// dev/no_pixel_write: the second stencil pass draws no color; only the stencil decides.
struct NoPixelWritePS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  void operator()(const rasterizer::PixelInput<1>&, rasterizer::PixelOutput& out) const {
    out.color = {simd::Float(0.0f), simd::Float(0.0f), simd::Float(0.0f), simd::Float(0.0f)};
  }
};

double srgb_decode(int byte) {
  const double s = byte / 255.0;
  return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
}

template <LuminanceRangeCombo C>
void check_counts(int samples) {
  const int W = 96, H = 64;
  rasterizer::Texture frame = rasterizer::Texture::create_2d(W, H, rasterizer::TextureFormat::RGBA8_sRGB, 1);
  std::vector<uint8_t> bytes(size_t(W) * H * 4);
  std::mt19937 rng(1234u + samples);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<uint8_t>(rng() & 0xff);
  for (int i = 0; i < 9; ++i) {  // inside the rectangle below: black (luminance exactly 0), greys, white (1)
    for (int c = 0; c < 3; ++c) bytes[(size_t(10) * W + 20 + i) * 4 + c] = static_cast<uint8_t>(std::min(255, 32 * i));
  }
  frame.upload(0, bytes);
  LuminanceRangeParams params;
  params.frame.texture = &frame;
  params.frame.state.min = params.frame.state.mag = rasterizer::Filter::Point;
  params.frame.state.mip = rasterizer::MipFilter::None;

  // The exposure region of a real frame is the viewport minus a border; any rectangle will do here.
  const int x0 = 5, y0 = 3, x1 = 91, y1 = 60;
  const RectVS vs{W, H, float(x0), float(y0), float(x1), float(y1)};
  rasterizer::Context ctx(2);
  rasterizer::ColorTarget color(W, H, samples);
  rasterizer::DepthStencilTarget ds(W, H, samples);
  const LuminanceRangePixelShader<C> ps{&params};

  // The new algorithm's 16 buckets and the calibration bucket.
  for (int bucket = 0; bucket <= 16; ++bucket) {
    const float lo = bucket == 16 ? 0.0f : std::pow(bucket / 16.0f, 1.5f);
    const float hi = bucket == 16 ? 100000.0f : std::pow((bucket + 1) / 16.0f, 1.5f);
    params.min_max_scale = luminance_range_constant(lo, hi);

    // Oracles: the scalar lane per pixel, and the luminance in double from the bytes.
    uint64_t scalar_pixels = 0, double_pixels = 0;
    std::vector<uint8_t> expect_written(size_t(W) * H, 0);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const float2<float> uv((x + 0.5f) / W, (y + 0.5f) / H);
        const LuminanceRangeOutput<float> out = luminance_range<C>(uv, params);
        const bool pass = C.reject == LuminanceReject::texkill ? !out.discard : out.color.w > 0.0f;
        scalar_pixels += pass;
        expect_written[size_t(y) * W + x] = pass;
        const uint8_t* t = &bytes[(size_t(y) * W + x) * 4];
        const double lum = 0.2125 * srgb_decode(t[0]) + 0.7154 * srgb_decode(t[1]) + 0.0721 * srgb_decode(t[2]);
        double_pixels += lum >= lo && lum <= params.min_max_scale.y;
      }
    EXPECT_EQ(scalar_pixels, double_pixels) << "bucket " << bucket << ": float shader vs double brute force";

    // Direct: the compare draw inside the query, color writes on so the pixels can be checked.
    rasterizer::PipelineState direct = luminance_range_pipeline_state(C.reject, LuminancePass::query);
    direct.blend.write_mask = rasterizer::kWriteAll;
    rasterizer::clear_color(ctx, color, glm::vec4(0.0f, 0.0f, 0.0f, 0.0f));
    rasterizer::OcclusionQuery query;
    ctx.begin_query(query);
    rasterizer::draw(ctx, rasterizer::Framebuffer{&color, nullptr}, direct, rasterizer::Geometry::non_indexed(6), vs, ps);
    ctx.end_query();
    EXPECT_EQ(ctx.query_result(query), scalar_pixels * samples) << "bucket " << bucket << ", " << samples << " samples";
    int wrong = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        for (int s = 0; s < samples; ++s)
          wrong += color.sample(x, y, s) != (expect_written[size_t(y) * W + x] ? 0xffffffffu : 0u);
    EXPECT_EQ(wrong, 0) << "bucket " << bucket << ": written pixels differ from the scalar path";

    // Stencil method: mark, then count where the stencil is 1.
    rasterizer::clear_depth_stencil(ctx, ds, 1.0f, 0);
    rasterizer::draw(ctx, rasterizer::Framebuffer{nullptr, &ds}, luminance_range_pipeline_state(C.reject, LuminancePass::stencil_mark),
                     rasterizer::Geometry::non_indexed(6), vs, ps);
    rasterizer::OcclusionQuery stencil_query;
    ctx.begin_query(stencil_query);
    const RectVS everything{W, H, 0.0f, 0.0f, float(W), float(H)};
    rasterizer::draw(ctx, rasterizer::Framebuffer{nullptr, &ds},
                     luminance_range_pipeline_state(C.reject, LuminancePass::stencil_count),
                     rasterizer::Geometry::non_indexed(6), everything, NoPixelWritePS{});
    ctx.end_query();
    EXPECT_EQ(ctx.query_result(stencil_query), scalar_pixels * samples) << "stencil method, bucket " << bucket;
  }
}

TEST(SourceLuminanceRange, OcclusionQueryCountsExactlyTheSamplesInRange) {
  for (int samples : {1, 4}) {
    check_counts<kAlpha>(samples);
    check_counts<kKill>(samples);
  }
}

}  // namespace
}  // namespace luxel::shading::source
