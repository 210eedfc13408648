// Mip generation (Texture::generate_mips): each level box-filtered from the one above it, per axis
// (texture.hpp, "Mip levels").

#include "luxel/rasterizer/texture.hpp"

#include "texture_internal.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace luxel::rasterizer {

using texture_detail::decode_texel;
using texture_detail::encode_texel;

// --- Mip generation ---------------------------------------------------------------------------

namespace {

/// Source texels and weights that make destination texel `i` along one axis (see the header).
struct AxisTaps {
  int count = 0;
  int index[3] = {};
  double weight[3] = {};
};

AxisTaps box_taps(int source_size, int i) {
  AxisTaps taps;
  if (source_size == 1) {
    taps.count = 1;
    taps.index[0] = 0;
    taps.weight[0] = 1.0;
  } else if (source_size % 2 == 0) {
    taps.count = 2;
    taps.index[0] = 2 * i;
    taps.index[1] = 2 * i + 1;
    taps.weight[0] = taps.weight[1] = 0.5;
  } else {
    const int m = source_size / 2;
    const double n = source_size;
    taps.count = 3;
    taps.index[0] = 2 * i;
    taps.index[1] = 2 * i + 1;
    taps.index[2] = 2 * i + 2;
    taps.weight[0] = (m - i) / n;
    taps.weight[1] = m / n;
    taps.weight[2] = (i + 1) / n;
  }
  return taps;
}

/// Decoder for mip generation: like decode_texel, but sRGB through the (exactly rounded) table
/// instead of three pow() per texel.
glm::dvec4 decode_for_mips(TextureFormat format, const uint8_t* t) {
  if (format == TextureFormat::RGBA8_sRGB) {
    const auto& table = kSrgbToLinear;
    return {table[t[0]], table[t[1]], table[t[2]], t[3] / 255.0};
  }
  return decode_texel(format, t);
}

}  // namespace

void Texture::generate_mips() {
  const size_t texel_bytes = static_cast<size_t>(bytes_per_texel(format_));
  std::vector<AxisTaps> taps_x, taps_y, taps_z;
  for (int face = 0; face < faces(); ++face) {
    for (int level = 1; level < levels_; ++level) {
      const auto source = level_bytes(level - 1, face);
      const auto destination = level_span(level, face);
      const int sw = width(level - 1), sh = height(level - 1), sd = depth(level - 1);
      const int dw = width(level), dh = height(level), dd = depth(level);
      taps_x.resize(dw);
      taps_y.resize(dh);
      taps_z.resize(dd);
      for (int i = 0; i < dw; ++i) taps_x[i] = box_taps(sw, i);
      for (int i = 0; i < dh; ++i) taps_y[i] = box_taps(sh, i);
      for (int i = 0; i < dd; ++i) taps_z[i] = box_taps(sd, i);
      for (int z = 0; z < dd; ++z) {
        for (int y = 0; y < dh; ++y) {
          for (int x = 0; x < dw; ++x) {
            glm::dvec4 sum(0.0);
            const AxisTaps &tz = taps_z[z], &ty = taps_y[y], &tx = taps_x[x];
            for (int c = 0; c < tz.count; ++c) {
              for (int b = 0; b < ty.count; ++b) {
                for (int a = 0; a < tx.count; ++a) {
                  const size_t index =
                      (static_cast<size_t>(tz.index[c]) * sh + ty.index[b]) * sw + tx.index[a];
                  sum += (tz.weight[c] * ty.weight[b] * tx.weight[a]) *
                         decode_for_mips(format_, source.data() + index * texel_bytes);
                }
              }
            }
            const size_t out = (static_cast<size_t>(z) * dh + y) * dw + x;
            encode_texel(format_, sum, destination.data() + out * texel_bytes);
          }
        }
      }
    }
  }
  for (int level = 1; level < levels_; ++level) {
    refresh_cube_copy(level, -1);
    for (int face = 0; face < faces(); ++face) set_level_opaque(level, face, alpha_at_max(level_bytes(level, face)));
  }
}

}  // namespace luxel::rasterizer
