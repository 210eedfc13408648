#pragma once
// One linear HDR image from 8-bit images of the same view taken at several exposures: the classic
// exposure-bracket merge, as a capture into 8-bit targets needs it (frame/cubemaps.hpp).
//
// Each image holds, per channel, code = sRGB-encode(clamp(radiance x exposure, 0, 1)) rounded to
// 8 bits (what the Source shaders' tone-map epilogue writes at tone-map scale `exposure`). Per
// texel and channel, the merge is the weighted mean over the exposures of
//   decode(code) / exposure,
// weighted by how well exposed the sample is: weight(code) = code - kDarkCode for codes strictly
// between kDarkCode and 255, else 0. A code of 255 is clipped (the radiance may be anything above
// it), a code at or below kDarkCode holds too few steps to say much (half a step is 4 % of the
// value at code 16 and grows fast below); in between, the weight grows with the code about as
// the sample's precision does (sRGB's half step is 1.2 / (code + 14) of the value). Where no
// exposure has weight, the one whose code is nearest mid-range decides (the darkest exposure
// where all clip: a lower bound; the brightest where all are dark).

#include "luxel/rasterizer/image.hpp"

#include <glm/vec4.hpp>

#include <span>
#include <vector>

namespace luxel::frame {

inline constexpr int kDarkCode = 8;

/// The weight of a sample with 8-bit code `code` (above).
float exposure_weight(int code);

/// Merges `images` (one per exposure, all the same size) taken at tone-map scales `exposures`
/// into linear rgb (alpha 1), row-major as the images. Throws std::invalid_argument when the
/// counts differ, there is no image, the sizes differ or an exposure is not positive and finite.
std::vector<glm::vec4> merge_exposures(std::span<const rasterizer::Image> images, std::span<const float> exposures);

}  // namespace luxel::frame
