#pragma once
// The engine's color-correction LUT (docs/fidelity.md#color-correction): a 32x32x32 lattice of
// color24 entries, gamma-space 8-bit in and out. Entry (r, g, b) holds what the color (r/31, g/31,
// b/31) becomes: the shader's coordinates (uvw = c * 31/32 + 0.5/32) put c = i/31 on texel center i,
// and the volume is filtered trilinearly in between. Other sizes N (c = i/(N-1), uvw = c (N-1)/N +
// 0.5/N) are luxel's, to measure what the engine's 32 costs against smaller and larger lattices.
//
// Entries are stored red fastest, index r + 32 g + 1024 b: the bit layout of the RGBX5551 key.
// The engine's .raw loader is closed, so that order is an inference; it is also the
// rasterizer's volume layout (x fastest, then y, then slices), so the entries upload as they are.

#include "luxel/postfx/color_transform.hpp"
#include "luxel/rasterizer/texture.hpp"
#include "luxel/shading/source/color_correction.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace luxel::postfx {

/// Lattice points per axis: the engine's.
inline constexpr int kLutSize = shading::source::kColorCorrectionLutSize;
inline constexpr int kLutEntries = kLutSize * kLutSize * kLutSize;
/// The sizes a Lut may have: 2 (the least that interpolates) to 64.
inline constexpr int kMinLutSize = 2, kMaxLutSize = 64;

/// The color of lattice index i along an axis of `size` points: i / (size - 1).
inline float lattice_color(int i, int size = kLutSize) { return static_cast<float>(i) / static_cast<float>(size - 1); }

struct Lut {
  using Color24 = std::array<uint8_t, 3>;
  int size = kLutSize;  ///< points per axis
  std::vector<Color24> entries = std::vector<Color24>(kLutEntries);  ///< index r + size g + size^2 b

  /// A LUT of `size` points per axis, entries black. Throws std::invalid_argument outside
  /// kMinLutSize..kMaxLutSize.
  static Lut of_size(int size);
  Color24& at(int r, int g, int b) { return entries[static_cast<size_t>((b * size + g) * size + r)]; }
  const Color24& at(int r, int g, int b) const { return entries[static_cast<size_t>((b * size + g) * size + r)]; }
  bool operator==(const Lut&) const = default;

  /// Every entry holds its own lattice color, rounded to 8 bits.
  static Lut identity(int size = kLutSize);
};

/// One 8-bit channel of a float: round(saturate(x) * 255), NaN -> 0.
uint8_t to_unorm8(float x);

/// The transform evaluated at every point of a `size`^3 lattice, each channel rounded with
/// to_unorm8. Throws std::invalid_argument for a size Lut::of_size refuses.
Lut sample_lut(const ColorTransform& transform, int size = kLutSize);

/// `lut` followed by `then`: each entry (over 255) transformed, rounded with to_unorm8. What a
/// look blended on top of a scene's node does to that node (frame/look.hpp).
Lut compose(const Lut& lut, const ColorTransform& then);

/// The LUT as the shader's volume texture: size^3 RGBA8 (alpha 255), one mip level, texel
/// (r, g, b) = entry (r, g, b), read without sRGB decode.
rasterizer::Texture lut_volume(const Lut& lut);

}  // namespace luxel::postfx
