#pragma once
// Private: per-sample depth/stencil tests, alpha test, blending and color packing on SIMD lanes.

#include "luxel/rasterizer/simd.hpp"
#include "luxel/rasterizer/srgb.hpp"
#include "luxel/rasterizer/state.hpp"

#include <cstdint>

namespace luxel::rasterizer::detail {

using simd::Float;
using simd::FloatMask;
using simd::Int;
using simd::IntMask;
using simd::LaneBits;

template <class T>
LUXEL_INLINE auto compare(CompareFunc func, const T& a, const T& b) {
  using M = decltype(a < b);
  switch (func) {
    case CompareFunc::Never: return M(false);
    case CompareFunc::Less: return a < b;
    case CompareFunc::Equal: return a == b;
    case CompareFunc::LessEqual: return a <= b;
    case CompareFunc::Greater: return a > b;
    case CompareFunc::NotEqual: return a != b;
    case CompareFunc::GreaterEqual: return a >= b;
    case CompareFunc::Always: break;
  }
  return M(true);
}

/// The result of a stencil op on 8-bit values held in 32-bit lanes.
inline Int stencil_op(StencilOp op, const Int& value, uint8_t ref) {
  switch (op) {
    case StencilOp::Keep: return value;
    case StencilOp::Zero: return Int(0);
    case StencilOp::Replace: return Int(ref);
    case StencilOp::IncrSat: return xsimd::min(value + Int(1), Int(255));
    case StencilOp::DecrSat: return xsimd::max(value - Int(1), Int(0));
    case StencilOp::Invert: return value ^ Int(255);
    case StencilOp::Incr: return (value + Int(1)) & Int(255);
    case StencilOp::Decr: return (value - Int(1)) & Int(255);
  }
  return value;
}

/// Four channels in [0, 1] (NaN -> 0) packed to RGBA8 with round-to-nearest-even.
using simd::pack_unorm8;

inline Int encode_srgb_channel(const Float& x) {
  const Int index = simd::round_to_int(xsimd::min(xsimd::max(x, Float(0.0f)), Float(1.0f)) * Float(65535.0f));
  alignas(64) int32_t idx[simd::kLanes], out[simd::kLanes];
  index.store_aligned(idx);
  const uint8_t* table = srgb_encode_table().data();
  for (int l = 0; l < simd::kLanes; ++l) out[l] = table[idx[l]];
  return Int::load_aligned(out);
}

/// RGB encoded to sRGB, alpha linear (as D3D does).
inline Int pack_srgb8(const simd::Float4& c) {
  auto q = [](const Float& x) {
    return simd::round_to_int(xsimd::min(xsimd::max(x, Float(0.0f)), Float(1.0f)) * Float(255.0f));
  };
  return encode_srgb_channel(c.x) | (encode_srgb_channel(c.y) << 8) | (encode_srgb_channel(c.z) << 16) |
         (q(c.w) << 24);
}

inline simd::Float4 unpack_unorm8(const Int& packed) {
  const Float scale(1.0f / 255.0f);
  return {xsimd::to_float(packed & Int(255)) * scale, xsimd::to_float((packed >> 8) & Int(255)) * scale,
          xsimd::to_float((packed >> 16) & Int(255)) * scale,
          xsimd::to_float(xsimd::bitwise_cast<Int>(xsimd::bitwise_cast<simd::UInt>(packed) >> 24)) * scale};
}

inline simd::Float4 unpack_srgb8(const Int& packed) {
  const float* table = kSrgbToLinear.data();
  return {Float::gather(table, packed & Int(255)), Float::gather(table, (packed >> 8) & Int(255)),
          Float::gather(table, (packed >> 16) & Int(255)),
          xsimd::to_float(xsimd::bitwise_cast<Int>(xsimd::bitwise_cast<simd::UInt>(packed) >> 24)) *
              Float(1.0f / 255.0f)};
}

inline Float blend_factor(BlendFactor f, const simd::Float4& src, const simd::Float4& dst,
                          const glm::vec4& constant, int channel) {
  auto ch = [channel](const simd::Float4& c) -> const Float& {
    return channel == 0 ? c.x : channel == 1 ? c.y : channel == 2 ? c.z : c.w;
  };
  const Float one(1.0f);
  switch (f) {
    case BlendFactor::Zero: return Float(0.0f);
    case BlendFactor::One: return one;
    case BlendFactor::SrcColor: return ch(src);
    case BlendFactor::InvSrcColor: return one - ch(src);
    case BlendFactor::SrcAlpha: return src.w;
    case BlendFactor::InvSrcAlpha: return one - src.w;
    case BlendFactor::DestAlpha: return dst.w;
    case BlendFactor::InvDestAlpha: return one - dst.w;
    case BlendFactor::DestColor: return ch(dst);
    case BlendFactor::InvDestColor: return one - ch(dst);
    case BlendFactor::SrcAlphaSat:
      return channel == 3 ? one : xsimd::min(src.w, one - dst.w);
    case BlendFactor::BlendFactor: return Float(constant[channel]);
    case BlendFactor::InvBlendFactor: return Float(1.0f - constant[channel]);
  }
  return one;
}

inline Float blend_op(BlendOp op, const Float& s, const Float& fs, const Float& d, const Float& fd) {
  switch (op) {
    case BlendOp::Add: return s * fs + d * fd;
    case BlendOp::Subtract: return s * fs - d * fd;
    case BlendOp::RevSubtract: return d * fd - s * fs;
    case BlendOp::Min: return xsimd::min(s, d);  // D3D: factors are ignored by min/max
    case BlendOp::Max: return xsimd::max(s, d);
  }
  return s;
}

/// Blends a (clamped) source color over a destination color.
inline simd::Float4 blend(const BlendState& b, const simd::Float4& src, const simd::Float4& dst) {
  simd::Float4 out;
  Float* o[4] = {&out.x, &out.y, &out.z, &out.w};
  const Float* s[4] = {&src.x, &src.y, &src.z, &src.w};
  const Float* d[4] = {&dst.x, &dst.y, &dst.z, &dst.w};
  for (int c = 0; c < 4; ++c) {
    const bool alpha = c == 3 && b.separate_alpha;
    const BlendFactor fs = alpha ? b.src_alpha : b.src, fd = alpha ? b.dst_alpha : b.dst;
    const BlendOp op = alpha ? b.op_alpha : b.op;
    *o[c] = blend_op(op, *s[c], blend_factor(fs, src, dst, b.blend_factor, c), *d[c],
                     blend_factor(fd, src, dst, b.blend_factor, c));
  }
  return out;
}

inline simd::Float4 saturate(const simd::Float4& c) {
  auto s = [](const Float& x) { return xsimd::min(xsimd::max(x, Float(0.0f)), Float(1.0f)); };
  return {s(c.x), s(c.y), s(c.z), s(c.w)};
}

}  // namespace luxel::rasterizer::detail
