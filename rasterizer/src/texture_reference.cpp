// The scalar reference of texture sampling: one sample at a time, written to be read.
//
// It follows the conventions in texture.hpp step by step. Where they fix float32 arithmetic
// (coordinate reduction, texel positions, filter weights, face projection) it does exactly those
// float operations, so that it picks the same texels as the SIMD path. Under the ideal rules,
// everything after that (decoding, filtering, cube seams) is done in double; under the hardware
// rules, filtering is the rules' own fixed-point and float32 arithmetic, step by step. Either way
// by different means than the SIMD path (true modulo for addressing, geometry for cube seams,
// plain integers for the fixed point), so the two check each other.

#include "luxel/rasterizer/texture.hpp"

#include "texture_internal.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

namespace luxel::rasterizer {

namespace {

using glm::dvec4;

dvec4 lerp(const dvec4& a, const dvec4& b, double t) { return a + t * (b - a); }

/// The hardware rules' blend of two values (texture.hpp, "Sampling rules"): in fixed point, with
/// integers (a, b: 8-bit values; w: the weight's 8 bits); otherwise in float32, rounded once.
struct HardwareBlend {
  bool fixed_point;
  dvec4 operator()(const dvec4& a, const dvec4& b, int w) const {
    dvec4 r;
    for (int c = 0; c < 4; ++c) {
      if (fixed_point) {
        const int64_t ai = static_cast<int64_t>(a[c]), bi = static_cast<int64_t>(b[c]);
        // a + floor(w (b - a) / 256 + 1/2) = floor((256 a + w (b - a) + 128) / 256)
        const int64_t n = 256 * ai + w * (bi - ai) + 128;
        r[c] = static_cast<double>(n >= 0 ? n / 256 : -((-n + 255) / 256));
      } else {
        const float fa = static_cast<float>(a[c]), fb = static_cast<float>(b[c]);
        r[c] = std::fma(static_cast<float>(w) / 256.0f, fb - fa, fa);
      }
    }
    return r;
  }
};

/// A float converted to 16.8 fixed point, rounded to nearest, ties to even (the hardware rules'
/// texel positions and LOD).
int64_t to_fixed_8(float x) { return static_cast<int64_t>(std::nearbyint(static_cast<double>(x) * 256.0)); }

/// One period of the coordinate, in float32 as the header prescribes.
float reduce(float c, Address mode) {
  if (std::isnan(c)) c = 0.0f;
  float r = c;
  switch (mode) {
    case Address::Wrap: r = c - std::floor(c); break;
    case Address::Mirror: r = c - 2.0f * std::floor(c * 0.5f); break;
    case Address::Clamp:
    case Address::Border: r = std::clamp(c, -1.0f, 2.0f); break;
  }
  return std::isnan(r) ? 0.0f : r;  // infinity - infinity under Wrap / Mirror
}

/// The texel index that `i` reads along an axis of `n` texels, or nothing for the border.
std::optional<int> address(int i, int n, Address mode) {
  switch (mode) {
    case Address::Wrap: return ((i % n) + n) % n;
    case Address::Mirror: {
      const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
      return m < n ? m : 2 * n - 1 - m;
    }
    case Address::Clamp: return std::clamp(i, 0, n - 1);
    case Address::Border:
      if (i < 0 || i >= n) return std::nullopt;
      return i;
  }
  return std::nullopt;
}

/// The texel a point read at face coordinate c in [0, 1] finds along a face n texels wide.
int cube_point_index(float c, int n) { return std::min(static_cast<int>(std::floor(c * static_cast<float>(n))), n - 1); }

/// The 2x2 footprint of a cube read whose first texel is (i, j) on a face n texels wide: t[b][a] is
/// texel (i + a, j + b) as `texel(i, j)` reads it (possibly one texel past an edge); at a cube
/// corner one texel lies on no face: it is `mean` of the other three.
template <class Texel, class Mean>
std::array<std::array<dvec4, 2>, 2> cube_footprint(int n, int i, int j, const Texel& texel, const Mean& mean) {
  std::array<std::array<dvec4, 2>, 2> t;
  bool corner[2][2];
  for (int b = 0; b < 2; ++b) {
    for (int a = 0; a < 2; ++a) {
      const bool off_i = i + a < 0 || i + a >= n, off_j = j + b < 0 || j + b >= n;
      corner[b][a] = off_i && off_j;
      if (!corner[b][a]) t[b][a] = texel(i + a, j + b);
    }
  }
  for (int b = 0; b < 2; ++b) {
    for (int a = 0; a < 2; ++a) {
      if (corner[b][a]) t[b][a] = mean(t[b][1 - a], t[1 - b][a], t[1 - b][1 - a]);
    }
  }
  return t;
}

struct Reference {
  const Texture& texture;
  const Sampler& sampler;

  dvec4 texel(int level, int face, int x, int y, int z) const {
    const auto bytes = texture.level_bytes(level, face);
    const size_t index =
        (static_cast<size_t>(z) * texture.height(level) + y) * texture.width(level) + static_cast<size_t>(x);
    return texture_detail::decode_texel(texture_detail::read_format(texture, sampler),
                                        bytes.data() + index * bytes_per_texel(texture.format()));
  }

  /// Texel (i, j, k) of a 2D or volume level, after addressing.
  dvec4 addressed(int level, int i, int j, int k) const {
    const auto x = address(i, texture.width(level), sampler.u);
    const auto y = address(j, texture.height(level), sampler.v);
    const auto z = texture.kind() == TextureKind::Volume ? address(k, texture.depth(level), sampler.w)
                                                         : std::optional<int>(0);
    if (!x || !y || !z) return dvec4(sampler.border);
    return texel(level, 0, *x, *y, *z);
  }

  dvec4 filter_2d_or_volume(int level, Filter filter, glm::vec3 c) const {
    const bool volume = texture.kind() == TextureKind::Volume;
    const float size[3] = {static_cast<float>(texture.width(level)),
                           static_cast<float>(texture.height(level)),
                           static_cast<float>(texture.depth(level))};
    if (filter == Filter::Point) {
      const int i = static_cast<int>(std::floor(c.x * size[0]));
      const int j = static_cast<int>(std::floor(c.y * size[1]));
      const int k = volume ? static_cast<int>(std::floor(c.z * size[2])) : 0;
      return addressed(level, i, j, k);
    }
    int first[3];
    double weight[3];
    for (int a = 0; a < (volume ? 3 : 2); ++a) {
      const float x = c[a] * size[a] - 0.5f;
      const float fl = std::floor(x);
      first[a] = static_cast<int>(fl);
      weight[a] = x - fl;
    }
    if (!volume) {
      const int i = first[0], j = first[1];
      return lerp(lerp(addressed(level, i, j, 0), addressed(level, i + 1, j, 0), weight[0]),
                  lerp(addressed(level, i, j + 1, 0), addressed(level, i + 1, j + 1, 0), weight[0]),
                  weight[1]);
    }
    const int i = first[0], j = first[1], k = first[2];
    auto slice = [&](int kk) {
      return lerp(lerp(addressed(level, i, j, kk), addressed(level, i + 1, j, kk), weight[0]),
                  lerp(addressed(level, i, j + 1, kk), addressed(level, i + 1, j + 1, kk), weight[0]),
                  weight[1]);
    };
    return lerp(slice(k), slice(k + 1), weight[2]);
  }

  /// Texel (i, j) of a cube face at `level`, where (i, j) may lie one texel past one edge of the
  /// face: extend the face's plane, take the direction through that texel's center, and read the
  /// texel of the cube that direction hits. (In double: the hit lands within 1/(2(n+1)) texel of
  /// the right texel's edge, too close for float32 at large sizes.)
  dvec4 cube_texel(int level, int face, int i, int j) const {
    const int n = texture.width(level);
    if (i >= 0 && i < n && j >= 0 && j < n) return texel(level, face, i, j, 0);
    int hit = 0, hi = 0, hj = 0;
    texel_across_edge(level, face, i, j, hit, hi, hj);
    return texel(level, hit, hi, hj, 0);
  }

  /// Where texel (i, j) of `face`, one texel past one of its edges, lies: face `hit`, texel (hi, hj).
  void texel_across_edge(int level, int face, int i, int j, int& hit, int& hi, int& hj) const {
    const int n = texture.width(level);
    const auto& basis = texture_detail::kCubeFaceBasis[face];
    const double s = (2.0 * i + 1.0) / n - 1.0, t = (2.0 * j + 1.0) / n - 1.0;
    const glm::dvec3 d =
        glm::dvec3(basis.normal) + glm::dvec3(basis.u_axis) * s + glm::dvec3(basis.v_axis) * t;
    const glm::dvec3 a = glm::abs(d);
    const int axis = a.z >= a.x && a.z >= a.y ? 2 : a.y >= a.x ? 1 : 0;
    hit = 2 * axis + (d[axis] < 0.0 ? 1 : 0);
    const auto& hit_basis = texture_detail::kCubeFaceBasis[hit];
    const double u = (glm::dot(glm::dvec3(hit_basis.u_axis), d) / a[axis] + 1.0) * 0.5;
    const double v = (glm::dot(glm::dvec3(hit_basis.v_axis), d) / a[axis] + 1.0) * 0.5;
    hi = std::clamp(static_cast<int>(std::floor(u * n)), 0, n - 1);
    hj = std::clamp(static_cast<int>(std::floor(v * n)), 0, n - 1);
  }

  dvec4 filter_cube(int level, Filter filter, const CubeFaceCoord& fc) const {
    const int face = static_cast<int>(fc.face);
    const int n = texture.width(level);
    const float size = static_cast<float>(n);
    if (filter == Filter::Point) {
      return texel(level, face, cube_point_index(fc.u, n), cube_point_index(fc.v, n), 0);
    }
    const float x = fc.u * size - 0.5f, y = fc.v * size - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const int i = static_cast<int>(fx), j = static_cast<int>(fy);
    const auto t = cube_footprint(
        n, i, j, [&](int ti, int tj) { return cube_texel(level, face, ti, tj); },
        [](const dvec4& a, const dvec4& b, const dvec4& d) { return (a + b + d) / 3.0; });
    return lerp(lerp(t[0][0], t[0][1], x - fx), lerp(t[1][0], t[1][1], x - fx), y - fy);
  }

  dvec4 at_level(int level, Filter filter, glm::vec3 coord) const {
    if (texture.kind() == TextureKind::Cube) return filter_cube(level, filter, cube_face(coord));
    const glm::vec3 c(reduce(coord.x, sampler.u), reduce(coord.y, sampler.v), reduce(coord.z, sampler.w));
    return filter_2d_or_volume(level, filter, c);
  }
};

/// The hardware rules: texels in the format's raw domain (8-bit formats as their bytes, RGBA16 as
/// integers, floats as floats), blended by HardwareBlend, turned into linear RGBA at the end.
struct HardwareReference {
  const Texture& texture;
  const Sampler& sampler;
  bool bytes = texture.format() == TextureFormat::RGBA8 || texture.format() == TextureFormat::RGBA8_sRGB;
  bool srgb = texture_detail::read_format(texture, sampler) == TextureFormat::RGBA8_sRGB;
  HardwareBlend blend{bytes};

  dvec4 raw_texel(int level, int face, int x, int y, int z) const {
    const auto all = texture.level_bytes(level, face);
    const size_t index = (static_cast<size_t>(z) * texture.height(level) + y) * texture.width(level) + static_cast<size_t>(x);
    const uint8_t* t = all.data() + index * bytes_per_texel(texture.format());
    auto u16 = [t](int c) { return static_cast<uint16_t>(t[2 * c] | (t[2 * c + 1] << 8)); };
    switch (texture.format()) {
      case TextureFormat::RGBA8:
      case TextureFormat::RGBA8_sRGB: return dvec4(t[0], t[1], t[2], t[3]);
      case TextureFormat::RGBA16: return dvec4(u16(0), u16(1), u16(2), u16(3));
      case TextureFormat::RGBA16F:
        return dvec4(texture_detail::half_to_float(u16(0)), texture_detail::half_to_float(u16(1)),
                     texture_detail::half_to_float(u16(2)), texture_detail::half_to_float(u16(3)));
      case TextureFormat::R32F: {
        float r;
        std::memcpy(&r, t, sizeof r);
        return dvec4(r, 1.0, 1.0, 1.0);
      }
    }
    return {};
  }

  /// The border color in the raw domain: rounded to 8-bit steps (sRGB-encoded for an sRGB read).
  dvec4 raw_border() const {
    const glm::vec4 b = sampler.border;
    if (!bytes) {
      if (texture.format() == TextureFormat::RGBA16) return dvec4(b * 65535.0f);
      return dvec4(b);
    }
    auto step = [](double c) { return static_cast<double>(std::round(static_cast<float>(c) * 255.0f)); };
    auto unit = [](float c) { return std::clamp(c, 0.0f, 1.0f); };
    if (srgb) {
      return dvec4(step(static_cast<float>(linear_to_srgb(unit(b.x)))), step(static_cast<float>(linear_to_srgb(unit(b.y)))),
                   step(static_cast<float>(linear_to_srgb(unit(b.z)))), step(unit(b.w)));
    }
    return dvec4(step(unit(b.x)), step(unit(b.y)), step(unit(b.z)), step(unit(b.w)));
  }

  dvec4 addressed(int level, int i, int j, int k) const {
    const auto x = address(i, texture.width(level), sampler.u);
    const auto y = address(j, texture.height(level), sampler.v);
    const auto z = texture.kind() == TextureKind::Volume ? address(k, texture.depth(level), sampler.w) : std::optional<int>(0);
    if (!x || !y || !z) return raw_border();
    return raw_texel(level, 0, *x, *y, *z);
  }

  /// The first texel and the 8-bit weight of the second along an axis of `size` texels.
  static void footprint(float c, float size, int& first, int& weight) {
    const int64_t fixed = to_fixed_8(c * size - 0.5f);
    first = static_cast<int>(fixed >> 8);
    weight = static_cast<int>(fixed & 255);
  }

  dvec4 filter_2d_or_volume(int level, Filter filter, glm::vec3 c) const {
    const bool volume = texture.kind() == TextureKind::Volume;
    const float size[3] = {static_cast<float>(texture.width(level)), static_cast<float>(texture.height(level)),
                           static_cast<float>(texture.depth(level))};
    if (filter == Filter::Point) {
      const int i = static_cast<int>(std::floor(c.x * size[0]));
      const int j = static_cast<int>(std::floor(c.y * size[1]));
      const int k = volume ? static_cast<int>(std::floor(c.z * size[2])) : 0;
      return addressed(level, i, j, k);
    }
    int first[3] = {0, 0, 0}, w[3] = {0, 0, 0};
    for (int a = 0; a < (volume ? 3 : 2); ++a) footprint(c[a], size[a], first[a], w[a]);
    const int i = first[0], j = first[1];
    auto slice = [&](int k) {
      return blend(blend(addressed(level, i, j, k), addressed(level, i + 1, j, k), w[0]),
                   blend(addressed(level, i, j + 1, k), addressed(level, i + 1, j + 1, k), w[0]), w[1]);
    };
    if (!volume) return slice(0);
    return blend(slice(first[2]), slice(first[2] + 1), w[2]);
  }

  /// Texel (i, j) of a cube face at `level`, possibly one texel past an edge (Reference::cube_texel
  /// finds which texel of which face), in the raw domain.
  dvec4 cube_texel(int level, int face, int i, int j) const {
    const int n = texture.width(level);
    if (i >= 0 && i < n && j >= 0 && j < n) return raw_texel(level, face, i, j, 0);
    int hit = 0, hi = 0, hj = 0;
    Reference{texture, sampler}.texel_across_edge(level, face, i, j, hit, hi, hj);
    return raw_texel(level, hit, hi, hj, 0);
  }

  dvec4 filter_cube(int level, Filter filter, const CubeFaceCoord& fc) const {
    const int face = static_cast<int>(fc.face);
    const int n = texture.width(level);
    const float size = static_cast<float>(n);
    if (filter == Filter::Point) {
      return raw_texel(level, face, cube_point_index(fc.u, n), cube_point_index(fc.v, n), 0);
    }
    int i, j, wx, wy;
    footprint(fc.u, size, i, wx);
    footprint(fc.v, size, j, wy);
    const auto t = cube_footprint(
        n, i, j, [&](int ti, int tj) { return cube_texel(level, face, ti, tj); },
        [&](const dvec4& a, const dvec4& b, const dvec4& d) { return corner_mean(a, b, d); });
    return blend(blend(t[0][0], t[0][1], wx), blend(t[1][0], t[1][1], wx), wy);
  }

  /// The mean of three texels: in fixed point the nearest integer (halves up), else float32.
  dvec4 corner_mean(const dvec4& a, const dvec4& b, const dvec4& d) const {
    dvec4 m;
    for (int c = 0; c < 4; ++c) {
      if (bytes) {
        const int64_t sum = static_cast<int64_t>(a[c]) + static_cast<int64_t>(b[c]) + static_cast<int64_t>(d[c]);
        m[c] = static_cast<double>((2 * sum + 3) / 6);
      } else {
        m[c] = (static_cast<float>(a[c]) + static_cast<float>(b[c]) + static_cast<float>(d[c])) / 3.0f;
      }
    }
    return m;
  }

  dvec4 at_level(int level, Filter filter, glm::vec3 coord) const {
    if (texture.kind() == TextureKind::Cube) return filter_cube(level, filter, cube_face(coord));
    const glm::vec3 c(reduce(coord.x, sampler.u), reduce(coord.y, sampler.v), reduce(coord.z, sampler.w));
    return filter_2d_or_volume(level, filter, c);
  }

  /// Raw to linear RGBA, as each format's last step.
  glm::vec4 finish(const dvec4& raw) const {
    const glm::vec4 r(raw);
    if (srgb) {
      auto decode = [](float byte) { return kSrgbToLinear[static_cast<size_t>(byte)]; };
      return {decode(r.x), decode(r.y), decode(r.z), r.w / 255.0f};
    }
    if (bytes) return r / 255.0f;
    if (texture.format() == TextureFormat::RGBA16) return r / 65535.0f;
    return r;
  }
};

/// sample_reference under the hardware rules.
glm::vec4 hardware_reference(const Texture& texture, const Sampler& sampler, glm::vec3 coord, float lod) {
  const HardwareReference ref{texture, sampler};
  lod = lod + sampler.lod_bias;
  if (std::isnan(lod)) lod = 0.0f;
  // 8 fractional bits; a LOD so large that it has none to lose (or infinite) stays as it is.
  if (std::abs(lod) < 65536.0f) lod = static_cast<float>(to_fixed_8(lod)) / 256.0f;
  lod = std::min(std::max(lod, sampler.min_lod), sampler.max_lod);
  const Filter filter = lod <= 0.0f ? sampler.mag : sampler.min;
  const float last = static_cast<float>(texture.mip_levels() - 1);
  switch (sampler.mip) {
    case MipFilter::None: return ref.finish(ref.at_level(0, filter, coord));
    case MipFilter::Point: {
      const int level = static_cast<int>(std::floor(std::min(std::max(lod, 0.0f), last) + 0.5f));
      return ref.finish(ref.at_level(level, filter, coord));
    }
    case MipFilter::Linear: {
      const float l = std::min(std::max(lod, 0.0f), last);
      const float fl = std::floor(l);
      const int level = static_cast<int>(fl);
      const int t = static_cast<int>((l - fl) * 256.0f);  // the LOD's 8 fractional bits
      const dvec4 finer = ref.at_level(level, filter, coord);
      if (t == 0) return ref.finish(finer);
      return ref.finish(ref.blend(finer, ref.at_level(level + 1, filter, coord), t));
    }
  }
  return {};
}

}  // namespace

glm::vec4 sample_reference(const Texture& texture, const Sampler& sampler, glm::vec3 coord, float lod) {
  if (sampler.rules == SamplingRules::hardware) return hardware_reference(texture, sampler, coord, lod);
  const Reference ref{texture, sampler};
  lod = lod + sampler.lod_bias;
  if (std::isnan(lod)) lod = 0.0f;
  lod = std::min(std::max(lod, sampler.min_lod), sampler.max_lod);
  const Filter filter = lod <= 0.0f ? sampler.mag : sampler.min;
  const float last = static_cast<float>(texture.mip_levels() - 1);
  switch (sampler.mip) {
    case MipFilter::None: return glm::vec4(ref.at_level(0, filter, coord));
    case MipFilter::Point: {
      const int level = static_cast<int>(std::floor(std::min(std::max(lod, 0.0f), last) + 0.5f));
      return glm::vec4(ref.at_level(level, filter, coord));
    }
    case MipFilter::Linear: {
      const float l = std::min(std::max(lod, 0.0f), last);
      const float fl = std::floor(l);
      const int level = static_cast<int>(fl);
      const double t = l - fl;
      const dvec4 finer = ref.at_level(level, filter, coord);
      if (t == 0.0) return glm::vec4(finer);
      return glm::vec4(lerp(finer, ref.at_level(level + 1, filter, coord), t));
    }
  }
  return {};
}

float lod_reference(const Texture& texture, glm::vec3 coord, glm::vec3 ddx, glm::vec3 ddy) {
  glm::dvec3 dx(ddx), dy(ddy);
  glm::dvec3 scale(texture.width(), texture.height(), texture.depth());
  if (texture.kind() == TextureKind::Texture2D) {
    dx.z = dy.z = 0.0;
  } else if (texture.kind() == TextureKind::Cube) {
    // Derivatives of the face coordinates u = (sc / |ma| + 1) / 2, v = (tc / |ma| + 1) / 2 on the
    // face `coord` selects, by the quotient rule.
    const CubeFaceCoord fc = cube_face(coord);
    const auto& basis = texture_detail::kCubeFaceBasis[static_cast<int>(fc.face)];
    const glm::dvec3 n(basis.normal), ua(basis.u_axis), va(basis.v_axis), c(coord);
    const double ma = glm::dot(n, c);  // = |major axis|, positive on its own face
    auto face_derivative = [&](const glm::dvec3& d) {
      const double dma = glm::dot(n, d);
      const double du = 0.5 * (glm::dot(ua, d) * ma - glm::dot(ua, c) * dma) / (ma * ma);
      const double dv = 0.5 * (glm::dot(va, d) * ma - glm::dot(va, c) * dma) / (ma * ma);
      return glm::dvec3(du, dv, 0.0);
    };
    dx = face_derivative(dx);
    dy = face_derivative(dy);
    scale.z = 0.0;
  }
  const double rho_x = glm::length(dx * scale), rho_y = glm::length(dy * scale);
  return static_cast<float>(std::log2(std::max(rho_x, rho_y)));
}

}  // namespace luxel::rasterizer
