#pragma once
// Private to the texture module: raw access to a Texture's storage and the scalar format
// conversions shared by texture.cpp (storage, uploads), texture_mips.cpp, texture_reference.cpp and
// texture_sample.cpp.

#include "luxel/rasterizer/srgb.hpp"
#include "luxel/rasterizer/texture.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>

namespace luxel::rasterizer {

/// The storage sampling reads: a Texture's levels, or for a cube map its bordered copy (see the
/// layout comments in Texture). Face f, level l starts at word f * face_words + level_offsets[l].
struct SampledStorage {
  const int32_t* words;
  int32_t face_words;
  const std::array<int32_t, kMaxMipLevels>* level_offsets;
  const int32_t* cells = nullptr;  ///< a volume's trilinear cells (Texture::cell_words_), if it keeps them
};

struct TextureAccess {
  static SampledStorage sampled(const Texture& t) {
    if (t.kind_ == TextureKind::Cube)
      return {reinterpret_cast<const int32_t*>(t.cube_words_.data()), t.cube_face_words_, &t.cube_level_offset_};
    return {reinterpret_cast<const int32_t*>(t.words_.data()), t.face_words_, &t.level_offset_,
            t.cell_words_.empty() ? nullptr : reinterpret_cast<const int32_t*>(t.cell_words_.data())};
  }
  /// Level 0 of a 2D texture, to be written in place (a resolve into it: framebuffer.cpp).
  static std::span<uint8_t> level0(Texture& t) { return t.level_span(0, 0); }
  /// Records that all of level 0 of a 2D texture was written in place, its alpha at the maximum
  /// everywhere or not (`alpha_at_max`).
  static void level_written(Texture& t, bool alpha_at_max) { t.set_level_opaque(0, 0, alpha_at_max); }
  /// Records that rows [y0, y1) of level 0 of a 2D texture were written in place: whether it is
  /// opaque follows from those rows' alpha (`alpha_at_max`: known to be at the maximum), and from
  /// the other rows' as they were.
  static void rows_written(Texture& t, int y0, int y1, bool alpha_at_max) {
    const size_t row_bytes = size_t(t.width()) * size_t(bytes_per_texel(t.format()));
    const auto rows = t.level_span(0, 0).subspan(size_t(y0) * row_bytes, size_t(y1 - y0) * row_bytes);
    const bool others = (y0 == 0 && y1 == t.height()) || t.level_opaque_[0] != 0;
    t.set_level_opaque(0, 0, others && (alpha_at_max || t.alpha_at_max(rows)));
  }
};

namespace texture_detail {

/// The format `sampler` reads `texture` as: RGBA8 read with Sampler::srgb_read is RGBA8_sRGB.
inline TextureFormat read_format(const Texture& texture, const Sampler& sampler) {
  return texture.format() == TextureFormat::RGBA8 && sampler.srgb_read ? TextureFormat::RGBA8_sRGB : texture.format();
}

/// IEEE half <-> float. Decoding is exact; encoding rounds to nearest even (overflow -> inf).
float half_to_float(uint16_t h);
uint16_t float_to_half(float f);

/// round-to-nearest-even(saturate(x) * 255 or 65535); NaN -> 0.
uint8_t encode_unorm8(double x);
uint16_t encode_unorm16(double x);

/// One texel at `texel` (bytes_per_texel(format) bytes), decoded to linear RGBA in double.
glm::dvec4 decode_texel(TextureFormat format, const uint8_t* texel);
/// Encodes linear RGBA into one texel of `format`.
void encode_texel(TextureFormat format, const glm::dvec4& linear, uint8_t* texel);

/// Cube face basis: a direction on face f is normal * ma + u_axis * sc + v_axis * tc.
struct CubeFaceBasis {
  glm::ivec3 normal, u_axis, v_axis;
};
extern const std::array<CubeFaceBasis, 6> kCubeFaceBasis;

}  // namespace texture_detail
}  // namespace luxel::rasterizer
