#pragma once
// Multisampling conventions.
//
// D3D9 left MSAA sample patterns to vendors; luxel uses the D3D10.1 standard patterns. Offsets
// are in 1/16 pixel from the pixel center, x to the right and y down, and are listed in sample
// order (sample s of a pixel is stored in plane s of the target).

#include <cstdint>

namespace luxel::rasterizer {

struct SampleOffset {
  int8_t x, y;  ///< 1/16 pixel, relative to the pixel center
};

/// True for the supported sample counts: 1, 2, 4 and 8.
constexpr bool is_valid_sample_count(int samples) {
  return samples == 1 || samples == 2 || samples == 4 || samples == 8;
}

namespace detail {
inline constexpr SampleOffset kSamples1[1] = {{0, 0}};
inline constexpr SampleOffset kSamples2[2] = {{4, 4}, {-4, -4}};
inline constexpr SampleOffset kSamples4[4] = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
inline constexpr SampleOffset kSamples8[8] = {{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
}  // namespace detail

/// The D3D10.1 standard sample positions for 1, 2, 4 and 8 samples (nullptr for other counts).
constexpr const SampleOffset* standard_sample_offsets(int samples) {
  switch (samples) {
    case 1: return detail::kSamples1;
    case 2: return detail::kSamples2;
    case 4: return detail::kSamples4;
    case 8: return detail::kSamples8;
    default: return nullptr;
  }
}

/// Sample position inside its pixel in subpixels (1/256 pixel) from the pixel's top-left corner.
/// The pixel center is at (128, 128); every standard position lies in [0, 240].
constexpr int sample_subpixel(int8_t offset16) { return 128 + 16 * offset16; }

}  // namespace luxel::rasterizer
