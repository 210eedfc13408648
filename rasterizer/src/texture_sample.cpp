// The public entry points of texture sampling: they pick the rule set (Sampler::rules), the
// one-level reads of the post passes, and the LOD of a sample() (texture_sample_impl.hpp, with
// the stage headers it includes, holds the filtering).

#include "luxel/rasterizer/texture.hpp"

#include "texture_sample_impl.hpp"

#include <span>
#include <stdexcept>
#include <string>

namespace luxel::rasterizer {

namespace texture_sampling {
template struct Sampling<HardwareRules>;
}  // namespace texture_sampling

namespace {

using simd::Float;
using simd::Float4;
using simd::FloatMask;
using texture_sampling::HardwareRules;
using texture_sampling::IdealRules;
using texture_sampling::Sampling;

/// Whether no LOD changes what `sampler` returns: one filter on both sides of the crossover and
/// level 0 only.
bool reads_one_level(const Sampler& sampler) { return sampler.mip == MipFilter::None && sampler.min == sampler.mag; }

bool hardware(const Sampler& sampler) { return sampler.rules == SamplingRules::hardware; }

/// Whether a one-level read gives the same bits by either rule set: a point read weighs nothing
/// and blends nothing, and only a border color is treated differently. The ideal rules' path then
/// serves it: it decodes an sRGB texel from the gathered word, where the hardware rules' decodes
/// the byte it would have filtered.
bool point_without_border(const Texture& texture, const Sampler& sampler) {
  return sampler.mag == Filter::Point && !texture_sampling::reads_border(texture, sampler);
}

Float4 sample_one_level(const Texture& texture, const Sampler& sampler, const TexCoord& coord) {
  return hardware(sampler) && !point_without_border(texture, sampler) ? Sampling<HardwareRules>::one_level(texture, sampler, coord)
                                                                      : Sampling<IdealRules>::one_level(texture, sampler, coord);
}

/// sample() of a sampler with a LOD to compute: out of line, so that the one-level reads of
/// sample() need none of its stack (the post passes' reads, several per pixel).
[[gnu::noinline]] Float4 sample_at_computed_lod(const Texture& texture, const Sampler& sampler, const TexCoord& coord,
                                                const Float& bias) {
  const bool has_w = texture.kind() != TextureKind::Texture2D;
  const Float zero(0.0f);
  const TexCoord dx{simd::ddx(coord.x), simd::ddx(coord.y), has_w ? simd::ddx(coord.z) : zero};
  const TexCoord dy{simd::ddy(coord.x), simd::ddy(coord.y), has_w ? simd::ddy(coord.z) : zero};
  Float lod = compute_lod(texture, coord, dx, dy);
  // The hardware rules: one LOD per quad, its top-left pixel's (the same for every pixel of a 2D
  // or volume quad, whose derivatives are the quad's; a cube map's differs per pixel with the
  // direction). The shader's bias stays per pixel.
  if (hardware(sampler)) lod = simd::quad_corner<0>(lod);
  return sample_level(texture, sampler, coord, lod + bias);
}

}  // namespace

Float4 sample_level(const Texture& texture, const Sampler& sampler, const TexCoord& coord, const Float& lod) {
  if (reads_one_level(sampler)) return sample_one_level(texture, sampler, coord);
  return hardware(sampler) ? Sampling<HardwareRules>::at_level(texture, sampler, coord, lod)
                           : Sampling<IdealRules>::at_level(texture, sampler, coord, lod);
}

Float compute_lod(const Texture& texture, const TexCoord& c, const TexCoord& dx, const TexCoord& dy) {
  Float rho2;
  if (texture.kind() == TextureKind::Cube) {
    // d(sc/|ma|) = (d sc - (sc/|ma|) d|ma|) / |ma|; signs do not matter for lengths, so sc and tc
    // are taken without their per-face signs (consistently with their derivatives).
    const Float ax = xsimd::abs(c.x), ay = xsimd::abs(c.y), az = xsimd::abs(c.z);
    const FloatMask on_z = (az >= ax) & (az >= ay);
    const FloatMask on_y = (!on_z) & (ay >= ax);
    auto pick = [&](const Float& x, const Float& y, const Float& z) {
      return xsimd::select(on_z, z, xsimd::select(on_y, y, x));
    };
    const Float ma = pick(c.x, c.y, c.z);
    const Float m = xsimd::abs(ma);
    const Float sign = xsimd::select(ma < Float(0.0f), Float(-1.0f), Float(1.0f));
    const Float s = pick(c.z, c.x, c.x) / m, t = pick(c.y, c.z, c.y) / m;
    // Face coordinates run over [0, 1] where sc/|ma| runs over [-1, 1]: texels per unit of s are n/2.
    const Float scale = Float(0.5f * static_cast<float>(texture.width())) / m;
    auto length2 = [&](const TexCoord& d) {
      const Float dm = sign * pick(d.x, d.y, d.z);
      const Float ds = (pick(d.z, d.x, d.x) - s * dm) * scale;
      const Float dt = (pick(d.y, d.z, d.y) - t * dm) * scale;
      return ds * ds + dt * dt;
    };
    rho2 = xsimd::max(length2(dx), length2(dy));
  } else {
    const Float w(static_cast<float>(texture.width())), h(static_cast<float>(texture.height()));
    auto length2 = [&](const TexCoord& d) {
      const Float du = d.x * w, dv = d.y * h;
      Float sum = du * du + dv * dv;
      if (texture.kind() == TextureKind::Volume) {
        const Float dw = d.z * Float(static_cast<float>(texture.depth()));
        sum = sum + dw * dw;
      }
      return sum;
    };
    rho2 = xsimd::max(length2(dx), length2(dy));
  }
  return Float(0.5f) * texture_sampling::lod_log2(rho2);
}

Float4 sample_grad(const Texture& texture, const Sampler& sampler, const TexCoord& coord, const TexCoord& ddx,
                   const TexCoord& ddy) {
  return sample_level(texture, sampler, coord, compute_lod(texture, coord, ddx, ddy));
}

void sample_taps(const Texture& texture, const Sampler& sampler, std::span<const TexCoord> coords, std::span<Float4> out) {
  if (out.size() != coords.size())
    throw std::invalid_argument("sample_taps: " + std::to_string(coords.size()) + " coordinates for " +
                                std::to_string(out.size()) + " results");
  if (texture.kind() == TextureKind::Texture2D && reads_one_level(sampler)) {
    return hardware(sampler) && !point_without_border(texture, sampler) ? Sampling<HardwareRules>::taps(texture, sampler, coords, out)
                                                                        : Sampling<IdealRules>::taps(texture, sampler, coords, out);
  }
  for (size_t k = 0; k < coords.size(); ++k) out[k] = sample(texture, sampler, coords[k]);
}

Float4 sample(const Texture& texture, const Sampler& sampler, const TexCoord& coord, const Float& bias) {
  if (reads_one_level(sampler)) return sample_one_level(texture, sampler, coord);
  return sample_at_computed_lod(texture, sampler, coord, bias);
}

}  // namespace luxel::rasterizer
