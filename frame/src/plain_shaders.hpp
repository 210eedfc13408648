#pragma once
// Private: the plain shaders the frame draws with until the Source frame (#8) arrives
// (renderer.hpp says what they compute).

#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/texture.hpp"
#include "luxel/scenes/scene.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>

namespace luxel::frame {

/// Position and vertex color x material color: for unlit, untextured materials.
struct UnlitVertex {
  static constexpr int kVaryings = 1;
  const glm::vec3* positions;
  const glm::vec4* colors;  ///< or null: white
  glm::vec4 color;          ///< the material's
  glm::mat4 view_projection;
  /// The front end prefetches the positions (draw.hpp); the colors, a second stream as large
  /// (W2's 48 MB), are prefetched here, as far ahead: without it W2 ran ~1.5% slower.
  static constexpr uint32_t kColorsAhead = 64;
  const void* input(uint32_t i) const { return positions + i; }
  void operator()(uint32_t i, rasterizer::VertexOutput<1>& out) const {
    out.position = view_projection * glm::vec4(positions[i], 1.0f);
    if (colors) rasterizer::simd::prefetch(colors + i + kColorsAhead);  // never faults, even past the end
    out.varyings[0] = colors ? colors[i] * color : color;
  }
};

/// The interpolated color, as it is: trivial (rasterizer/draw.hpp), so the workloads' draws take
/// the rasterizer's fastest paths.
struct UnlitPixel {
  static constexpr bool kCanDiscard = false, kWritesDepth = false, kTrivial = true;
  void operator()(const rasterizer::PixelInput<1>& in, rasterizer::PixelOutput& out) const {
    out.color = in.varyings[0];
  }
};

/// Texture coordinates, world normal and vertex color x material color, packed in two
/// varyings: (u, v, nx, ny), (nz, r, g, b).
struct PlainVertex {
  static constexpr int kVaryings = 2;
  const glm::vec3* positions;
  const glm::vec3* normals;  ///< or null: no normal (ambient only)
  const glm::vec2* uvs;      ///< or null: (0, 0)
  const glm::vec4* colors;   ///< or null: white
  glm::vec4 color;
  scenes::UvTransform uv_transform;
  glm::mat4 view_projection;
  void operator()(uint32_t i, rasterizer::VertexOutput<2>& out) const {
    out.position = view_projection * glm::vec4(positions[i], 1.0f);
    const glm::vec2 uv = uv_transform(uvs ? uvs[i] : glm::vec2(0.0f));
    const glm::vec3 n = normals ? normals[i] : glm::vec3(0.0f);
    const glm::vec4 c = colors ? colors[i] * color : color;
    out.varyings[0] = {uv.x, uv.y, n.x, n.y};
    out.varyings[1] = {n.z, c.r, c.g, c.b};
  }
};

/// The lighting of the plain shader: rgb = ambient + ambient_up * (0.5 + 0.5 n.z) + sun * max(0, n.l).
/// Unlit materials use ambient 1 and nothing else, which leaves the product as it is.
struct PlainLight {
  glm::vec3 ambient{1.0f}, ambient_up{0.0f}, sun{0.0f};
  glm::vec3 to_sun{0.0f, 0.0f, 1.0f};
};

/// base texture x vertex color x material color x lighting, opaque.
struct PlainPixel {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  const rasterizer::Texture* texture;
  const rasterizer::Sampler* sampler;
  PlainLight light;
  void operator()(const rasterizer::PixelInput<2>& in, rasterizer::PixelOutput& out) const {
    using rasterizer::simd::Float;
    const rasterizer::simd::Float4& a = in.varyings[0];
    const rasterizer::simd::Float4& b = in.varyings[1];
    const rasterizer::simd::Float4 albedo = rasterizer::sample(*texture, *sampler, {a.x, a.y, Float(0.0f)});
    const Float inv_len = Float(1.0f) / xsimd::sqrt(a.z * a.z + a.w * a.w + b.x * b.x + Float(1e-20f));
    const Float ndotl = xsimd::max(
        Float(0.0f), (a.z * Float(light.to_sun.x) + a.w * Float(light.to_sun.y) + b.x * Float(light.to_sun.z)) * inv_len);
    const Float up = Float(0.5f) + Float(0.5f) * b.x * inv_len;
    auto lit = [&](int c) {
      return Float(light.ambient[c]) + Float(light.ambient_up[c]) * up + Float(light.sun[c]) * ndotl;
    };
    out.color = {albedo.x * b.y * lit(0), albedo.y * b.z * lit(1), albedo.z * b.w * lit(2), Float(1.0f)};
  }
};

/// The sky behind everything: one triangle over the whole screen at the far plane, carrying the
/// view ray's direction (linear in screen space for either projection) to a cube-map lookup.
struct SkyVertex {
  static constexpr int kVaryings = 1;
  glm::vec4 clip[3];
  glm::vec4 direction[3];
  void operator()(uint32_t i, rasterizer::VertexOutput<1>& out) const {
    out.position = clip[i];
    out.varyings[0] = direction[i];
  }
};

struct SkyPixel {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  const rasterizer::Texture* cube;
  const rasterizer::Sampler* sampler;
  void operator()(const rasterizer::PixelInput<1>& in, rasterizer::PixelOutput& out) const {
    const rasterizer::simd::Float4& d = in.varyings[0];
    const rasterizer::simd::Float4 c = rasterizer::sample(*cube, *sampler, {d.x, d.y, d.z});
    out.color = {c.x, c.y, c.z, rasterizer::simd::Float(1.0f)};
  }
};

}  // namespace luxel::frame
