#pragma once
// An 8-bit image shrunk by a whole factor, each pixel the rounded mean of the factor x factor
// block of pixels it covers: what the rasterizer's MSAA resolve (rasterizer/framebuffer.hpp) does
// with a pixel's samples, in the same space (the stored 8-bit values, sRGB-encoded where the
// shaders encoded them) and with the same rounding (half up). The msaa section's reference: a
// frame drawn factor times larger with one sample per pixel, box-filtered down.

#include "luxel/rasterizer/image.hpp"

namespace luxel::cli {

/// `image` (width and height multiples of `factor` >= 1, else std::invalid_argument) shrunk by
/// `factor`: each channel of each pixel floor((sum of the block's values + n / 2) / n), n = factor².
rasterizer::Image box_filter_down(const rasterizer::Image& image, int factor);

}  // namespace luxel::cli
