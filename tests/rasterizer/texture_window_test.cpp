// Magnified reads of 8-byte texels (RGBA16F, RGBA16) whose stamp lies within four rows of four
// texels take their texels from a window loaded once instead of gathers (texel_window.hpp). They
// must return what the scalar reference returns under the hardware rules, to the bit: every lane,
// every address mode, at the level's edges (where the window is moved back inside the level), on
// levels too small for a window, and on stamps that spread past one.

#include "luxel/rasterizer/texture.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace luxel::rasterizer::texel_window_test {
namespace {

using simd::kLanes;

std::array<glm::vec4, kLanes> lanes_of(const simd::Float4& r) {
  std::array<float, kLanes> x, y, z, w;
  r.x.store_unaligned(x.data());
  r.y.store_unaligned(y.data());
  r.z.store_unaligned(z.data());
  r.w.store_unaligned(w.data());
  std::array<glm::vec4, kLanes> out;
  for (int l = 0; l < kLanes; ++l) out[l] = {x[l], y[l], z[l], w[l]};
  return out;
}

/// Texels that differ in every channel, so that a texel taken from the wrong place shows; alpha 1
/// on `opaque` textures (read as Opaque: three channels).
Texture random_texture(TextureFormat format, int width, int height, bool opaque, std::mt19937& rng) {
  std::uniform_real_distribution<float> value(0.0f, format == TextureFormat::RGBA16F ? 4.0f : 1.0f);
  std::vector<glm::vec4> texels(static_cast<size_t>(width) * height);
  for (glm::vec4& t : texels) t = {value(rng), value(rng), value(rng), opaque ? 1.0f : value(rng)};
  Texture t = Texture::create_2d(width, height, format, 1);
  t.upload(0, texels);
  return t;
}

struct Case {
  TextureFormat format;
  int width, height;
  Address address;
  bool opaque;
};

std::string name_of(const Case& c) {
  return std::string(c.format == TextureFormat::RGBA16F ? "RGBA16F " : "RGBA16 ") + std::to_string(c.width) + "x" +
         std::to_string(c.height) + " address " + std::to_string(static_cast<int>(c.address)) + (c.opaque ? " opaque" : "");
}

/// `stamps` stamps of random texel coordinates spread over `spread` texels around a random point
/// (anywhere, edges and beyond included), each read by sample(), sample_taps() and the reference.
void expect_reads_match_reference(const Case& c, float spread, int stamps, std::mt19937& rng) {
  const Texture t = random_texture(c.format, c.width, c.height, c.opaque, rng);
  Sampler s;
  s.mip = MipFilter::None;
  s.u = s.v = c.address;
  std::uniform_real_distribution<float> centre_u(-1.0f, c.width + 1.0f), centre_v(-1.0f, c.height + 1.0f);
  std::uniform_real_distribution<float> offset(-0.5f * spread, 0.5f * spread);
  for (int n = 0; n < stamps; ++n) {
    const float cu = centre_u(rng), cv = centre_v(rng);
    std::array<glm::vec3, kLanes> coords;
    for (glm::vec3& p : coords) p = {(cu + offset(rng)) / c.width, (cv + offset(rng)) / c.height, 0.0f};
    alignas(64) std::array<float, kLanes> u, v;
    for (int l = 0; l < kLanes; ++l) u[l] = coords[l].x, v[l] = coords[l].y;
    const TexCoord coord{simd::Float::load_aligned(u.data()), simd::Float::load_aligned(v.data()), simd::Float(0.0f)};
    const auto sampled = lanes_of(sample(t, s, coord));
    std::array<TexCoord, 2> tap_coords{coord, coord};
    std::array<simd::Float4, 2> taps;
    sample_taps(t, s, tap_coords, taps);
    const auto tapped = lanes_of(taps[1]);
    for (int l = 0; l < kLanes; ++l) {
      const glm::vec4 want = sample_reference(t, s, coords[l], 0.0f);
      for (int ch = 0; ch < 4; ++ch) {
        ASSERT_EQ(sampled[l][ch], want[ch]) << name_of(c) << ", sample(), lane " << l << " channel " << ch << " at ("
                                            << coords[l].x << ", " << coords[l].y << ")";
        ASSERT_EQ(tapped[l][ch], want[ch]) << name_of(c) << ", sample_taps(), lane " << l << " channel " << ch;
      }
    }
  }
}

std::vector<Case> cases() {
  std::vector<Case> all;
  for (TextureFormat format : {TextureFormat::RGBA16F, TextureFormat::RGBA16})
    for (auto [w, h] : {std::pair{4, 4}, std::pair{9, 6}, std::pair{33, 17}, std::pair{3, 8}, std::pair{8, 2}})
      for (Address a : {Address::Clamp, Address::Wrap, Address::Mirror})
        for (bool opaque : {false, true}) all.push_back({format, w, h, a, opaque});
  return all;
}

TEST(TextureWindow, StampsWithinFourTexelsReadWhatTheReferenceReads) {
  std::mt19937 rng(7);
  for (const Case& c : cases()) expect_reads_match_reference(c, 2.5f, 200, rng);
}

TEST(TextureWindow, StampsAtTheWindowsSizeAndBeyondReadWhatTheReferenceReads) {
  std::mt19937 rng(11);
  for (const Case& c : cases()) {
    expect_reads_match_reference(c, 3.0f, 100, rng);
    expect_reads_match_reference(c, 6.0f, 100, rng);
  }
}

}  // namespace
}  // namespace luxel::rasterizer::texel_window_test
