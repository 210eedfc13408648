// Texture storage: creation and validation, uploads, texel loads, and the scalar format
// conversions and cube-face geometry the sampling paths share. Mip generation is in
// texture_mips.cpp, the copies sampling reads (cube maps' bordered copy, volumes' cells) in
// texture_copies.cpp.

#include "luxel/rasterizer/texture.hpp"

#include "texture_internal.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace luxel::rasterizer {

using texture_detail::decode_texel;
using texture_detail::encode_texel;

// --- Format conversions ----------------------------------------------------------------------

namespace texture_detail {

float half_to_float(uint16_t h) {
  const bool negative = (h & 0x8000u) != 0;
  const int exponent = (h >> 10) & 0x1f;
  const int mantissa = h & 0x3ff;
  float magnitude;
  if (exponent == 0x1f) {
    // Keep NaN payloads (quiet bit included) rather than collapsing every NaN to one.
    return std::bit_cast<float>((negative ? 0x80000000u : 0u) | 0x7f800000u | (uint32_t(mantissa) << 13));
  } else if (exponent == 0) {
    magnitude = std::ldexp(static_cast<float>(mantissa), -24);  // denormal: mantissa * 2^-24
  } else {
    magnitude = std::ldexp(static_cast<float>(mantissa + 1024), exponent - 25);
  }
  return negative ? -magnitude : magnitude;
}

uint16_t float_to_half(float f) {
  const uint32_t bits = std::bit_cast<uint32_t>(f);
  const uint16_t sign = static_cast<uint16_t>((bits >> 16) & 0x8000u);
  const uint32_t magnitude = bits & 0x7fffffffu;
  if (magnitude >= 0x7f800000u) {  // inf or NaN (NaN stays a quiet NaN)
    return sign |
           (magnitude > 0x7f800000u ? uint16_t(0x7e00u | ((magnitude >> 13) & 0x3ffu)) : uint16_t(0x7c00u));
  }
  if (magnitude >= 0x477ff000u) return sign | 0x7c00u;  // >= 65520 rounds past 65504
  if (magnitude < 0x38800000u) {                        // below 2^-14: a half denormal (or 0)
    const float scaled = std::bit_cast<float>(magnitude) * 16777216.0f;  // in units of 2^-24, exact
    return sign | static_cast<uint16_t>(std::nearbyint(scaled));         // 1024 becomes 2^-14
  }
  uint32_t h = (magnitude - 0x38000000u) >> 13;  // rebias the exponent, keep 10 mantissa bits
  const uint32_t rest = magnitude & 0x1fffu;
  if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) ++h;  // nearest, ties to even
  return sign | static_cast<uint16_t>(h);
}

uint8_t encode_unorm8(double x) {
  if (!(x > 0.0)) return 0;  // negative or NaN
  if (x >= 1.0) return 255;
  return static_cast<uint8_t>(std::nearbyint(x * 255.0));
}

uint16_t encode_unorm16(double x) {
  if (!(x > 0.0)) return 0;
  if (x >= 1.0) return 65535;
  return static_cast<uint16_t>(std::nearbyint(x * 65535.0));
}

glm::dvec4 decode_texel(TextureFormat format, const uint8_t* t) {
  switch (format) {
    case TextureFormat::RGBA8: return glm::dvec4(t[0], t[1], t[2], t[3]) / 255.0;
    case TextureFormat::RGBA8_sRGB:
      return {srgb_to_linear(t[0] / 255.0), srgb_to_linear(t[1] / 255.0), srgb_to_linear(t[2] / 255.0),
              t[3] / 255.0};
    case TextureFormat::RGBA16F: {
      uint16_t h[4];
      std::memcpy(h, t, 8);
      return {half_to_float(h[0]), half_to_float(h[1]), half_to_float(h[2]), half_to_float(h[3])};
    }
    case TextureFormat::RGBA16: {
      uint16_t c[4];
      std::memcpy(c, t, 8);
      return glm::dvec4(c[0], c[1], c[2], c[3]) / 65535.0;
    }
    case TextureFormat::R32F: {
      float r;
      std::memcpy(&r, t, 4);
      return {r, 1.0, 1.0, 1.0};
    }
  }
  return {};
}

void encode_texel(TextureFormat format, const glm::dvec4& c, uint8_t* t) {
  switch (format) {
    case TextureFormat::RGBA8:
      for (int i = 0; i < 4; ++i) t[i] = encode_unorm8(c[i]);
      return;
    case TextureFormat::RGBA8_sRGB:
      for (int i = 0; i < 3; ++i) t[i] = encode_unorm8(linear_to_srgb(std::clamp(c[i], 0.0, 1.0)));
      t[3] = encode_unorm8(c[3]);
      return;
    case TextureFormat::RGBA16F: {
      const uint16_t h[4] = {float_to_half(static_cast<float>(c[0])), float_to_half(static_cast<float>(c[1])),
                             float_to_half(static_cast<float>(c[2])),
                             float_to_half(static_cast<float>(c[3]))};
      std::memcpy(t, h, 8);
      return;
    }
    case TextureFormat::RGBA16: {
      const uint16_t u[4] = {encode_unorm16(c[0]), encode_unorm16(c[1]), encode_unorm16(c[2]),
                             encode_unorm16(c[3])};
      std::memcpy(t, u, 8);
      return;
    }
    case TextureFormat::R32F: {
      const float r = static_cast<float>(c[0]);
      std::memcpy(t, &r, 4);
      return;
    }
  }
}

// D3D's cube-map layout (the same table as OpenGL's): +X (sc, tc) = (-z, -y), -X (+z, -y),
// +Y (+x, +z), -Y (+x, -z), +Z (+x, -y), -Z (-x, -y).
const std::array<CubeFaceBasis, 6> kCubeFaceBasis = {{
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
    {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},
    {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
}};

}  // namespace texture_detail

int bytes_per_texel(TextureFormat format) {
  switch (format) {
    case TextureFormat::RGBA16F:
    case TextureFormat::RGBA16: return 8;
    default: return 4;
  }
}

// --- Cube geometry ---------------------------------------------------------------------------

namespace {
/// The component of d along a signed unit axis (exactly, infinities included, unlike a dot product).
float along(const glm::ivec3& axis, const glm::vec3& d) {
  const int k = axis.x != 0 ? 0 : axis.y != 0 ? 1 : 2;
  return static_cast<float>(axis[k]) * d[k];
}
}  // namespace

CubeFaceCoord cube_face(glm::vec3 d) {
  const float ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
  int axis;  // 0 = x, 1 = y, 2 = z; ties prefer z, then y
  if (az >= ax && az >= ay) {
    axis = 2;
  } else if (ay >= ax) {
    axis = 1;
  } else {
    axis = 0;
  }
  const float ma = d[axis];
  const int face = 2 * axis + (ma < 0.0f ? 1 : 0);
  const auto& basis = texture_detail::kCubeFaceBasis[face];
  const float sc = along(basis.u_axis, d), tc = along(basis.v_axis, d);
  const float m = std::fabs(ma);
  // A zero (or infinite) direction reads the face's center. A NaN component can make the major
  // axis not the largest, so the result is also clamped to the face.
  float s = sc / m, t = tc / m;
  s = std::isnan(s) ? 0.0f : std::clamp(s, -1.0f, 1.0f);
  t = std::isnan(t) ? 0.0f : std::clamp(t, -1.0f, 1.0f);
  return {static_cast<CubeFace>(face), (s + 1.0f) * 0.5f, (t + 1.0f) * 0.5f};
}

glm::vec3 cube_direction(CubeFace face, float u, float v) {
  const auto& basis = texture_detail::kCubeFaceBasis[static_cast<int>(face)];
  return glm::vec3(basis.normal) + glm::vec3(basis.u_axis) * (2.0f * u - 1.0f) +
         glm::vec3(basis.v_axis) * (2.0f * v - 1.0f);
}

// --- Creation ---------------------------------------------------------------------------------

namespace {

[[noreturn]] void invalid(const std::string& what) { throw std::invalid_argument("luxel texture: " + what); }

void check_size(const char* name, int size, int max) {
  if (size < 1 || size > max) {
    invalid(std::string(name) + " " + std::to_string(size) + " is not in [1, " + std::to_string(max) + "]");
  }
}

const char* kind_name(TextureKind kind) {
  switch (kind) {
    case TextureKind::Texture2D: return "2D texture";
    case TextureKind::Cube: return "cube map";
    case TextureKind::Volume: return "volume texture";
  }
  return "texture";
}

std::string size_text(const TextureDesc& desc) {
  std::string text = std::to_string(desc.width);
  text += 'x';
  text += std::to_string(desc.height);
  if (desc.kind == TextureKind::Volume) {
    text += 'x';
    text += std::to_string(desc.depth);
  }
  return text;
}

}  // namespace

int Texture::full_mip_chain(int width, int height, int depth) {
  const int largest = std::max({width, height, depth, 1});
  return std::bit_width(static_cast<unsigned>(largest));  // floor(log2) + 1
}

Texture Texture::create(const TextureDesc& desc) {
  const int max_size = desc.kind == TextureKind::Volume ? kMaxVolumeSize : kMaxTextureSize;
  check_size("width", desc.width, max_size);
  check_size("height", desc.height, max_size);
  if (desc.kind == TextureKind::Volume) {
    check_size("depth", desc.depth, max_size);
  } else if (desc.depth != 1) {
    invalid(std::string("a ") + kind_name(desc.kind) + " has depth 1, not " + std::to_string(desc.depth));
  }
  if (desc.kind == TextureKind::Cube && desc.width != desc.height) {
    invalid("cube map faces must be square, not " + std::to_string(desc.width) + "x" +
            std::to_string(desc.height));
  }
  const int full = full_mip_chain(desc.width, desc.height, desc.depth);
  if (desc.mip_levels < 0 || desc.mip_levels > full) {
    invalid("mip_levels " + std::to_string(desc.mip_levels) + " is not in [0 (full chain), " +
            std::to_string(full) + "] for a " + size_text(desc) + " " + kind_name(desc.kind));
  }

  Texture t;
  t.kind_ = desc.kind;
  t.format_ = desc.format;
  t.width_ = desc.width;
  t.height_ = desc.height;
  t.depth_ = desc.depth;
  t.levels_ = desc.mip_levels == kFullMipChain ? full : desc.mip_levels;
  t.words_per_texel_ = bytes_per_texel(desc.format) / 4;
  int64_t offset = 0;
  for (int l = 0; l < t.levels_; ++l) {
    t.level_offset_[l] = static_cast<int32_t>(offset);
    offset += static_cast<int64_t>(t.width(l)) * t.height(l) * t.depth(l) * t.words_per_texel_;
    if (offset > INT32_MAX) break;
  }
  const int64_t total = offset * t.faces();
  if (total > INT32_MAX) {
    // Sampling gathers texels with 32-bit word offsets from one base pointer.
    invalid("a " + size_text(desc) + " " + kind_name(desc.kind) + " needs more than 8 GiB");
  }
  t.face_words_ = static_cast<int32_t>(offset);
  // Past the last texel, the words a sampling read of a stamp row may load (simd::gather_stamp_rows).
  t.words_.assign(static_cast<size_t>(total) + simd::kStampRowWindowWords, 0u);
  if (t.kind_ == TextureKind::Cube) {
    int64_t bordered = 0;
    for (int l = 0; l < t.levels_; ++l) {
      t.cube_level_offset_[l] = static_cast<int32_t>(bordered);
      bordered += static_cast<int64_t>(t.width(l) + 2) * (t.width(l) + 2) * t.words_per_texel_;
    }
    if (bordered * t.faces() > INT32_MAX) invalid("a " + size_text(desc) + " cube needs more than 8 GiB to sample");
    t.cube_face_words_ = static_cast<int32_t>(bordered);
    t.cube_words_.assign(static_cast<size_t>(bordered * t.faces()), 0u);
  }
  const int64_t cell_words = 4 * int64_t{t.width_ + 1} * (t.height_ + 1) * (t.depth_ + 2);
  if (t.kind_ == TextureKind::Volume && t.levels_ == 1 && t.words_per_texel_ == 1 && cell_words <= kMaxCellWords)
    t.cell_words_.assign(static_cast<size_t>(cell_words), 0u);
  // All zeros: opaque only as R32F, which reads alpha 1 whatever it holds.
  t.level_opaque_.assign(static_cast<size_t>(t.faces() * t.levels_), desc.format == TextureFormat::R32F ? 1 : 0);
  t.opaque_ = desc.format == TextureFormat::R32F;
  return t;
}

Texture Texture::create_2d(int width, int height, TextureFormat format, int mip_levels) {
  return create({TextureKind::Texture2D, format, width, height, 1, mip_levels});
}

Texture Texture::create_cube(int size, TextureFormat format, int mip_levels) {
  return create({TextureKind::Cube, format, size, size, 1, mip_levels});
}

Texture Texture::create_volume(int width, int height, int depth, TextureFormat format, int mip_levels) {
  return create({TextureKind::Volume, format, width, height, depth, mip_levels});
}

// --- Access -----------------------------------------------------------------------------------

void Texture::check_level_face(int level, int face) const {
  if (level < 0 || level >= levels_) {
    throw std::out_of_range("luxel texture: level " + std::to_string(level) + " is not in [0, " +
                            std::to_string(levels_) + ")");
  }
  if (face < 0 || face >= faces()) {
    throw std::out_of_range("luxel texture: face " + std::to_string(face) + " is not in [0, " +
                            std::to_string(faces()) + ")");
  }
}

size_t Texture::level_words(int level) const {
  return static_cast<size_t>(width(level)) * height(level) * depth(level) * words_per_texel_;
}

std::span<const uint8_t> Texture::level_bytes(int level, int face) const {
  check_level_face(level, face);
  const uint32_t* first = words_.data() + static_cast<size_t>(face) * face_words_ + level_offset_[level];
  return {reinterpret_cast<const uint8_t*>(first), level_words(level) * sizeof(uint32_t)};
}

std::span<uint8_t> Texture::level_span(int level, int face) {
  const auto bytes = level_bytes(level, face);
  return {const_cast<uint8_t*>(bytes.data()), bytes.size()};
}

void Texture::upload(int level, std::span<const uint8_t> bytes, int face) {
  const auto destination = level_span(level, face);
  if (bytes.size() != destination.size()) {
    invalid("level " + std::to_string(level) + " takes " + std::to_string(destination.size()) +
            " bytes, not " + std::to_string(bytes.size()));
  }
  std::memcpy(destination.data(), bytes.data(), bytes.size());
  refresh_cube_copy(level, face);
  refresh_cells();
  set_level_opaque(level, face, alpha_at_max(destination));
}

void Texture::upload(int level, std::span<const glm::vec4> texels, int face) {
  const auto destination = level_span(level, face);
  const size_t texel_bytes = static_cast<size_t>(bytes_per_texel(format_));
  if (texels.size() * texel_bytes != destination.size()) {
    invalid("level " + std::to_string(level) + " takes " + std::to_string(destination.size() / texel_bytes) +
            " texels, not " + std::to_string(texels.size()));
  }
  for (size_t i = 0; i < texels.size(); ++i) {
    encode_texel(format_, glm::dvec4(texels[i]), destination.data() + i * texel_bytes);
  }
  refresh_cube_copy(level, face);
  refresh_cells();
  set_level_opaque(level, face, alpha_at_max(destination));
}

bool Texture::alpha_at_max(std::span<const uint8_t> texels) const {
  if (format_ == TextureFormat::R32F) return true;  // reads alpha 1 whatever it holds
  const uint32_t* words = reinterpret_cast<const uint32_t*>(texels.data());
  const size_t count = texels.size() / sizeof(uint32_t);
  // The word holding alpha, its place and its maximum: RGBA8 0xff in bits 24-31; RGBA16 0xffff
  // and RGBA16F 0x3c00 (1.0) in the high half of a texel's second word.
  const bool eight_bit = words_per_texel_ == 1;
  const uint32_t one = format_ == TextureFormat::RGBA16F ? 0x3c00u : eight_bit ? 0xffu : 0xffffu;
  const int shift = eight_bit ? 24 : 16;
  uint32_t differ = 0;  // (constant strides, no early exit: the loops vectorize)
  if (eight_bit) {
    for (size_t i = 0; i < count; ++i) differ |= (words[i] >> shift) ^ one;
  } else {
    for (size_t i = 1; i < count; i += 2) differ |= (words[i] >> shift) ^ one;
  }
  return differ == 0;
}

void Texture::set_level_opaque(int level, int face, bool opaque) {
  level_opaque_[static_cast<size_t>(face) * levels_ + level] = opaque ? 1 : 0;
  opaque_ = std::all_of(level_opaque_.begin(), level_opaque_.end(), [](uint8_t o) { return o != 0; });
}

glm::vec4 Texture::load(int x, int y, int z, int level) const {
  const int face = kind_ == TextureKind::Cube ? z : 0;
  const int slice = kind_ == TextureKind::Cube ? 0 : z;
  check_level_face(level, face);
  if (x < 0 || x >= width(level) || y < 0 || y >= height(level) || slice < 0 || slice >= depth(level)) {
    throw std::out_of_range("luxel texture: texel (" + std::to_string(x) + ", " + std::to_string(y) + ", " +
                            std::to_string(z) + ") is outside level " + std::to_string(level));
  }
  const size_t index = (static_cast<size_t>(slice) * height(level) + y) * width(level) + x;
  const auto bytes = level_bytes(level, face);
  return glm::vec4(decode_texel(format_, bytes.data() + index * bytes_per_texel(format_)));
}

}  // namespace luxel::rasterizer
