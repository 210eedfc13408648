// Textures: storage and formats, closed-form sampling checks (addressing, filtering, LOD, cube
// faces and seams, volumes, mips), and the SIMD path held to the scalar reference.
//
// Oracles are independent of the code under test: hand-computed values (sRGB constants from
// Python's math, cube-face layouts from D3D's table), conservation laws (mips keep the mean),
// smooth functions (seamless cube filtering of a linear function of the direction), and the
// scalar reference, which picks texels by other means than the SIMD path (true modulo, ray
// casting across cube edges) and filters in double.

#include "luxel/rasterizer/texture.hpp"

#include "luxel/rasterizer/srgb.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace luxel::rasterizer {
namespace {

using simd::kLanes;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// --- Helpers ----------------------------------------------------------------------------------

using LaneValues = std::array<float, kLanes>;

simd::Float lanes_of(const LaneValues& v) { return simd::Float::load_unaligned(v.data()); }

std::array<glm::vec4, kLanes> unpack(const simd::Float4& r) {
  LaneValues x, y, z, w;
  r.x.store_unaligned(x.data());
  r.y.store_unaligned(y.data());
  r.z.store_unaligned(z.data());
  r.w.store_unaligned(w.data());
  std::array<glm::vec4, kLanes> out;
  for (int l = 0; l < kLanes; ++l) out[l] = {x[l], y[l], z[l], w[l]};
  return out;
}

/// The SIMD path on one coordinate (all lanes the same), lane 0's result.
glm::vec4 simd_sample_level(const Texture& t, const Sampler& s, glm::vec3 c, float lod) {
  const TexCoord coord{simd::Float(c.x), simd::Float(c.y), simd::Float(c.z)};
  return unpack(sample_level(t, s, coord, simd::Float(lod)))[0];
}

/// Both paths; tests check every expectation on each.
std::array<glm::vec4, 2> both_paths(const Texture& t, const Sampler& s, glm::vec3 c, float lod = 0.0f) {
  return {sample_reference(t, s, c, lod), simd_sample_level(t, s, c, lod)};
}

#define EXPECT_BOTH_NEAR(texture, sampler, coord, lod, expected, tolerance)                             \
  for (const glm::vec4 got : both_paths(texture, sampler, coord, lod)) {                                \
    for (int ch = 0; ch < 4; ++ch) EXPECT_NEAR(got[ch], (expected)[ch], tolerance) << "channel " << ch; \
  }

Sampler point_sampler(Address address = Address::Wrap) {
  Sampler s;
  s.min = s.mag = Filter::Point;
  s.mip = MipFilter::None;
  s.u = s.v = s.w = address;
  return s;
}

Sampler linear_sampler(Address address = Address::Wrap) {
  Sampler s = point_sampler(address);
  s.min = s.mag = Filter::Linear;
  return s;
}

/// A float texture (R32F) with level 0 texels given (x fastest, then y, then z).
Texture r32f_2d(int w, int h, const std::vector<float>& values, int levels = 1) {
  Texture t = Texture::create_2d(w, h, TextureFormat::R32F, levels);
  t.upload(0, std::span(reinterpret_cast<const uint8_t*>(values.data()), values.size() * sizeof(float)));
  return t;
}

/// Random contents for every level and face: any bytes for UNORM formats, values in [-2, 2] for
/// float formats (finite, so results can be compared with a tolerance).
void fill_random(Texture& t, std::mt19937& rng) {
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_real_distribution<float> value(-2.0f, 2.0f);
  for (int face = 0; face < t.faces(); ++face) {
    for (int level = 0; level < t.mip_levels(); ++level) {
      const auto bytes = t.level_bytes(level, face);
      if (t.format() == TextureFormat::RGBA16F || t.format() == TextureFormat::R32F) {
        const size_t texels = bytes.size() / bytes_per_texel(t.format());
        std::vector<glm::vec4> v(texels);
        for (auto& x : v) x = {value(rng), value(rng), value(rng), value(rng)};
        t.upload(level, v, face);
      } else {
        std::vector<uint8_t> random(bytes.size());
        for (auto& b : random) b = static_cast<uint8_t>(byte(rng));
        t.upload(level, random, face);
      }
    }
  }
}

const char* name(TextureFormat f) {
  switch (f) {
    case TextureFormat::RGBA8: return "RGBA8";
    case TextureFormat::RGBA8_sRGB: return "RGBA8_sRGB";
    case TextureFormat::RGBA16F: return "RGBA16F";
    case TextureFormat::RGBA16: return "RGBA16";
    case TextureFormat::R32F: return "R32F";
  }
  return "?";
}
const char* name(Filter f) { return f == Filter::Point ? "point" : "linear"; }
const char* name(MipFilter f) {
  return f == MipFilter::None ? "none" : f == MipFilter::Point ? "point" : "linear";
}
const char* name(Address a) {
  switch (a) {
    case Address::Wrap: return "wrap";
    case Address::Mirror: return "mirror";
    case Address::Clamp: return "clamp";
    case Address::Border: return "border";
  }
  return "?";
}

constexpr std::array kFormats = {TextureFormat::RGBA8, TextureFormat::RGBA8_sRGB, TextureFormat::RGBA16F,
                                 TextureFormat::RGBA16, TextureFormat::R32F};

// --- Creation and storage ---------------------------------------------------------------------

TEST(TextureCreate, SizesLevelsAndStorage) {
  // The words past the last texel that a sampling read of a stamp row may load.
  constexpr size_t kPadding = 4u * simd::kStampRowWindowWords;
  const Texture big = Texture::create_2d(1024, 1024, TextureFormat::RGBA8);
  EXPECT_EQ(big.mip_levels(), 11);
  EXPECT_EQ(big.width(10), 1);
  // 4 bytes x (1024^2 + 512^2 + ... + 1): native storage, ~5.3 MiB, not float32.
  EXPECT_EQ(big.storage_bytes(), 4u * 1398101u + kPadding);

  const Texture odd = Texture::create_2d(13, 7, TextureFormat::RGBA16F);
  EXPECT_EQ(odd.mip_levels(), 4);  // 13x7, 6x3, 3x1, 1x1
  EXPECT_EQ(odd.width(1), 6);
  EXPECT_EQ(odd.height(1), 3);
  EXPECT_EQ(odd.width(2), 3);
  EXPECT_EQ(odd.height(2), 1);
  EXPECT_EQ(odd.width(3), 1);
  EXPECT_EQ(odd.storage_bytes(), 8u * (91 + 18 + 3 + 1) + kPadding);
  EXPECT_EQ(odd.level_bytes(1).size(), 8u * 18);

  const Texture cube = Texture::create_cube(16, TextureFormat::RGBA8_sRGB);
  EXPECT_EQ(cube.kind(), TextureKind::Cube);
  EXPECT_EQ(cube.faces(), 6);
  EXPECT_EQ(cube.mip_levels(), 5);
  // The levels, and the copy sampling reads: each level bordered by one texel.
  EXPECT_EQ(cube.storage_bytes(), 6u * 4u * ((256 + 64 + 16 + 4 + 1) + (18 * 18 + 10 * 10 + 6 * 6 + 4 * 4 + 3 * 3)) + kPadding);

  const Texture volume = Texture::create_volume(8, 4, 2, TextureFormat::R32F);
  EXPECT_EQ(volume.mip_levels(), 4);
  EXPECT_EQ(volume.depth(1), 1);
  EXPECT_EQ(volume.height(2), 1);
  EXPECT_EQ(volume.storage_bytes(), 4u * (64 + 8 + 2 + 1) + kPadding);
  // One level of a one-word format: the texels, and four per trilinear cell's square, (8+1)(4+1)
  // squares in each of 2+2 slices; a two-word format keeps none, nor does a volume whose cells
  // would pass kMaxCellWords (100^3 is the largest cube that keeps them).
  EXPECT_EQ(Texture::create_volume(8, 4, 2, TextureFormat::RGBA8, 1).storage_bytes(), 4u * (64 + 4 * 9 * 5 * 4) + kPadding);
  EXPECT_EQ(Texture::create_volume(100, 100, 100, TextureFormat::R32F, 1).storage_bytes(),
            4u * (100 * 100 * 100 + 4 * 101 * 101 * 102) + kPadding);
  EXPECT_EQ(Texture::create_volume(101, 101, 101, TextureFormat::R32F, 1).storage_bytes(), 4u * 101 * 101 * 101 + kPadding);
  EXPECT_EQ(Texture::create_volume(8, 4, 2, TextureFormat::RGBA16F, 1).storage_bytes(), 8u * 64 + kPadding);
  EXPECT_EQ(Texture::create_volume(127, 127, 127, TextureFormat::R32F, 1).storage_bytes(), 4u * 127 * 127 * 127 + kPadding);

  EXPECT_EQ(Texture::create_2d(64, 64, TextureFormat::RGBA16, 1).mip_levels(), 1);
  EXPECT_EQ(Texture::create_2d(64, 64, TextureFormat::RGBA16, 3).storage_bytes(), 8u * (4096 + 1024 + 256) + kPadding);
}

TEST(TextureCreate, BadSizesThrow) {
  EXPECT_THROW(Texture::create_2d(0, 4, TextureFormat::RGBA8), std::invalid_argument);
  EXPECT_THROW(Texture::create_2d(4, -1, TextureFormat::RGBA8), std::invalid_argument);
  EXPECT_THROW(Texture::create_2d(8193, 4, TextureFormat::RGBA8), std::invalid_argument);
  EXPECT_THROW(Texture::create_cube(0, TextureFormat::RGBA8), std::invalid_argument);
  EXPECT_THROW(Texture::create_cube(8193, TextureFormat::RGBA8), std::invalid_argument);
  EXPECT_THROW(Texture::create({TextureKind::Cube, TextureFormat::RGBA8, 8, 4, 1, 0}), std::invalid_argument);
  EXPECT_THROW(Texture::create({TextureKind::Texture2D, TextureFormat::RGBA8, 8, 8, 2, 0}),
               std::invalid_argument);
  EXPECT_THROW(Texture::create_volume(4, 4, 0, TextureFormat::RGBA8), std::invalid_argument);
  EXPECT_THROW(Texture::create_volume(2049, 4, 4, TextureFormat::RGBA8), std::invalid_argument);
  EXPECT_THROW(Texture::create_2d(8, 8, TextureFormat::RGBA8, 5), std::invalid_argument);  // full chain is 4
  EXPECT_THROW(Texture::create_2d(8, 8, TextureFormat::RGBA8, -1), std::invalid_argument);
  // Within the per-axis limits but past 32-bit word offsets: refused before allocating.
  EXPECT_THROW(Texture::create_volume(2048, 2048, 2048, TextureFormat::RGBA8), std::invalid_argument);
  try {
    Texture::create_2d(8193, 16, TextureFormat::RGBA8);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("width 8193"), std::string::npos) << e.what();
  }
  try {
    Texture::create({TextureKind::Cube, TextureFormat::RGBA8, 8, 4, 1, 0});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("square"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(Texture::create_2d(8192, 1, TextureFormat::RGBA8));
}

TEST(TextureCreate, BadAccessThrows) {
  Texture t = Texture::create_cube(4, TextureFormat::RGBA8, 2);
  std::vector<uint8_t> bytes(4 * 4 * 4);
  EXPECT_NO_THROW(t.upload(0, bytes, 5));
  EXPECT_THROW(t.upload(0, bytes, 6), std::out_of_range);
  EXPECT_THROW(t.upload(2, bytes, 0), std::out_of_range);
  EXPECT_THROW(t.upload(1, bytes, 0), std::invalid_argument);  // level 1 is 2x2
  std::vector<glm::vec4> texels(15);
  EXPECT_THROW(t.upload(0, texels, 0), std::invalid_argument);
  EXPECT_THROW(t.load(4, 0, 0, 0), std::out_of_range);
  EXPECT_THROW(t.load(0, 0, 6, 0), std::out_of_range);
  EXPECT_THROW(t.load(0, 0, 0, 2), std::out_of_range);
}

// --- Formats ----------------------------------------------------------------------------------

TEST(TextureFormat, Rgba8EncodeRoundsToNearestEven) {
  Texture t = Texture::create_2d(4, 2, TextureFormat::RGBA8, 1);
  // 0.5 is the only value in [0, 1] that lands exactly on a tie (x * 255 = k + 1/2 needs x = a/2).
  const std::vector<glm::vec4> in = {{0.5f, 0.4f / 255, 0.6f / 255, 2.4f / 255},
                                     {-1.0f, 2.0f, kNaN, 1.0f},
                                     {0.25f, 0.75f, 100.0f / 255, 200.0f / 255},
                                     {0, 0, 0, 0},
                                     {0, 0, 0, 0},
                                     {0, 0, 0, 0},
                                     {0, 0, 0, 0},
                                     {0, 0, 0, 0}};
  t.upload(0, in);
  const auto b = t.level_bytes(0);
  EXPECT_EQ(b[0], 128);  // 127.5 -> 128
  EXPECT_EQ(b[1], 0);
  EXPECT_EQ(b[2], 1);
  EXPECT_EQ(b[3], 2);
  EXPECT_EQ(b[4], 0);  // saturate
  EXPECT_EQ(b[5], 255);
  EXPECT_EQ(b[6], 0);  // NaN -> 0
  EXPECT_EQ(b[7], 255);
  EXPECT_EQ(b[8], 64);   // 63.75
  EXPECT_EQ(b[9], 191);  // 191.25
  EXPECT_EQ(b[10], 100);
  EXPECT_EQ(b[11], 200);
  EXPECT_EQ(t.load(2, 0), glm::vec4(64 / 255.0f, 191 / 255.0f, 100 / 255.0f, 200 / 255.0f));
}

TEST(TextureFormat, SrgbDecodesKnownValues) {
  // Expected values: Python, math on the IEC 61966-2-1 curve in double.
  Texture t = Texture::create_2d(2, 1, TextureFormat::RGBA8_sRGB, 1);
  const std::vector<uint8_t> bytes = {0, 10, 128, 128, 188, 255, 1, 255};
  t.upload(0, bytes);
  const glm::vec4 a = t.load(0, 0), b = t.load(1, 0);
  EXPECT_EQ(a.x, 0.0f);
  EXPECT_FLOAT_EQ(a.y, 0.003035269835488375f);  // linear segment: 10/255/12.92
  EXPECT_FLOAT_EQ(a.z, 0.21586050011389926f);
  EXPECT_FLOAT_EQ(a.w, 128 / 255.0f);  // alpha is linear
  EXPECT_FLOAT_EQ(b.x, 0.5028864580325687f);
  EXPECT_EQ(b.y, 1.0f);
  EXPECT_FLOAT_EQ(b.z, 0.0003035269835488375f);
  // Both sampling paths decode the same way (point sampling at the texel centers).
  const Sampler s = point_sampler();
  for (const glm::vec4 got : both_paths(t, s, {0.25f, 0.5f, 0})) EXPECT_EQ(got, a);
  for (const glm::vec4 got : both_paths(t, s, {0.75f, 0.5f, 0})) EXPECT_EQ(got, b);

  // Every byte: the SIMD path's table agrees with the exact curve, rounded once to float.
  Texture all = Texture::create_2d(256, 1, TextureFormat::RGBA8_sRGB, 1);
  std::vector<uint8_t> ramp(256 * 4);
  for (int c = 0; c < 256; ++c)
    ramp[c * 4] = ramp[c * 4 + 1] = ramp[c * 4 + 2] = ramp[c * 4 + 3] = uint8_t(c);
  all.upload(0, ramp);
  for (int c = 0; c < 256; ++c) {
    const float expected =
        static_cast<float>(c <= 10 ? c / 255.0 / 12.92 : std::pow((c / 255.0 + 0.055) / 1.055, 2.4));
    const glm::vec4 got = simd_sample_level(all, s, {(c + 0.5f) / 256, 0.5f, 0}, 0.0f);
    EXPECT_EQ(got.x, expected) << c;
    EXPECT_EQ(got.w, c / 255.0f) << c;
    EXPECT_EQ(all.load(c, 0).x, expected) << c;
  }

  // Encoding: linear 0.5 is sRGB 187.516 -> 188; alpha stays linear.
  t.upload(0, std::vector<glm::vec4>{{0.5f, 0.21586050011389926f, 1.0f, 0.5f},
                                     {0.0f, 0.003035269835488375f, 2.0f, 1.0f}});
  const auto e = t.level_bytes(0);
  EXPECT_EQ(e[0], 188);
  EXPECT_EQ(e[1], 128);
  EXPECT_EQ(e[2], 255);
  EXPECT_EQ(e[3], 128);
  EXPECT_EQ(e[4], 0);
  EXPECT_EQ(e[5], 10);
  EXPECT_EQ(e[6], 255);
}

TEST(TextureFormat, SrgbReadSamplerStateDecodesAnRgba8TextureAsRgba8Srgb) {
  // D3DSAMP_SRGBTEXTURE: the same bytes in an RGBA8 texture read with srgb_read give what the
  // RGBA8_sRGB texture gives: the curve's values (SrgbDecodesKnownValues), filtered in linear.
  const std::vector<uint8_t> bytes = {0, 10, 128, 128, 188, 255, 1, 255};
  Texture plain = Texture::create_2d(2, 1, TextureFormat::RGBA8, 1);
  plain.upload(0, bytes);
  Sampler s = point_sampler();
  s.srgb_read = true;
  for (const glm::vec4 got : both_paths(plain, s, {0.25f, 0.5f, 0})) {
    EXPECT_EQ(got.x, 0.0f);
    EXPECT_FLOAT_EQ(got.y, 0.003035269835488375f);
    EXPECT_FLOAT_EQ(got.z, 0.21586050011389926f);
    EXPECT_FLOAT_EQ(got.w, 128 / 255.0f);  // alpha is linear
  }
  // Bilinear halfway between the two texels. The ideal rules decode before filtering: the mean of
  // the decoded values (0.5 (0.0030353 + 1) = 0.5015177). The hardware rules filter the codes in
  // fixed point (10 + floor(128 (255 - 10) / 256 + 1/2) = 133) and decode that: 0.2346.
  Sampler linear = s;
  linear.min = linear.mag = Filter::Linear;
  linear.u = linear.v = Address::Clamp;
  linear.rules = SamplingRules::ideal;
  for (const glm::vec4 got : both_paths(plain, linear, {0.5f, 0.5f, 0})) EXPECT_NEAR(got.y, 0.5015176349f, 1e-6f);
  linear.rules = SamplingRules::hardware;
  for (const glm::vec4 got : both_paths(plain, linear, {0.5f, 0.5f, 0})) EXPECT_EQ(got.y, kSrgbToLinear[133]);
  // Read without it, the bytes are gamma values; an RGBA8_sRGB texture decodes either way.
  Sampler gamma = s;
  gamma.srgb_read = false;
  for (const glm::vec4 got : both_paths(plain, gamma, {0.25f, 0.5f, 0})) EXPECT_EQ(got.y, 10 / 255.0f);
  Texture srgb = Texture::create_2d(2, 1, TextureFormat::RGBA8_sRGB, 1);
  srgb.upload(0, bytes);
  for (const Sampler& any : {s, gamma})
    for (const glm::vec4 got : both_paths(srgb, any, {0.75f, 0.5f, 0})) EXPECT_FLOAT_EQ(got.x, 0.5028864580325687f);
}

TEST(TextureFormat, Rgba16fRoundTrips) {
  const float denormal = std::ldexp(1.0f, -24), smallest_normal = std::ldexp(1.0f, -14);
  const std::vector<glm::vec4> in = {
      {1.5f, -2.0f, 65504.0f, denormal},
      {smallest_normal, 3 * denormal, -0.0f, 0.1f},
      {1.0f + std::ldexp(1.0f, -11), 1.0f + 3 * std::ldexp(1.0f, -11), 70000.0f, -kInf},
      {kNaN, 65519.0f, 65520.0f, 1e-9f}};
  const std::vector<glm::vec4> expected = {
      {1.5f, -2.0f, 65504.0f, denormal},
      {smallest_normal, 3 * denormal, -0.0f, 0.0999755859375f},  // 0.1 -> nearest half
      {1.0f, 1.0f + std::ldexp(1.0f, -9), kInf, -kInf},          // ties to even; overflow -> inf
      {kNaN, 65504.0f, kInf, 0.0f}};
  Texture t = Texture::create_2d(4, 1, TextureFormat::RGBA16F, 1);
  t.upload(0, in);
  Sampler s = point_sampler();
  for (int x = 0; x < 4; ++x) {
    const glm::vec4 loaded = t.load(x, 0);
    for (int c = 0; c < 4; ++c) {
      if (std::isnan(expected[x][c])) {
        EXPECT_TRUE(std::isnan(loaded[c]));
      } else {
        EXPECT_EQ(loaded[c], expected[x][c]) << "texel " << x << " channel " << c;
        EXPECT_EQ(std::signbit(loaded[c]), std::signbit(expected[x][c]));
      }
    }
    // The SIMD decoder (F16C) agrees, denormals included, also with denormals flushed.
    for (bool flush : {false, true}) {
      std::optional<simd::ScopedFlushDenormals> ftz;
      if (flush) ftz.emplace();
      const glm::vec4 got = simd_sample_level(t, s, {(x + 0.5f) / 4, 0.5f, 0}, 0.0f);
      for (int c = 0; c < 4; ++c) {
        if (std::isnan(expected[x][c])) {
          EXPECT_TRUE(std::isnan(got[c]));
        } else {
          EXPECT_EQ(got[c], expected[x][c]) << "texel " << x << " channel " << c << " flush " << flush;
        }
      }
    }
  }
}

TEST(TextureFormat, Rgba16RoundTrips) {
  Texture t = Texture::create_2d(2, 1, TextureFormat::RGBA16, 1);
  t.upload(0,
           std::vector<glm::vec4>{{0.5f, 1.0f, 0.0f, 1.0f / 65535}, {0.25f, 2.0f, -1.0f, 12345.0f / 65535}});
  uint16_t raw[8];
  std::memcpy(raw, t.level_bytes(0).data(), 16);
  EXPECT_EQ(raw[0], 32768);  // 32767.5 -> even
  EXPECT_EQ(raw[1], 65535);
  EXPECT_EQ(raw[2], 0);
  EXPECT_EQ(raw[3], 1);
  EXPECT_EQ(raw[4], 16384);  // 16383.75
  EXPECT_EQ(raw[5], 65535);
  EXPECT_EQ(raw[6], 0);
  EXPECT_EQ(raw[7], 12345);
  const glm::vec4 expected(32768 / 65535.0f, 1.0f, 0.0f, 1 / 65535.0f);
  EXPECT_EQ(t.load(0, 0), expected);
  for (const glm::vec4 got : both_paths(t, point_sampler(), {0.25f, 0.5f, 0})) EXPECT_EQ(got, expected);
}

TEST(TextureFormat, R32fReadsAsRed111) {
  const Texture t = r32f_2d(2, 1, {-3.5f, 1e30f});
  EXPECT_EQ(t.load(0, 0), glm::vec4(-3.5f, 1, 1, 1));
  for (const glm::vec4 got : both_paths(t, point_sampler(), {0.75f, 0.5f, 0})) {
    EXPECT_EQ(got, glm::vec4(1e30f, 1, 1, 1));
  }
}

// --- Filtering and addressing -----------------------------------------------------------------

TEST(TextureSampling, PointHitsTexelCenters) {
  std::mt19937 rng(1);
  for (const TextureFormat format : kFormats) {
    SCOPED_TRACE(name(format));
    Texture t2 = Texture::create_2d(7, 5, format);
    Texture tv = Texture::create_volume(3, 4, 5, format);
    Texture tc = Texture::create_cube(6, format);
    fill_random(t2, rng);
    fill_random(tv, rng);
    fill_random(tc, rng);
    for (const MipFilter mip : {MipFilter::Point, MipFilter::Linear}) {
      Sampler s = point_sampler();
      s.mip = mip;
      for (int level = 0; level < 2; ++level) {
        for (int y = 0; y < t2.height(level); ++y) {
          for (int x = 0; x < t2.width(level); ++x) {
            const glm::vec3 c((x + 0.5f) / t2.width(level), (y + 0.5f) / t2.height(level), 0);
            for (const glm::vec4 got : both_paths(t2, s, c, float(level)))
              EXPECT_EQ(got, t2.load(x, y, 0, level));
          }
        }
        for (int z = 0; z < tv.depth(level); ++z) {
          for (int y = 0; y < tv.height(level); ++y) {
            for (int x = 0; x < tv.width(level); ++x) {
              const glm::vec3 c((x + 0.5f) / tv.width(level), (y + 0.5f) / tv.height(level),
                                (z + 0.5f) / tv.depth(level));
              for (const glm::vec4 got : both_paths(tv, s, c, float(level)))
                EXPECT_EQ(got, tv.load(x, y, z, level));
            }
          }
        }
        const int n = tc.width(level);
        for (int face = 0; face < 6; ++face) {
          for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
              const glm::vec3 d = cube_direction(CubeFace(face), (x + 0.5f) / n, (y + 0.5f) / n);
              for (const glm::vec4 got : both_paths(tc, s, d, float(level)))
                EXPECT_EQ(got, tc.load(x, y, face, level));
            }
          }
        }
      }
    }
  }
}

TEST(TextureSampling, BilinearBetweenTexelsAverages) {
  std::mt19937 rng(2);
  for (const TextureFormat format : kFormats) {
    SCOPED_TRACE(name(format));
    Texture t = Texture::create_2d(4, 4, format, 1);
    fill_random(t, rng);
    Sampler s = linear_sampler(Address::Clamp);
    s.rules = SamplingRules::ideal;  // exact weights; TextureHardwareRules covers the hardware's
    for (int y = 0; y < 3; ++y) {
      for (int x = 0; x < 3; ++x) {
        // The corner shared by texels (x, y) .. (x+1, y+1): all four weigh 1/4.
        const glm::vec4 four =
            (t.load(x, y) + t.load(x + 1, y) + t.load(x, y + 1) + t.load(x + 1, y + 1)) * 0.25f;
        EXPECT_BOTH_NEAR(t, s, glm::vec3((x + 1) / 4.0f, (y + 1) / 4.0f, 0), 0.0f, four, 2e-6f);
        // Halfway between two texel centers along x, on a row's center line.
        const glm::vec4 two = (t.load(x, y) + t.load(x + 1, y)) * 0.5f;
        EXPECT_BOTH_NEAR(t, s, glm::vec3((x + 1) / 4.0f, (y + 0.5f) / 4.0f, 0), 0.0f, two, 2e-6f);
        // A quarter of the way: weights 3/4, 1/4.
        const glm::vec4 quarter = t.load(x, y) * 0.75f + t.load(x + 1, y) * 0.25f;
        EXPECT_BOTH_NEAR(t, s, glm::vec3((x + 0.75f) / 4.0f, (y + 0.5f) / 4.0f, 0), 0.0f, quarter, 2e-6f);
      }
    }
  }
}

TEST(TextureAddressing, KnownCoordinates) {
  const Texture t = r32f_2d(4, 1, {1, 2, 3, 4});
  auto red = [&](const Sampler& s, float u) {
    const auto r = both_paths(t, s, {u, 0.5f, 0});
    EXPECT_EQ(r[0].x, r[1].x) << "reference and SIMD differ at u = " << u;
    return r[1].x;
  };
  // Point.
  EXPECT_EQ(red(point_sampler(Address::Wrap), 1.125f), 1);
  EXPECT_EQ(red(point_sampler(Address::Wrap), -0.125f), 4);
  EXPECT_EQ(red(point_sampler(Address::Wrap), 2.875f), 4);
  EXPECT_EQ(red(point_sampler(Address::Wrap), 1000.375f), 2);
  EXPECT_EQ(red(point_sampler(Address::Mirror), 1.125f), 4);   // 2 - 1.125 = 0.875
  EXPECT_EQ(red(point_sampler(Address::Mirror), 1.875f), 1);   // 0.125
  EXPECT_EQ(red(point_sampler(Address::Mirror), -0.125f), 1);  // 0.125
  EXPECT_EQ(red(point_sampler(Address::Mirror), -1.375f), 3);  // 1.375 -> 0.625
  EXPECT_EQ(red(point_sampler(Address::Mirror), 2.125f), 1);
  EXPECT_EQ(red(point_sampler(Address::Clamp), 5.0f), 4);
  EXPECT_EQ(red(point_sampler(Address::Clamp), -3.0f), 1);
  Sampler border = point_sampler(Address::Border);
  border.border = {9, 8, 7, 6};
  EXPECT_EQ(red(border, 1.125f), 9);
  EXPECT_EQ(red(border, -0.125f), 9);
  EXPECT_EQ(red(border, 0.875f), 4);
  for (const glm::vec4 got : both_paths(t, border, {-0.5f, 0.5f, 0})) EXPECT_EQ(got, glm::vec4(9, 8, 7, 6));
  // Linear: the footprint's texels are addressed one by one.
  EXPECT_FLOAT_EQ(red(linear_sampler(Address::Wrap), 0.0f), 2.5f);  // texels 3 and 0
  EXPECT_FLOAT_EQ(red(linear_sampler(Address::Wrap), 1.0f), 2.5f);
  EXPECT_FLOAT_EQ(red(linear_sampler(Address::Mirror), 0.0f), 1.0f);  // texels -1 -> 0 and 0
  EXPECT_FLOAT_EQ(red(linear_sampler(Address::Mirror), 1.0f), 4.0f);
  EXPECT_FLOAT_EQ(red(linear_sampler(Address::Clamp), 0.0f), 1.0f);
  EXPECT_FLOAT_EQ(red(linear_sampler(Address::Clamp), 1.0f), 4.0f);
  Sampler linear_border = linear_sampler(Address::Border);
  linear_border.border = {9, 8, 7, 6};
  EXPECT_FLOAT_EQ(red(linear_border, 0.0f), 5.0f);     // (9 + 1) / 2
  EXPECT_FLOAT_EQ(red(linear_border, 1.0f), 6.5f);     // (4 + 9) / 2
  EXPECT_FLOAT_EQ(red(linear_border, 0.0625f), 3.0f);  // 3/4 of the way from border 9 to texel 1
  EXPECT_FLOAT_EQ(red(linear_border, -0.125f), 9.0f);
  // Far from the origin, wrap keeps sub-texel precision (the coordinate is reduced first).
  EXPECT_FLOAT_EQ(red(linear_sampler(Address::Wrap), 4096.25f), 1.5f);
  // NaN reads coordinate 0; infinity reads 0 under wrap/mirror and the edge under clamp.
  EXPECT_EQ(red(point_sampler(Address::Wrap), kNaN), 1);
  EXPECT_EQ(red(point_sampler(Address::Clamp), kNaN), 1);
  EXPECT_EQ(red(point_sampler(Address::Wrap), kInf), 1);
  EXPECT_EQ(red(point_sampler(Address::Mirror), -kInf), 1);
  EXPECT_EQ(red(point_sampler(Address::Clamp), kInf), 4);
  EXPECT_EQ(red(point_sampler(Address::Clamp), -kInf), 1);
}

TEST(TextureAddressing, PerAxisModes) {
  // 2x2: u wraps, v uses the border.
  const Texture t = r32f_2d(2, 2, {1, 2, 3, 4});
  Sampler s = point_sampler(Address::Wrap);
  s.v = Address::Border;
  s.border = glm::vec4(7);
  for (const glm::vec4 got : both_paths(t, s, {-0.25f, 0.25f, 0})) EXPECT_EQ(got.x, 2);  // wraps to texel 1
  for (const glm::vec4 got : both_paths(t, s, {0.25f, 1.25f, 0})) EXPECT_EQ(got.x, 7);   // below the bottom
  for (const glm::vec4 got : both_paths(t, s, {1.75f, 0.75f, 0})) EXPECT_EQ(got.x, 4);
  s.u = Address::Clamp;
  s.v = Address::Mirror;
  for (const glm::vec4 got : both_paths(t, s, {3.0f, 1.25f, 0}))
    EXPECT_EQ(got.x, 4);  // x clamps to 1, y mirrors to 1
  // Volumes address w too: slices 1, 2, 4, 8.
  Texture v = Texture::create_volume(1, 1, 4, TextureFormat::R32F, 1);
  const std::vector<float> slices = {1, 2, 4, 8};
  v.upload(0, std::span(reinterpret_cast<const uint8_t*>(slices.data()), 16));
  Sampler vs = point_sampler(Address::Wrap);
  for (const glm::vec4 got : both_paths(v, vs, {0.5f, 0.5f, 1.125f})) EXPECT_EQ(got.x, 1);
  vs.w = Address::Clamp;
  for (const glm::vec4 got : both_paths(v, vs, {0.5f, 0.5f, 1.125f})) EXPECT_EQ(got.x, 8);
}

TEST(TextureVolume, SamplesAcrossSlices) {
  Texture v = Texture::create_volume(1, 1, 4, TextureFormat::R32F, 1);
  const std::vector<float> slices = {1, 2, 4, 8};
  v.upload(0, std::span(reinterpret_cast<const uint8_t*>(slices.data()), 16));
  const Sampler wrap = linear_sampler(Address::Wrap), clamp = linear_sampler(Address::Clamp);
  for (int k = 0; k < 4; ++k)
    EXPECT_BOTH_NEAR(v, wrap, glm::vec3(0.5f, 0.5f, (k + 0.5f) / 4), 0.0f, glm::vec4(slices[k], 1, 1, 1),
                     0.0f);
  EXPECT_BOTH_NEAR(v, wrap, glm::vec3(0.5f, 0.5f, 0.5f), 0.0f, glm::vec4(3, 1, 1, 1), 1e-6f);  // slices 1, 2
  EXPECT_BOTH_NEAR(v, wrap, glm::vec3(0.5f, 0.5f, 0.0f), 0.0f, glm::vec4(4.5f, 1, 1, 1),
                   1e-6f);  // slices 3, 0
  EXPECT_BOTH_NEAR(v, clamp, glm::vec3(0.5f, 0.5f, 0.0f), 0.0f, glm::vec4(1, 1, 1, 1), 1e-6f);
  EXPECT_BOTH_NEAR(v, wrap, glm::vec3(0.5f, 0.5f, 0.3125f), 0.0f, glm::vec4(1.75f, 1, 1, 1),
                   1e-6f);  // 1/4 of 1 -> 2
  // Trilinear in space at the center of a 2x2x2 volume: the mean of all eight texels.
  Texture c = Texture::create_volume(2, 2, 2, TextureFormat::R32F, 1);
  const std::vector<float> eight = {1, 2, 3, 5, 7, 11, 13, 17};
  c.upload(0, std::span(reinterpret_cast<const uint8_t*>(eight.data()), 32));
  EXPECT_BOTH_NEAR(c, clamp, glm::vec3(0.5f), 0.0f, glm::vec4(59.0f / 8, 1, 1, 1), 1e-5f);
  // An upload remakes the trilinear cells Clamp reads: a quarter of the way from texel (0, 0, 0)
  // to (1, 1, 1), then past the far corner (texel (1, 1, 1) alone).
  const std::vector<float> other = {2, 4, 8, 16, 32, 64, 128, 256};
  c.upload(0, std::span(reinterpret_cast<const uint8_t*>(other.data()), 32));
  float quarter = 0;
  for (int t = 0; t < 8; ++t) quarter += other[size_t(t)] * (t & 1 ? 0.25f : 0.75f) * (t & 2 ? 0.25f : 0.75f) * (t & 4 ? 0.25f : 0.75f);
  EXPECT_BOTH_NEAR(c, clamp, glm::vec3(0.375f), 0.0f, glm::vec4(quarter, 1, 1, 1), 1e-5f);
  EXPECT_BOTH_NEAR(c, clamp, glm::vec3(1.5f), 0.0f, glm::vec4(256, 1, 1, 1), 0.0f);
}

// --- Mip generation ---------------------------------------------------------------------------

TEST(TextureMips, CheckerBecomesGrey) {
  // Black/white checker: level 1 is the average, 127.5 -> 128 (ties to even) in RGBA8 ...
  std::vector<uint8_t> checker(4 * 4 * 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const uint8_t v = (x + y) % 2 ? 255 : 0;
      uint8_t* p = checker.data() + (y * 4 + x) * 4;
      p[0] = p[1] = p[2] = v;
      p[3] = 255;
    }
  }
  Texture linear = Texture::create_2d(4, 4, TextureFormat::RGBA8);
  linear.upload(0, checker);
  linear.generate_mips();
  for (int level = 1; level < 3; ++level) {
    for (uint8_t b : linear.level_bytes(level)) EXPECT_TRUE(b == 128 || b == 255);
    EXPECT_EQ(linear.level_bytes(level)[0], 128);
    EXPECT_EQ(linear.level_bytes(level)[3], 255);
  }
  // ... and in sRGB the average is taken in linear space: 0.5 linear encodes to 188, not 128.
  Texture srgb = Texture::create_2d(4, 4, TextureFormat::RGBA8_sRGB);
  srgb.upload(0, checker);
  srgb.generate_mips();
  for (int level = 1; level < 3; ++level) {
    const auto b = srgb.level_bytes(level);
    for (size_t i = 0; i < b.size(); ++i)
      EXPECT_EQ(b[i], i % 4 == 3 ? 255 : 188) << "level " << level << " byte " << i;
  }
}

TEST(TextureMips, OddSizesUseTheAreaWeightedBox) {
  // 5 -> 2: texels (2/5, 2/5, 1/5) and (1/5, 2/5, 2/5); 2 -> 1: the mean.
  Texture t = r32f_2d(5, 1, {1, 2, 4, 8, 16}, 0);
  t.generate_mips();
  ASSERT_EQ(t.mip_levels(), 3);
  EXPECT_FLOAT_EQ(t.load(0, 0, 0, 1).x, 2.0f);   // (2*1 + 2*2 + 4) / 5
  EXPECT_FLOAT_EQ(t.load(1, 0, 0, 1).x, 10.4f);  // (4 + 2*8 + 2*16) / 5
  EXPECT_FLOAT_EQ(t.load(0, 0, 0, 2).x, 6.2f);
  // 3x3 -> 1x1: the mean of nine.
  Texture nine = r32f_2d(3, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9}, 0);
  nine.generate_mips();
  EXPECT_FLOAT_EQ(nine.load(0, 0, 0, 1).x, 5.0f);
}

TEST(TextureMips, EveryLevelKeepsTheMean) {
  // The exact box filter conserves the mean for any size (odd, even, 1) and any kind.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  const std::array<std::array<int, 3>, 6> sizes = {
      {{13, 7, 1}, {5, 1, 1}, {1, 9, 1}, {6, 10, 1}, {7, 3, 5}, {2, 5, 3}}};
  for (const auto& size : sizes) {
    const bool volume = size[2] > 1;
    Texture t = volume ? Texture::create_volume(size[0], size[1], size[2], TextureFormat::R32F)
                       : Texture::create_2d(size[0], size[1], TextureFormat::R32F);
    std::vector<glm::vec4> texels(size_t(size[0]) * size[1] * size[2]);
    double sum = 0;
    for (auto& x : texels) {
      x = glm::vec4(value(rng));
      sum += x.x;
    }
    t.upload(0, texels);
    t.generate_mips();
    const double mean = sum / texels.size();
    for (int level = 1; level < t.mip_levels(); ++level) {
      double level_sum = 0;
      for (int z = 0; z < t.depth(level); ++z)
        for (int y = 0; y < t.height(level); ++y)
          for (int x = 0; x < t.width(level); ++x) level_sum += t.load(x, y, z, level).x;
      EXPECT_NEAR(level_sum / (t.width(level) * t.height(level) * t.depth(level)), mean, 1e-5)
          << size[0] << "x" << size[1] << "x" << size[2] << " level " << level;
    }
  }
}

TEST(TextureMips, VolumeAndCubeLevels) {
  Texture v = Texture::create_volume(2, 2, 2, TextureFormat::RGBA16F);
  const std::vector<glm::vec4> eight = {glm::vec4(1), glm::vec4(2),  glm::vec4(3),  glm::vec4(5),
                                        glm::vec4(7), glm::vec4(11), glm::vec4(13), glm::vec4(17)};
  v.upload(0, eight);
  v.generate_mips();
  EXPECT_EQ(v.load(0, 0, 0, 1), glm::vec4(7.375f));  // 59 / 8, exact in half
  // Cube faces are filtered on their own: a constant face stays constant.
  Texture c = Texture::create_cube(4, TextureFormat::RGBA16);
  for (int face = 0; face < 6; ++face) c.upload(0, std::vector<glm::vec4>(16, glm::vec4(face / 8.0f)), face);
  c.generate_mips();
  for (int face = 0; face < 6; ++face) {
    for (int level = 1; level < 3; ++level) EXPECT_EQ(c.load(0, 0, face, level), c.load(0, 0, face, 0));
  }
}

// --- Level of detail --------------------------------------------------------------------------

/// compute_lod on one set of derivatives (all lanes alike), lane 0.
float simd_lod(const Texture& t, glm::vec3 c, glm::vec3 dx, glm::vec3 dy) {
  auto tc = [](glm::vec3 v) { return TexCoord{simd::Float(v.x), simd::Float(v.y), simd::Float(v.z)}; };
  LaneValues out;
  compute_lod(t, tc(c), tc(dx), tc(dy)).store_unaligned(out.data());
  return out[0];
}

TEST(TextureLod, FromKnownDerivatives) {
  const Texture t = Texture::create_2d(256, 128, TextureFormat::RGBA8);
  struct Case {
    glm::vec3 dx, dy;
    float lod;
  };
  const Case cases_2d[] = {
      {{1 / 256.0f, 0, 0}, {0, 1 / 128.0f, 0}, 0.0f},
      {{2 / 256.0f, 0, 0}, {0, 1 / 128.0f, 0}, 1.0f},  // scale by 2 -> LOD 1
      {{4 / 256.0f, 0, 0}, {0, 1 / 128.0f, 0}, 2.0f},  // isotropic: the larger axis wins
      {{0, 0, 0}, {0, 8 / 128.0f, 0}, 3.0f},
      {{3 / 256.0f, 4 / 128.0f, 0}, {0, 0, 0}, std::log2(5.0f)},
      {{0.5f / 256, 0, 0}, {0, 0.5f / 128, 0}, -1.0f},
  };
  for (const Case& c : cases_2d) {
    EXPECT_NEAR(lod_reference(t, {0.3f, 0.6f, 0}, c.dx, c.dy), c.lod, 1e-6);
    EXPECT_NEAR(simd_lod(t, {0.3f, 0.6f, 0}, c.dx, c.dy), c.lod, 1e-6);
  }
  const Texture v = Texture::create_volume(16, 16, 64, TextureFormat::R32F);
  EXPECT_NEAR(lod_reference(v, {0.5f, 0.5f, 0.5f}, {0, 0, 8 / 64.0f}, {1 / 16.0f, 0, 0}), 3.0f, 1e-6);
  EXPECT_NEAR(simd_lod(v, {0.5f, 0.5f, 0.5f}, {0, 0, 8 / 64.0f}, {1 / 16.0f, 0, 0}), 3.0f, 1e-6);
  // Cube, 64 texels a face: at the center of +Z, u = (x/z + 1)/2, so dx = 2/64 is one texel.
  const Texture c = Texture::create_cube(64, TextureFormat::RGBA16F);
  const Case cube_cases[] = {
      {{2 / 64.0f, 0, 0}, {0, 2 / 64.0f, 0}, 0.0f},
      {{8 / 64.0f, 0, 0}, {0, 0, 0}, 2.0f},
  };
  for (const Case& k : cube_cases) {
    EXPECT_NEAR(lod_reference(c, {0, 0, 1}, k.dx, k.dy), k.lod, 1e-6);
    EXPECT_NEAR(simd_lod(c, {0, 0, 1}, k.dx, k.dy), k.lod, 1e-6);
    // The same on every face, and for an unnormalized direction scaled with its derivatives.
    EXPECT_NEAR(lod_reference(c, {0, 0, -3}, 3.0f * k.dx, 3.0f * k.dy), k.lod, 1e-6);
    EXPECT_NEAR(simd_lod(c, {0, 0, -3}, 3.0f * k.dx, 3.0f * k.dy), k.lod, 1e-6);
  }
  // Off center, moving along the major axis moves u too: at (0.5, 0, 1), d/dz of x/z is -0.5,
  // so du = 0.25 dz, i.e. 16 dz texels; dz = 1/16 is one texel.
  EXPECT_NEAR(lod_reference(c, {0.5f, 0, 1}, {0, 0, 1 / 16.0f}, {0, 0, 0}), 0.0f, 1e-6);
  EXPECT_NEAR(simd_lod(c, {0.5f, 0, 1}, {0, 0, 1 / 16.0f}, {0, 0, 0}), 0.0f, 1e-6);
}

TEST(TextureLod, SelectsLevels) {
  // An 8x8 R32F texture whose levels are constant: 1, 2, 4, 8.
  Texture t = Texture::create_2d(8, 8, TextureFormat::R32F);
  for (int level = 0; level < 4; ++level) {
    const int n = t.width(level);
    t.upload(level, std::vector<glm::vec4>(size_t(n) * n, glm::vec4(float(1 << level))));
  }
  const glm::vec3 c(0.3f, 0.7f, 0);
  auto red = [&](const Sampler& s, float lod) {
    const auto r = both_paths(t, s, c, lod);
    EXPECT_NEAR(r[0].x, r[1].x, 1e-6f) << "lod " << lod;
    return r[1].x;
  };
  Sampler s = linear_sampler();
  s.mip = MipFilter::None;
  EXPECT_EQ(red(s, 2.0f), 1.0f);
  s.mip = MipFilter::Point;
  EXPECT_EQ(red(s, -5.0f), 1.0f);
  EXPECT_EQ(red(s, 0.49f), 1.0f);
  EXPECT_EQ(red(s, 0.5f), 2.0f);  // a tie goes to the coarser level
  EXPECT_EQ(red(s, 1.4f), 2.0f);
  EXPECT_EQ(red(s, 2.6f), 8.0f);
  EXPECT_EQ(red(s, 10.0f), 8.0f);
  EXPECT_EQ(red(s, kNaN), 1.0f);  // NaN counts as 0
  s.mip = MipFilter::Linear;
  EXPECT_FLOAT_EQ(red(s, 0.25f), 1.25f);
  EXPECT_FLOAT_EQ(red(s, 1.5f), 3.0f);
  EXPECT_FLOAT_EQ(red(s, 2.75f), 7.0f);
  EXPECT_FLOAT_EQ(red(s, 5.0f), 8.0f);
  s.lod_bias = 1.0f;
  EXPECT_FLOAT_EQ(red(s, 0.0f), 2.0f);
  s.lod_bias = 0.0f;
  s.min_lod = 1.0f;
  EXPECT_FLOAT_EQ(red(s, 0.0f), 2.0f);
  s.min_lod = 0.0f;
  s.max_lod = 1.5f;
  EXPECT_FLOAT_EQ(red(s, 3.0f), 3.0f);
}

TEST(TextureLod, MagnifiesUpToZero) {
  // 2x1 texels 0, 1; at u = 0.5 point reads texel 1, linear the average.
  Texture t = Texture::create_2d(2, 1, TextureFormat::R32F);
  t.upload(0, std::vector<glm::vec4>{glm::vec4(0), glm::vec4(1)});
  Sampler s;
  s.mag = Filter::Point;
  s.min = Filter::Linear;
  s.mip = MipFilter::None;
  for (const glm::vec4 got : both_paths(t, s, {0.5f, 0.5f, 0}, 0.0f)) EXPECT_EQ(got.x, 1.0f);
  for (const glm::vec4 got : both_paths(t, s, {0.5f, 0.5f, 0}, -3.0f)) EXPECT_EQ(got.x, 1.0f);
  for (const glm::vec4 got : both_paths(t, s, {0.5f, 0.5f, 0}, 0.01f)) EXPECT_EQ(got.x, 0.5f);
  std::swap(s.mag, s.min);
  for (const glm::vec4 got : both_paths(t, s, {0.5f, 0.5f, 0}, 0.0f)) EXPECT_EQ(got.x, 0.5f);
  for (const glm::vec4 got : both_paths(t, s, {0.5f, 0.5f, 0}, 0.01f)) EXPECT_EQ(got.x, 1.0f);
}

TEST(TextureLod, ImplicitFromQuadDerivatives) {
  // A stamp whose u grows by 2 texels per pixel in x (64 texels wide) and v by 1 in y: LOD 1.
  std::mt19937 rng(4);
  Texture t = Texture::create_2d(64, 64, TextureFormat::RGBA8);
  fill_random(t, rng);
  LaneValues u, v;
  for (int l = 0; l < kLanes; ++l) {
    u[l] = 0.1f + (simd::lane_x(l) + 0.5f) * (2 / 64.0f);
    v[l] = 0.2f + (simd::lane_y(l) + 0.5f) * (1 / 64.0f);
  }
  const TexCoord c{lanes_of(u), lanes_of(v), simd::Float(0.0f)};
  const Sampler s;  // trilinear
  LaneValues lod;
  compute_lod(t, c, {simd::ddx(c.x), simd::ddx(c.y), simd::Float(0)},
              {simd::ddy(c.x), simd::ddy(c.y), simd::Float(0)})
      .store_unaligned(lod.data());
  for (float l : lod) EXPECT_NEAR(l, 1.0f, 1e-6f);
  for (const float bias : {0.0f, 0.5f, -2.0f}) {
    const auto implicit = unpack(sample(t, s, c, simd::Float(bias)));
    const auto explicit_lod = unpack(sample_level(t, s, c, lanes_of(lod) + simd::Float(bias)));
    for (int l = 0; l < kLanes; ++l) {
      EXPECT_EQ(implicit[l], explicit_lod[l]) << "lane " << l << " bias " << bias;
      const glm::vec4 ref = sample_reference(t, s, {u[l], v[l], 0}, 1.0f + bias);
      for (int ch = 0; ch < 4; ++ch) EXPECT_NEAR(implicit[l][ch], ref[ch], 1e-5f);
    }
  }
}

TEST(TextureLod, OneFilterWithoutMipsReadsTheSameAtAnyLod) {
  // sample() skips the LOD for such a sampler: it must equal level 0 at any derivatives and bias.
  std::mt19937 rng(9);
  Texture t = Texture::create_2d(64, 64, TextureFormat::RGBA8);
  fill_random(t, rng);
  LaneValues u, v;
  for (int l = 0; l < kLanes; ++l) {
    u[l] = 0.1f + (simd::lane_x(l) + 0.5f) * (9 / 64.0f);  // minified: LOD about 3
    v[l] = 0.2f + (simd::lane_y(l) + 0.5f) * (0.3f / 64.0f);
  }
  const TexCoord c{lanes_of(u), lanes_of(v), simd::Float(0.0f)};
  for (const Filter f : {Filter::Point, Filter::Linear}) {
    Sampler s;
    s.min = s.mag = f;
    s.mip = MipFilter::None;
    const auto level0 = unpack(sample_level(t, s, c, simd::Float(0.0f)));
    for (const float bias : {0.0f, 4.0f, -3.0f, std::numeric_limits<float>::quiet_NaN()}) {
      const auto implicit = unpack(sample(t, s, c, simd::Float(bias)));
      for (int l = 0; l < kLanes; ++l) EXPECT_EQ(implicit[l], level0[l]) << "lane " << l << " bias " << bias;
    }
  }
}

// --- Cube maps --------------------------------------------------------------------------------

/// A cube whose texel (face, x, y) holds the number face * n * n + y * n + x (R32F, exact).
Texture numbered_cube(int n) {
  Texture t = Texture::create_cube(n, TextureFormat::R32F, 1);
  for (int face = 0; face < 6; ++face) {
    std::vector<glm::vec4> texels;
    for (int i = 0; i < n * n; ++i) texels.emplace_back(float(face * n * n + i));
    t.upload(0, texels, face);
  }
  return t;
}

TEST(TextureCube, FaceSelectionAndOrientation) {
  struct Case {
    glm::vec3 dir;
    CubeFace face;
    float u, v;
  };
  // From D3D's cube-map table: +X (sc, tc) = (-z, -y), -X (z, -y), +Y (x, z), -Y (x, -z),
  // +Z (x, -y), -Z (-x, -y); u = (sc/|ma| + 1)/2, v = (tc/|ma| + 1)/2.
  const Case cases[] = {
      {{1, 0, 0}, CubeFace::PositiveX, 0.5f, 0.5f},
      {{-1, 0, 0}, CubeFace::NegativeX, 0.5f, 0.5f},
      {{0, 1, 0}, CubeFace::PositiveY, 0.5f, 0.5f},
      {{0, -1, 0}, CubeFace::NegativeY, 0.5f, 0.5f},
      {{0, 0, 1}, CubeFace::PositiveZ, 0.5f, 0.5f},
      {{0, 0, -1}, CubeFace::NegativeZ, 0.5f, 0.5f},
      {{1, 0.5f, -0.5f}, CubeFace::PositiveX, 0.75f, 0.25f},
      {{2, 1, -1}, CubeFace::PositiveX, 0.75f, 0.25f},  // scale does not matter
      {{-1, 0.5f, -0.5f}, CubeFace::NegativeX, 0.25f, 0.25f},
      {{0.5f, 1, -0.5f}, CubeFace::PositiveY, 0.75f, 0.25f},
      {{0.5f, -1, -0.5f}, CubeFace::NegativeY, 0.75f, 0.75f},
      {{0.5f, 0.5f, 1}, CubeFace::PositiveZ, 0.75f, 0.25f},
      {{0.5f, 0.5f, -1}, CubeFace::NegativeZ, 0.25f, 0.25f},
      // Ties: z over y over x; zero counts as positive; the zero vector reads +Z's center.
      {{1, 1, 0}, CubeFace::PositiveY, 1.0f, 0.5f},
      {{1, -1, 0}, CubeFace::NegativeY, 1.0f, 0.5f},
      {{1, 0, 1}, CubeFace::PositiveZ, 1.0f, 0.5f},
      {{0, -1, 1}, CubeFace::PositiveZ, 0.5f, 1.0f},
      {{1, 1, 1}, CubeFace::PositiveZ, 1.0f, 0.0f},
      {{-1, -1, -1}, CubeFace::NegativeZ, 1.0f, 1.0f},
      {{0, 0, 0}, CubeFace::PositiveZ, 0.5f, 0.5f},
      {{-0.0f, 0.0f, -0.0f}, CubeFace::PositiveZ, 0.5f, 0.5f},
  };
  const int n = 4;
  const Texture numbered = numbered_cube(n);
  const Sampler s = point_sampler();
  for (const Case& c : cases) {
    const CubeFaceCoord got = cube_face(c.dir);
    EXPECT_EQ(got.face, c.face) << c.dir.x << " " << c.dir.y << " " << c.dir.z;
    EXPECT_EQ(got.u, c.u);
    EXPECT_EQ(got.v, c.v);
    // Both sampling paths read the texel of that face and position.
    const int x = std::min(int(c.u * n), n - 1), y = std::min(int(c.v * n), n - 1);
    const float expected = float(int(c.face) * n * n + y * n + x);
    for (const glm::vec4 r : both_paths(numbered, s, c.dir)) EXPECT_EQ(r.x, expected);
    // cube_direction inverts cube_face.
    const glm::vec3 back = cube_direction(got.face, got.u, got.v);
    if (c.dir != glm::vec3(0)) {
      const CubeFaceCoord again = cube_face(back);
      EXPECT_EQ(again.face, got.face);
      EXPECT_FLOAT_EQ(again.u, got.u);
      EXPECT_FLOAT_EQ(again.v, got.v);
    }
  }
}

TEST(TextureCube, SeamlessAcrossEdgesAndCorners) {
  // Each face constant (face + 1). On an edge, bilinear reads half of each face; at a corner,
  // 1/4 each of three faces plus their mean for the missing texel: the mean of the three.
  for (const int n : {1, 2, 4, 7}) {
    SCOPED_TRACE(n);
    Texture t = Texture::create_cube(n, TextureFormat::RGBA16F, 1);
    for (int face = 0; face < 6; ++face) {
      t.upload(0, std::vector<glm::vec4>(size_t(n) * n, glm::vec4(float(face + 1))), face);
    }
    auto value = [](int axis, float sign) { return float(2 * axis + (sign < 0 ? 1 : 0) + 1); };
    const Sampler s = linear_sampler();
    for (int a = 0; a < 3; ++a) {
      for (int b = a + 1; b < 3; ++b) {
        const int c = 3 - a - b;
        for (const float sa : {-1.0f, 1.0f}) {
          for (const float sb : {-1.0f, 1.0f}) {
            glm::vec3 d(0);
            d[a] = sa;
            d[b] = sb;
            d[c] = 0.3f;  // anywhere along the edge
            // (A 1x1 face has no texel row of its own along the edge: its footprint also reaches
            // the faces across the other edges, so only corners have a closed form there.)
            const float edge = (value(a, sa) + value(b, sb)) / 2;
            if (n > 1) EXPECT_BOTH_NEAR(t, s, d, 0.0f, glm::vec4(edge), 1e-6f);
            for (const float sc : {-1.0f, 1.0f}) {
              d[c] = sc;
              const float corner = (value(a, sa) + value(b, sb) + value(c, sc)) / 3;
              EXPECT_BOTH_NEAR(t, s, d, 0.0f, glm::vec4(corner), 1e-6f);
            }
          }
        }
      }
    }
  }
}

TEST(TextureCube, SeamlessFilteringIsSmooth) {
  // Texels hold f(direction of the texel center), f linear in the unit direction. Seamless
  // bilinear filtering reproduces f closely even next to edges and corners: within a face the
  // error is second order (~4e-4 here), across an edge first order, as the texel grid bends
  // there (measured 3.1e-3 at n = 32, halving as n doubles). Clamping at each face's edge instead
  // gives 6.4e-3; a texel from the wrong neighbour, or a flipped edge, is off by ~0.1.
  const int n = 32;
  Texture t = Texture::create_cube(n, TextureFormat::R32F, 1);
  auto f = [](glm::vec3 d) {
    d = glm::normalize(d);
    return 0.5f + 0.3f * d.x - 0.2f * d.y + 0.25f * d.z;
  };
  for (int face = 0; face < 6; ++face) {
    std::vector<glm::vec4> texels;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        texels.emplace_back(f(cube_direction(CubeFace(face), (x + 0.5f) / n, (y + 0.5f) / n)));
    t.upload(0, texels, face);
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> along(0.0f, 1.0f), near_edge(0.0f, 1.0f / n);
  std::uniform_int_distribution<int> pick(0, 5);
  const Sampler s = linear_sampler();
  float worst = 0;
  for (int i = 0; i < 3000; ++i) {
    const CubeFace face = CubeFace(pick(rng));
    float u = along(rng), v = along(rng);
    // Push one or both coordinates within a texel of an edge.
    if (i % 3 != 2) u = (i & 1) ? near_edge(rng) : 1 - near_edge(rng);
    if (i % 3 != 0) v = (i & 2) ? near_edge(rng) : 1 - near_edge(rng);
    const glm::vec3 d = cube_direction(face, u, v);
    for (const glm::vec4 got : both_paths(t, s, d)) worst = std::max(worst, std::fabs(got.x - f(d)));
  }
  EXPECT_LT(worst, 4e-3f);
}

// --- SIMD against the reference ---------------------------------------------------------------

struct TestTexture {
  Texture texture;
  std::string label;
};

std::vector<TestTexture> random_textures(TextureFormat format, std::mt19937& rng) {
  std::vector<TestTexture> out;
  auto add = [&](Texture t, std::string label) {
    fill_random(t, rng);
    out.push_back({std::move(t), std::move(label) + " " + name(format)});
  };
  add(Texture::create_2d(13, 7, format), "2D 13x7");
  add(Texture::create_2d(32, 8, format, 3), "2D 32x8 (3 levels)");
  add(Texture::create_2d(1, 1, format), "2D 1x1");
  add(Texture::create_2d(6, 33, format), "2D 6x33");
  add(Texture::create_volume(5, 3, 6, format), "volume 5x3x6");
  add(Texture::create_volume(4, 4, 4, format, 2), "volume 4x4x4 (2 levels)");
  add(Texture::create_volume(1, 2, 9, format), "volume 1x2x9");
  // One level: a one-word format's volume keeps trilinear cells, which Clamp reads.
  add(Texture::create_volume(7, 5, 4, format, 1), "volume 7x5x4 (1 level)");
  add(Texture::create_volume(1, 3, 2, format, 1), "volume 1x3x2 (1 level)");
  add(Texture::create_cube(9, format), "cube 9");
  add(Texture::create_cube(1, format), "cube 1");
  add(Texture::create_cube(16, format, 3), "cube 16 (3 levels)");
  return out;
}

/// Random coordinates with a share of exact texel centers and edges, face edges and corners,
/// axis ties, and non-finite values.
glm::vec3 random_coord(const Texture& t, std::mt19937& rng) {
  std::uniform_real_distribution<float> wide(-3.0f, 4.0f), unit(0.0f, 1.0f);
  std::uniform_int_distribution<int> kind(0, 99), small(-20, 20);
  const int k = kind(rng);
  if (t.kind() == TextureKind::Cube) {
    if (k < 40) return {wide(rng) - 0.5f, wide(rng) - 0.5f, wide(rng) - 0.5f};
    if (k < 80) {  // on or near a face edge / corner
      const float u = k % 2 ? unit(rng) : (k % 4 < 2 ? 0.0f : 1.0f) + (unit(rng) - 0.5f) * 0.02f * (k % 3);
      const float v =
          k % 5 < 2 ? unit(rng) : (k % 4 == 1 ? 1.0f : 0.0f) + (unit(rng) - 0.5f) * 0.02f * (k % 3);
      return cube_direction(CubeFace(k % 6), std::clamp(u, 0.0f, 1.0f), std::clamp(v, 0.0f, 1.0f)) *
             (0.5f + unit(rng));
    }
    if (k < 95) {  // ties between axes
      glm::vec3 d(small(rng) / 4.0f, small(rng) / 4.0f, small(rng) / 4.0f);
      d[k % 3] = (k % 2 ? 1.0f : -1.0f) * std::fabs(d[(k + 1) % 3]);
      return d;
    }
    return {k % 2 ? kNaN : kInf, 1.0f, k % 3 ? 0.0f : -kInf};
  }
  glm::vec3 c(wide(rng), wide(rng), wide(rng));
  if (k < 30) {  // texel centers and edges of some level
    const int level = std::uniform_int_distribution<int>(0, t.mip_levels() - 1)(rng);
    const float size[3] = {float(t.width(level)), float(t.height(level)), float(t.depth(level))};
    for (int a = 0; a < 3; ++a) c[a] = (small(rng) + (k % 2 ? 0.5f : 0.0f)) / size[a];
  } else if (k < 33) {
    c[k % 3] = k == 30 ? kNaN : k == 31 ? kInf : -kInf;
  } else if (k < 36) {
    c[k % 3] = (k % 2 ? 1.0f : -1.0f) * 3.0e6f * unit(rng);  // far from the origin
  }
  return c;
}

float random_lod(const Texture& t, std::mt19937& rng) {
  std::uniform_real_distribution<float> lod(-2.0f, float(t.mip_levels()) + 1.0f);
  std::uniform_int_distribution<int> kind(0, 99);
  const int k = kind(rng);
  if (k < 10) return std::floor(lod(rng));
  if (k < 20) return std::floor(lod(rng)) + 0.5f;
  if (k == 20) return kNaN;
  if (k == 21) return kInf;
  return lod(rng);
}

std::vector<Sampler> sampler_configs(TextureKind kind, std::mt19937& rng) {
  std::vector<Sampler> out;
  std::vector<std::array<Address, 3>> addressing;
  if (kind == TextureKind::Cube) {
    addressing.push_back({Address::Wrap, Address::Wrap, Address::Wrap});
  } else {
    for (const Address a : {Address::Wrap, Address::Mirror, Address::Clamp, Address::Border})
      addressing.push_back({a, a, a});
    std::uniform_int_distribution<int> any(0, 3);
    for (int i = 0; i < 2; ++i)
      addressing.push_back({Address(any(rng)), Address(any(rng)), Address(any(rng))});
  }
  std::uniform_real_distribution<float> color(-0.5f, 1.5f);
  for (const auto& a : addressing) {
    for (const Filter mag : {Filter::Point, Filter::Linear}) {
      for (const Filter min : {Filter::Point, Filter::Linear}) {
        for (const MipFilter mip : {MipFilter::None, MipFilter::Point, MipFilter::Linear}) {
          Sampler s;
          s.mag = mag;
          s.min = min;
          s.mip = mip;
          s.u = a[0];
          s.v = a[1];
          s.w = a[2];
          s.border = {color(rng), color(rng), color(rng), color(rng)};
          out.push_back(s);
        }
      }
    }
  }
  // Bias and clamps.
  Sampler biased;
  biased.lod_bias = 0.75f;
  biased.min_lod = 0.5f;
  biased.max_lod = 1.25f;
  out.push_back(biased);
  return out;
}

/// Calls fn(texture, sampler) for every format's random textures and each texture's sampler
/// configurations, drawing both from `rng` in that order.
template <class Fn>
void for_each_texture_and_sampler(std::mt19937& rng, Fn&& fn) {
  for (const TextureFormat format : kFormats)
    for (const TestTexture& tt : random_textures(format, rng))
      for (const Sampler& s : sampler_configs(tt.texture.kind(), rng)) fn(tt, s);
}

std::string describe(const Sampler& s) {
  std::ostringstream o;
  o << "mag " << name(s.mag) << ", min " << name(s.min) << ", mip " << name(s.mip) << ", address "
    << name(s.u) << "/" << name(s.v) << "/" << name(s.w) << ", bias " << s.lod_bias;
  return o.str();
}

// Tolerance of SIMD against reference. Both pick the same texels and weights (same float32
// coordinate arithmetic); what differs is filtering in float32 with FMA lerps (UNORM channels on
// their 0..2^n-1 scale, then one division) against double. On texel values of magnitude <= 2 that
// is a few float32 roundings (ulp(2) = 2.4e-7): 1e-6 allows ~4. A wrong texel or weight is off by
// >= 1e-3.
constexpr float kSimdTolerance = 1e-6f;

// Under the hardware rules the two paths do the same fixed-point and float32 steps: they must
// agree to the bit. Under the ideal rules the reference filters in double.
TEST(TextureSimd, MatchesReference) {
  std::mt19937 rng(6);
  constexpr int kStampsPerConfig = 48;
  long compared = 0, configs = 0;
  float worst = 0;
  for_each_texture_and_sampler(rng, [&](const TestTexture& tt, const Sampler& any_rules) {
    if (HasFatalFailure()) return;
    const Texture& t = tt.texture;
    Sampler s = any_rules;
    s.rules = configs++ % 2 ? SamplingRules::ideal : SamplingRules::hardware;
    const float tolerance = s.rules == SamplingRules::hardware ? 0.0f : kSimdTolerance;
    int failures = 0;
    for (int stamp = 0; stamp < kStampsPerConfig; ++stamp) {
      std::array<glm::vec3, kLanes> coord;
      LaneValues x, y, z, lod;
      for (int l = 0; l < kLanes; ++l) {
        coord[l] = random_coord(t, rng);
        x[l] = coord[l].x;
        y[l] = coord[l].y;
        z[l] = coord[l].z;
        // Half the stamps share one LOD per quad, as implicit LODs do.
        lod[l] = stamp % 2 && l % 4 ? lod[l - l % 4] : random_lod(t, rng);
      }
      const auto got = unpack(sample_level(t, s, {lanes_of(x), lanes_of(y), lanes_of(z)}, lanes_of(lod)));
      for (int l = 0; l < kLanes; ++l) {
        const glm::vec4 want = sample_reference(t, s, coord[l], lod[l]);
        ++compared;
        for (int ch = 0; ch < 4; ++ch) {
          const float error = std::fabs(got[l][ch] - want[ch]);
          worst = std::max(worst, error);
          const bool same_nan = std::isnan(got[l][ch]) && std::isnan(want[ch]);
          if (!(error <= tolerance) && !(same_nan && s.rules == SamplingRules::hardware) && failures++ < 3) {
            ADD_FAILURE() << tt.label << ", " << describe(s) << ": coord (" << coord[l].x << ", "
                          << coord[l].y << ", " << coord[l].z << ") lod " << lod[l] << " channel " << ch
                          << ": SIMD " << got[l][ch] << ", reference " << want[ch];
          }
        }
      }
    }
  });
  RecordProperty("samples", std::to_string(compared));
  RecordProperty("worst_error", std::to_string(worst));
  std::printf("[          ] %ld samples, worst |SIMD - reference| = %g\n", compared, worst);
}

// A sampler without mips and with one filter on both sides of the crossover has its own path
// (texture_sample_impl.hpp, sample_one_level_impl). It must read the very bits the general path reads
// with the same filter: reached there through a sampler whose other filter no lane uses (all
// lanes magnified at LOD -1, all minified at LOD +1; without mips level 0 either way).
TEST(TextureSimd, OneLevelPathReadsWhatTheGeneralPathReads) {
  std::mt19937 rng(13);
  long compared = 0;
  for_each_texture_and_sampler(rng, [&](const TestTexture& tt, const Sampler& s) {
    if (HasFatalFailure()) return;
    const Texture& t = tt.texture;
    if (s.mip != MipFilter::None || s.min != s.mag) return;
    const Filter f = s.mag, other = f == Filter::Point ? Filter::Linear : Filter::Point;
    Sampler magnified = s, minified = s;
    magnified.min = other;
    minified.mag = other;
    for (int stamp = 0; stamp < 8; ++stamp) {
      LaneValues x, y, z;
      for (int l = 0; l < kLanes; ++l) {
        const glm::vec3 c = random_coord(t, rng);
        x[l] = c.x, y[l] = c.y, z[l] = c.z;
      }
      const TexCoord c{lanes_of(x), lanes_of(y), lanes_of(z)};
      const auto one_level = unpack(sample_level(t, s, c, simd::Float(0.0f)));
      const auto general_mag = unpack(sample_level(t, magnified, c, simd::Float(-1.0f)));
      const auto general_min = unpack(sample_level(t, minified, c, simd::Float(1.0f)));
      for (int l = 0; l < kLanes; ++l) {
        for (int ch = 0; ch < 4; ++ch) {
          ++compared;
          ASSERT_EQ(std::bit_cast<uint32_t>(one_level[l][ch]), std::bit_cast<uint32_t>(general_mag[l][ch]))
              << tt.label << ", " << describe(s) << ", lane " << l << " channel " << ch;
          ASSERT_EQ(std::bit_cast<uint32_t>(one_level[l][ch]), std::bit_cast<uint32_t>(general_min[l][ch]))
              << tt.label << ", " << describe(s) << ", lane " << l << " channel " << ch;
        }
      }
    }
  });
  EXPECT_GT(compared, 10000);
}

// A trilinear read of a volume's cells reads a cell once when every lane's footprint lies in it
// (texture_filters.hpp, filter_volume_cells): the same bits as the general path, which reads each
// lane's eight texels one by one; for stamps inside one cell (edge cells, past the edges and
// inside), and for stamps with one lane in the next cell along each axis.
TEST(TextureSimd, OneCellStampsReadWhatTheGeneralPathReads) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> within(0.0f, 1.0f);
  long compared = 0;
  for (const TextureFormat format : {TextureFormat::RGBA8, TextureFormat::RGBA8_sRGB, TextureFormat::R32F}) {
    Texture t = Texture::create_volume(6, 5, 4, format, 1);
    fill_random(t, rng);
    const Sampler s = linear_sampler(Address::Clamp);
    Sampler general = s;  // the general path: a second filter that no lane uses (see above)
    general.min = Filter::Point;
    const int size[3] = {t.width(), t.height(), t.depth()};
    for (int stamp = 0; stamp < 200; ++stamp) {
      // The cell: footprints starting at texel c along each axis, c in [-1, n - 1]; the first
      // and the last read the edge texel twice (Clamp). Footprint start c covers coordinates
      // [(c + 0.5) / n, (c + 1.5) / n).
      int cell[3];
      for (int a = 0; a < 3; ++a) cell[a] = std::uniform_int_distribution<int>(-1, size[a] - 1)(rng);
      const int odd_axis = stamp % 4 - 1;  // -1: every lane in the cell; else one lane in the next along this axis
      LaneValues c[3];
      for (int l = 0; l < kLanes; ++l)
        for (int a = 0; a < 3; ++a) {
          const int start = cell[a] + (a == odd_axis && l == kLanes - 1 ? 1 : 0);
          c[a][size_t(l)] = (float(start) + 0.5f + within(rng)) / float(size[a]);
        }
      const TexCoord coord{lanes_of(c[0]), lanes_of(c[1]), lanes_of(c[2])};
      const auto cells = unpack(sample_level(t, s, coord, simd::Float(0.0f)));
      const auto texels = unpack(sample_level(t, general, coord, simd::Float(-1.0f)));
      for (int l = 0; l < kLanes; ++l)
        for (int ch = 0; ch < 4; ++ch, ++compared)
          ASSERT_EQ(std::bit_cast<uint32_t>(cells[l][ch]), std::bit_cast<uint32_t>(texels[l][ch]))
              << name(format) << ", stamp " << stamp << ", lane " << l << " channel " << ch;
    }
  }
  EXPECT_EQ(compared, 3L * 200 * kLanes * 4);
}

// The one-level bilinear path reads only the first texel along an axis where every lane's weight
// along it is 0 (texture_filters.hpp, filter_2d): a post pass's blur taps along one axis at the
// other's texel centers. The same bits as the general path, which always reads all four, whatever
// the format, addressing and the lanes' mix of centers and not.
TEST(TextureSimd, OneLevelBilinearAtTexelCentersReadsWhatTheGeneralPathReads) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<float> wide(-0.7f, 1.7f);
  std::uniform_int_distribution<int> any_row(-3, 40);
  long compared = 0;
  for (const TextureFormat format : kFormats) {
    // Power-of-two sizes put every center exactly on a float; 13x7 only some of them.
    for (const auto& [w, h] : {std::pair{32, 8}, std::pair{16, 16}, std::pair{13, 7}}) {
      Texture t = Texture::create_2d(w, h, format);
      fill_random(t, rng);
      for (const Address a : {Address::Clamp, Address::Wrap, Address::Mirror, Address::Border}) {
        Sampler s;
        s.mag = s.min = Filter::Linear;
        s.mip = MipFilter::None;
        s.u = s.v = a;
        s.border = {0.25f, 0.5f, 0.75f, 1.0f};
        Sampler general = s;
        general.min = Filter::Point;  // no lane minified at LOD -1: the general path, bilinear
        for (int stamp = 0; stamp < 64; ++stamp) {
          // Rows at centers, columns at centers, both, or a lane or two off the centers.
          const int mode = stamp % 4;
          const int row = any_row(rng), column = any_row(rng);
          LaneValues x, y;
          for (int l = 0; l < kLanes; ++l) {
            const bool off = mode == 3 && l == stamp % kLanes;
            x[l] = mode == 1 || mode == 2 || (mode == 3 && !off) ? (float(column + l % 3) + 0.5f) / float(w) : wide(rng);
            y[l] = mode == 0 || mode == 2 || (mode == 3 && !off) ? (float(row) + 0.5f) / float(h) : wide(rng);
          }
          const TexCoord c{lanes_of(x), lanes_of(y), simd::Float(0.0f)};
          const auto one_level = unpack(sample_level(t, s, c, simd::Float(0.0f)));
          const auto reference = unpack(sample_level(t, general, c, simd::Float(-1.0f)));
          for (int l = 0; l < kLanes; ++l) {
            for (int ch = 0; ch < 4; ++ch) {
              ++compared;
              ASSERT_EQ(std::bit_cast<uint32_t>(one_level[l][ch]), std::bit_cast<uint32_t>(reference[l][ch]))
                  << name(format) << " " << w << "x" << h << ", " << describe(s) << ", mode " << mode << ", lane " << l
                  << " channel " << ch << " at (" << x[l] << ", " << y[l] << ")";
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 10000);
}

// sample_taps reads several coordinates of one sampler in one call (a blur's taps): each result
// the very bits sample() returns for its coordinate, for every kind, format and sampler (the
// one-level 2D reads have their own path), random coordinates and blur-like ones (taps along u
// on texel-center rows, where the zero-weight skip reads one row; taps along v, which share their
// columns). No taps is fine too; a count of results other than the coordinates' throws.
TEST(TextureSimd, TapsReadWhatSampleReadsAtEachTap) {
  std::mt19937 rng(31);
  long compared = 0;
  for_each_texture_and_sampler(rng, [&](const TestTexture& tt, const Sampler& s) {
    if (HasFatalFailure()) return;
    const Texture& t = tt.texture;
    for (int round = 0; round < 5; ++round) {
      const size_t taps = round == 0 ? 0 : round == 1 ? 1 : 13;
      std::vector<TexCoord> coords;
      for (size_t k = 0; k < taps; ++k) {
        LaneValues x, y, z;
        for (int l = 0; l < kLanes; ++l) {
          const glm::vec3 c = random_coord(t, rng);
          x[l] = c.x, y[l] = c.y, z[l] = c.z;
          const float along = 1.3366f * float(int(k) - 6);
          if (round == 3 && t.kind() == TextureKind::Texture2D) {  // a horizontal blur's taps
            x[l] = (float(l % 8) + 0.5f + along) / float(t.width());
            y[l] = (float(l / 8) + 0.5f) / float(t.height());
          }
          if (round == 4 && t.kind() == TextureKind::Texture2D) {  // a vertical one's, off the centers
            x[l] = (float(l % 8) + 0.25f) / float(t.width());
            y[l] = (float(l / 8) + 0.5f + 0.5625f * along) / float(t.height());
          }
        }
        coords.push_back({lanes_of(x), lanes_of(y), lanes_of(z)});
      }
      std::vector<simd::Float4> got(taps);
      sample_taps(t, s, coords, got);
      for (size_t k = 0; k < taps; ++k) {
        const auto want = unpack(sample(t, s, coords[k]));
        const auto tap = unpack(got[k]);
        for (int l = 0; l < kLanes; ++l) {
          for (int ch = 0; ch < 4; ++ch) {
            ++compared;
            ASSERT_EQ(std::bit_cast<uint32_t>(tap[l][ch]), std::bit_cast<uint32_t>(want[l][ch]))
                << tt.label << ", " << describe(s) << ", round " << round << ", tap " << k << ", lane " << l
                << " channel " << ch;
          }
        }
      }
    }
  });
  EXPECT_GT(compared, 100000);
  const Texture t = Texture::create_2d(4, 4, TextureFormat::RGBA8);
  const std::vector<TexCoord> one{{simd::Float(0.5f), simd::Float(0.5f), simd::Float(0.0f)}};
  std::vector<simd::Float4> two(2);
  EXPECT_THROW(sample_taps(t, Sampler{}, one, two), std::invalid_argument);
}

/// Sets the alpha of every texel of every level and face: `step` steps below the format's
/// maximum (RGBA8 and sRGB: 255, RGBA16: 65535, RGBA16F: the half 1.0, 0x3c00).
void set_alpha(Texture& t, int step) {
  for (int face = 0; face < t.faces(); ++face) {
    for (int level = 0; level < t.mip_levels(); ++level) {
      const auto current = t.level_bytes(level, face);
      std::vector<uint8_t> bytes(current.begin(), current.end());
      const size_t texel = size_t(bytes_per_texel(t.format()));
      for (size_t i = 0; i < bytes.size(); i += texel) {
        if (texel == 4) {
          bytes[i + 3] = uint8_t(255 - step);
        } else {
          const uint16_t alpha = uint16_t((t.format() == TextureFormat::RGBA16F ? 0x3c00 : 0xffff) - step);
          std::memcpy(&bytes[i + 6], &alpha, 2);
        }
      }
      t.upload(level, bytes, face);
    }
  }
}

TEST(TextureCreate, OpaqueFollowsUploads) {
  Texture t = Texture::create_2d(8, 4, TextureFormat::RGBA8);
  EXPECT_FALSE(t.opaque());  // zeros
  std::vector<glm::vec4> white(32, glm::vec4(1.0f));
  t.upload(0, white);
  EXPECT_FALSE(t.opaque());  // the other levels are still zero
  t.generate_mips();
  EXPECT_TRUE(t.opaque());
  white[5].a = 254.0f / 255.0f;
  t.upload(0, white);
  EXPECT_FALSE(t.opaque());
  EXPECT_TRUE(Texture::create_2d(8, 4, TextureFormat::R32F).opaque());  // alpha reads 1 whatever it holds
  for (const TextureFormat format : {TextureFormat::RGBA8_sRGB, TextureFormat::RGBA16F, TextureFormat::RGBA16}) {
    Texture c = Texture::create_cube(4, format, 2);
    set_alpha(c, 0);
    EXPECT_TRUE(c.opaque()) << name(format);
    set_alpha(c, 1);
    EXPECT_FALSE(c.opaque()) << name(format);
  }
}

// An opaque texture is read through a path that filters the color channels alone and returns
// alpha 1. Its colors must be bit for bit those of a twin whose alpha is one step lower (read
// through the four-channel path: alpha takes no part in filtering the colors), and its alpha
// exactly 1, wherever no border color enters the footprint.
TEST(TextureSimd, OpaqueTexturesFilterTheColorsAlone) {
  std::mt19937 rng(11);
  constexpr int kStampsPerConfig = 16;
  long compared = 0;
  for (const TextureFormat format : kFormats) {
    if (format == TextureFormat::R32F) continue;  // always opaque: MatchesReference covers it
    for (const TestTexture& tt : random_textures(format, rng)) {
      Texture opaque = tt.texture, twin = tt.texture;
      set_alpha(opaque, 0);
      set_alpha(twin, 1);
      ASSERT_TRUE(opaque.opaque()) << tt.label;
      ASSERT_FALSE(twin.opaque()) << tt.label;
      for (const Sampler& s : sampler_configs(opaque.kind(), rng)) {
        const bool border = opaque.kind() != TextureKind::Cube &&
                            (s.u == Address::Border || s.v == Address::Border ||
                             (opaque.kind() == TextureKind::Volume && s.w == Address::Border));
        int failures = 0;
        for (int stamp = 0; stamp < kStampsPerConfig; ++stamp) {
          LaneValues x, y, z, lod;
          for (int l = 0; l < kLanes; ++l) {
            const glm::vec3 c = random_coord(opaque, rng);
            x[l] = c.x, y[l] = c.y, z[l] = c.z;
            lod[l] = random_lod(opaque, rng);
          }
          const TexCoord coord{lanes_of(x), lanes_of(y), lanes_of(z)};
          const auto got = unpack(sample_level(opaque, s, coord, lanes_of(lod)));
          const auto want = unpack(sample_level(twin, s, coord, lanes_of(lod)));
          for (int l = 0; l < kLanes; ++l) {
            ++compared;
            bool same = true;
            for (int ch = 0; ch < 3; ++ch) same &= std::memcmp(&got[l][ch], &want[l][ch], sizeof(float)) == 0;
            if (!border) same &= got[l].a == 1.0f;
            if (!same && failures++ < 3) {
              ADD_FAILURE() << tt.label << ", " << describe(s) << ", lane " << l << ": opaque (" << got[l].r << ", "
                            << got[l].g << ", " << got[l].b << ", " << got[l].a << "), twin (" << want[l].r << ", "
                            << want[l].g << ", " << want[l].b << ", " << want[l].a << ")";
            }
          }
        }
      }
    }
  }
  std::printf("[          ] %ld samples compared\n", compared);
}

TEST(TextureSimd, ImplicitLodMatchesExplicitAndReference) {
  // sample() must be sample_level() at compute_lod() of the coarse quad derivatives (under the
  // hardware rules the quad's top-left pixel's, for the whole quad), and compute_lod() must agree
  // with lod_reference() on those derivatives.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> base(-1.0f, 1.0f), slope(-0.2f, 0.2f), curve(-0.05f, 0.05f);
  float worst_lod = 0;
  for (const TextureFormat format : {TextureFormat::RGBA8, TextureFormat::RGBA16F}) {
    for (const TestTexture& tt : random_textures(format, rng)) {
      const Texture& t = tt.texture;
      for (int stamp = 0; stamp < 40; ++stamp) {
        Sampler s;
        s.rules = stamp % 2 ? SamplingRules::ideal : SamplingRules::hardware;
        // Smooth (quadratic) coordinates over the stamp's pixels.
        glm::vec3 c0, gx, gy, q;
        for (int a = 0; a < 3; ++a) {
          c0[a] = base(rng) * (t.kind() == TextureKind::Cube ? 1.0f : 2.0f);
          gx[a] = slope(rng);
          gy[a] = slope(rng);
          q[a] = curve(rng);
        }
        if (t.kind() == TextureKind::Cube) c0[stamp % 3] = stamp % 2 ? 1.5f : -1.5f;
        std::array<glm::vec3, kLanes> coord;
        LaneValues x, y, z;
        for (int l = 0; l < kLanes; ++l) {
          const float px = float(simd::lane_x(l)), py = float(simd::lane_y(l));
          coord[l] = c0 + gx * px + gy * py + q * (px * px);
          x[l] = coord[l].x;
          y[l] = coord[l].y;
          z[l] = coord[l].z;
        }
        const TexCoord c{lanes_of(x), lanes_of(y), lanes_of(z)};
        const TexCoord dx{simd::ddx(c.x), simd::ddx(c.y), simd::ddx(c.z)},
            dy{simd::ddy(c.x), simd::ddy(c.y), simd::ddy(c.z)};
        LaneValues lod;
        compute_lod(t, c, dx, dy).store_unaligned(lod.data());
        const float bias = stamp % 4 == 0 ? 0.0f : slope(rng) * 5;
        const auto implicit = unpack(sample(t, s, c, simd::Float(bias)));
        LaneValues used = lod;
        if (s.rules == SamplingRules::hardware)
          for (int l = 0; l < kLanes; ++l) used[l] = lod[l - l % 4];
        const auto explicit_lod = unpack(sample_level(t, s, c, lanes_of(used) + simd::Float(bias)));
        for (int l = 0; l < kLanes; ++l) {
          EXPECT_EQ(implicit[l], explicit_lod[l]) << tt.label << " lane " << l;
          // Coarse derivatives: top row and left column of the lane's quad.
          const int q0 = l - l % 4;
          const glm::vec3 ddx = coord[q0 + 1] - coord[q0], ddy = coord[q0 + 2] - coord[q0];
          const float want = lod_reference(t, coord[l], ddx, ddy);
          if (std::isfinite(want) && want > -20) {
            worst_lod = std::max(worst_lod, std::fabs(lod[l] - want));
            EXPECT_NEAR(lod[l], want, 2e-5f) << tt.label << " lane " << l;
          }
        }
      }
    }
  }
  std::printf("[          ] worst |compute_lod - lod_reference| = %g\n", worst_lod);
}

TEST(TextureSimd, LastLevelOfTheLongestChain) {
  // An 8192-texel side has kMaxMipLevels levels, so the level after the last does not exist even
  // as padding in the level table. A stamp whose lanes blend two levels while others sit on the
  // last one must not fetch a level past it for those. Their results do not show it (the fetch
  // is blended with weight 0), and ASan cannot see a read past an array inside an object: the
  // sanitizer builds check every level sampled (texture_addressing.hpp, level_geometry).
  // 8192x2 has the same chain as 8192x8192 at 1/4096 of the memory. LODs sweep from below 0 to
  // past the last level, the eight lanes of a stamp spread over 1.75 levels.
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> unit(-0.5f, 1.5f);
  for (const TextureFormat format : {TextureFormat::RGBA8, TextureFormat::RGBA16F}) {
    Texture t = Texture::create_2d(kMaxTextureSize, 2, format);
    ASSERT_EQ(t.mip_levels(), kMaxMipLevels);
    fill_random(t, rng);
    for (const Address address : {Address::Wrap, Address::Clamp}) {
      for (const Filter mag : {Filter::Point, Filter::Linear}) {
        for (const Filter min : {Filter::Point, Filter::Linear}) {
          for (const MipFilter mip : {MipFilter::None, MipFilter::Point, MipFilter::Linear}) {
            Sampler s;
            s.mag = mag;
            s.min = min;
            s.mip = mip;
            s.u = s.v = address;
            int failures = 0;
            for (float base = -2.0f; base <= kMaxMipLevels + 1.0f; base += 0.125f) {
              std::array<glm::vec3, kLanes> coord;
              LaneValues x, y, z{}, lod;
              for (int l = 0; l < kLanes; ++l) {
                coord[l] = {unit(rng), unit(rng), 0.0f};
                x[l] = coord[l].x;
                y[l] = coord[l].y;
                lod[l] = base + 0.25f * l;
              }
              const auto got = unpack(sample_level(t, s, {lanes_of(x), lanes_of(y), lanes_of(z)}, lanes_of(lod)));
              for (int l = 0; l < kLanes; ++l) {
                const glm::vec4 want = sample_reference(t, s, coord[l], lod[l]);
                for (int ch = 0; ch < 4; ++ch) {
                  if (!(std::fabs(got[l][ch] - want[ch]) <= kSimdTolerance) && failures++ < 3) {
                    ADD_FAILURE() << name(format) << ", " << describe(s) << ": lod " << lod[l] << " channel "
                                  << ch << ": SIMD " << got[l][ch] << ", reference " << want[ch];
                  }
                }
              }
            }
          }
        }
      }
    }
  }
}

TEST(TextureSimd, GarbageInIsSafe) {
  // Lanes outside a triangle carry whatever the interpolators produced: any float must read
  // inside the texture (checked by ASan, which sees every texel read as the SIMD path uses scalar
  // loads instead of hardware gathers under it) and give finite texels. Every combination of
  // special values for the three coordinates, with special LODs and biases.
  std::mt19937 rng(8);
  const float specials[] = {kNaN, kInf, -kInf, 3e38f, -3e38f, 1e-38f, -0.0f, 8388609.0f, -8388607.5f, 0.75f};
  constexpr int kCount = int(std::size(specials));
  for (const TextureFormat format : {TextureFormat::RGBA8, TextureFormat::RGBA16F}) {
    for (const TestTexture& tt : random_textures(format, rng)) {
      const std::vector<Sampler> samplers = sampler_configs(tt.texture.kind(), rng);
      for (size_t si = 0; si < samplers.size(); si += 5) {
        const Sampler& s = samplers[si];
        for (int first = 0; first < kCount * kCount * kCount; first += kLanes) {
          LaneValues x, y, z, lod;
          for (int l = 0; l < kLanes; ++l) {
            const int combo = (first + l) % (kCount * kCount * kCount);
            x[l] = specials[combo % kCount];
            y[l] = specials[combo / kCount % kCount];
            z[l] = specials[combo / (kCount * kCount)];
            lod[l] = specials[(combo + si) % kCount];
          }
          const TexCoord c{lanes_of(x), lanes_of(y), lanes_of(z)};
          for (const auto& r : {unpack(sample_level(tt.texture, s, c, lanes_of(lod))),
                                unpack(sample(tt.texture, s, c, lanes_of(lod)))}) {
            for (int l = 0; l < kLanes; ++l) {
              for (int ch = 0; ch < 4; ++ch) {
                ASSERT_TRUE(std::isfinite(r[l][ch])) << tt.label << " " << describe(s) << " at (" << x[l]
                                                     << ", " << y[l] << ", " << z[l] << ") lod " << lod[l];
              }
            }
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace luxel::rasterizer
