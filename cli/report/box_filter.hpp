#pragma once
// An 8-bit image shrunk by a whole factor, each pixel the mean of the factor x factor block of
// pixels it covers, in one of two spaces:
//  - stored: the rounded mean of the stored 8-bit values (sRGB-encoded where the shaders encoded
//    them), what the rasterizer's MSAA resolve (rasterizer/framebuffer.hpp) does with a pixel's
//    samples, with the same rounding (half up);
//  - linear light: each color byte decoded as sRGB (rasterizer/srgb.hpp), averaged in double and
//    encoded again, rounded to nearest; alpha as stored. What a resolve of a float target would do.
// The msaa section's references: a frame drawn factor times larger with one sample per pixel,
// box-filtered down.

#include "luxel/rasterizer/image.hpp"

namespace luxel::cli {

enum class BoxSpace { stored, linear_light };

/// `image` (width and height multiples of `factor` >= 1, else std::invalid_argument) shrunk by
/// `factor`. Stored: each channel of each pixel floor((sum of the block's values + n / 2) / n),
/// n = factor². Linear light: each color channel round(255 encode(mean of decode(v / 255))).
rasterizer::Image box_filter_down(const rasterizer::Image& image, int factor, BoxSpace space = BoxSpace::stored);

}  // namespace luxel::cli
