// Texture sampling cost: time per stamp (simd::kLanes pixels) and per pixel.
//
// Each benchmark walks the stamps of a 256x128-pixel screen rectangle covered by one textured
// quad, as a rasterizer would: texture coordinates are affine in screen space, so neighbouring
// stamps read neighbouring texels (the cache behaviour of real draws) and the LOD is what the
// scale below makes it. Textures are 1024x1024 (cube faces 256, volumes 64^3), with mips.
//
// Reported: real time per iteration = one stamp; "pixel" = time per pixel.

#include "luxel/rasterizer/texture.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace luxel::rasterizer {
namespace {

using simd::Float;
using simd::kLanes;

constexpr int kScreenWidth = 256, kScreenHeight = 128;

struct Stamps {
  std::vector<TexCoord> coords;
  std::vector<Float> lods;
};

/// Stamps of the screen rectangle. `texels_per_pixel` sets the LOD (log2 of it); `kind` picks
/// how screen positions become coordinates (2D/volume: affine; cube: directions sweeping across
/// the +Z face and over its edges).
Stamps make_stamps(const Texture& t, float texels_per_pixel) {
  Stamps s;
  const float du = texels_per_pixel / static_cast<float>(t.width());
  for (int y = 0; y < kScreenHeight; y += simd::kStampHeight) {
    for (int x = 0; x < kScreenWidth; x += simd::kStampWidth) {
      alignas(64) float u[kLanes], v[kLanes], w[kLanes];
      for (int l = 0; l < kLanes; ++l) {
        const float px = static_cast<float>(x + simd::lane_x(l)) + 0.5f;
        const float py = static_cast<float>(y + simd::lane_y(l)) + 0.5f;
        if (t.kind() == TextureKind::Cube) {
          // Across the +Z face and over its right and bottom edges.
          u[l] = -0.8f + px * du * 2.0f;
          v[l] = -0.8f + py * du * 2.0f;
          w[l] = 1.0f;
        } else {
          u[l] = 0.13f + px * du + py * du * 0.25f;
          v[l] = 0.37f + py * du - px * du * 0.25f;
          w[l] = 0.41f + (px + py) * du * 0.5f;
        }
      }
      s.coords.push_back({Float::load_aligned(u), Float::load_aligned(v), Float::load_aligned(w)});
      s.lods.push_back(Float(std::log2(texels_per_pixel)));
    }
  }
  return s;
}

/// Random texels in level 0 of every face.
void fill_level0(Texture& t) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  for (int face = 0; face < t.faces(); ++face) {
    std::vector<glm::vec4> texels(static_cast<size_t>(t.width()) * t.height() * t.depth());
    for (auto& c : texels) c = {value(rng), value(rng), value(rng), value(rng)};
    t.upload(0, texels, face);
  }
}

Texture make_texture(TextureKind kind, TextureFormat format) {
  Texture t = kind == TextureKind::Cube     ? Texture::create_cube(256, format)
              : kind == TextureKind::Volume ? Texture::create_volume(64, 64, 64, format)
                                            : Texture::create_2d(1024, 1024, format);
  fill_level0(t);
  t.generate_mips();
  return t;
}

enum class Lod { Explicit, Implicit };

void run(benchmark::State& state, TextureKind kind, TextureFormat format, Filter filter, MipFilter mip,
         float texels_per_pixel, Lod lod = Lod::Explicit) {
  const Texture t = make_texture(kind, format);
  Sampler sampler;
  sampler.min = sampler.mag = filter;
  sampler.mip = mip;
  const Stamps stamps = make_stamps(t, texels_per_pixel);
  size_t i = 0;
  for (auto _ : state) {
    const simd::Float4 r = lod == Lod::Implicit ? sample(t, sampler, stamps.coords[i])
                                                : sample_level(t, sampler, stamps.coords[i], stamps.lods[i]);
    benchmark::DoNotOptimize(r);
    if (++i == stamps.coords.size()) i = 0;
  }
  state.counters["pixel"] = benchmark::Counter(static_cast<double>(state.iterations()) * kLanes,
                                               benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Magnified (LOD < 0): one bilinear level. Minified 2.5 texels per pixel: trilinear between
// levels 1 and 2 on every lane.
constexpr float kMagnified = 0.7f, kMinified = 2.5f;

void BM_Texture2D_RGBA8_Bilinear(benchmark::State& s) {
  run(s, TextureKind::Texture2D, TextureFormat::RGBA8, Filter::Linear, MipFilter::Linear, kMagnified);
}
void BM_Texture2D_RGBA8_Trilinear(benchmark::State& s) {
  run(s, TextureKind::Texture2D, TextureFormat::RGBA8, Filter::Linear, MipFilter::Linear, kMinified);
}
void BM_Texture2D_RGBA8_Trilinear_ImplicitLod(benchmark::State& s) {
  run(s, TextureKind::Texture2D, TextureFormat::RGBA8, Filter::Linear, MipFilter::Linear, kMinified,
      Lod::Implicit);
}
void BM_Texture2D_RGBA8_Point(benchmark::State& s) {
  run(s, TextureKind::Texture2D, TextureFormat::RGBA8, Filter::Point, MipFilter::Point, kMinified);
}
void BM_Texture2D_RGBA8sRGB_Trilinear(benchmark::State& s) {
  run(s, TextureKind::Texture2D, TextureFormat::RGBA8_sRGB, Filter::Linear, MipFilter::Linear, kMinified);
}
void BM_Texture2D_RGBA16F_Bilinear(benchmark::State& s) {
  run(s, TextureKind::Texture2D, TextureFormat::RGBA16F, Filter::Linear, MipFilter::Linear, kMagnified);
}
void BM_Texture2D_RGBA16F_Trilinear(benchmark::State& s) {
  run(s, TextureKind::Texture2D, TextureFormat::RGBA16F, Filter::Linear, MipFilter::Linear, kMinified);
}
void BM_Cube_RGBA16F_Trilinear(benchmark::State& s) {
  run(s, TextureKind::Cube, TextureFormat::RGBA16F, Filter::Linear, MipFilter::Linear, kMinified);
}
void BM_Cube_RGBA16F_Trilinear_ImplicitLod(benchmark::State& s) {
  run(s, TextureKind::Cube, TextureFormat::RGBA16F, Filter::Linear, MipFilter::Linear, kMinified,
      Lod::Implicit);
}
void BM_Volume_RGBA8_Trilinear(benchmark::State& s) {
  run(s, TextureKind::Volume, TextureFormat::RGBA8, Filter::Linear, MipFilter::Linear, kMinified);
}
void BM_Volume_RGBA16F_Trilinear(benchmark::State& s) {
  run(s, TextureKind::Volume, TextureFormat::RGBA16F, Filter::Linear, MipFilter::Linear, kMinified);
}

/// The color-correction pass's read of its LUT: a 32^3 volume of one level, trilinear under Clamp
/// (so from its trilinear cells, texture.hpp), the coordinates moving a quarter of a texel per
/// pixel, as a frame's colors move.
void BM_Volume_RGBA8_ColorLookup(benchmark::State& state) {
  Texture t = Texture::create_volume(32, 32, 32, TextureFormat::RGBA8, 1);
  fill_level0(t);
  Sampler sampler;
  sampler.mip = MipFilter::None;
  sampler.u = sampler.v = sampler.w = Address::Clamp;
  const Stamps stamps = make_stamps(t, 0.25f);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sample(t, sampler, stamps.coords[i]));
    if (++i == stamps.coords.size()) i = 0;
  }
  state.counters["pixel"] = benchmark::Counter(static_cast<double>(state.iterations()) * kLanes,
                                               benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

/// A blur's 13 taps of one stamp (the bloom's, horizontal, on a level-0 sampler that needs no
/// LOD): independent samples, so what one costs when others overlap it. Reported per sample.
void BM_Texture2D_RGBA8_BlurTaps(benchmark::State& state) {
  const Texture t = make_texture(TextureKind::Texture2D, TextureFormat::RGBA8);
  Sampler sampler;
  sampler.mip = MipFilter::None;
  sampler.u = sampler.v = Address::Clamp;
  const Stamps stamps = make_stamps(t, kMagnified);
  constexpr int kTaps = 13;
  std::vector<std::array<TexCoord, kTaps>> taps(stamps.coords.size());
  for (size_t i = 0; i < taps.size(); ++i)
    for (int k = 0; k < kTaps; ++k)
      taps[i][k] = {stamps.coords[i].x + Float(float(k - 6) * 1.37f / float(t.width())), stamps.coords[i].y, Float(0.0f)};
  std::array<simd::Float4, kTaps> out;
  size_t i = 0;
  for (auto _ : state) {
    for (int k = 0; k < kTaps; ++k) out[k] = sample(t, sampler, taps[i][k]);
    benchmark::DoNotOptimize(out);
    if (++i == taps.size()) i = 0;
  }
  state.counters["sample"] = benchmark::Counter(static_cast<double>(state.iterations()) * kTaps,
                                                benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_Texture2D_RGBA8_Bilinear);
BENCHMARK(BM_Texture2D_RGBA8_BlurTaps);
BENCHMARK(BM_Texture2D_RGBA8_Trilinear);
BENCHMARK(BM_Texture2D_RGBA8_Trilinear_ImplicitLod);
BENCHMARK(BM_Texture2D_RGBA8_Point);
BENCHMARK(BM_Texture2D_RGBA8sRGB_Trilinear);
BENCHMARK(BM_Texture2D_RGBA16F_Bilinear);
BENCHMARK(BM_Texture2D_RGBA16F_Trilinear);
BENCHMARK(BM_Cube_RGBA16F_Trilinear);
BENCHMARK(BM_Cube_RGBA16F_Trilinear_ImplicitLod);
BENCHMARK(BM_Volume_RGBA8_Trilinear);
BENCHMARK(BM_Volume_RGBA8_ColorLookup);
BENCHMARK(BM_Volume_RGBA16F_Trilinear);

}  // namespace
}  // namespace luxel::rasterizer
