// ImageDifference through OpenImageIO's ImageBufAlgo::compare, the function idiff calls, so that
// the numbers mean what idiff's do by construction (image_difference.hpp).

#include "luxel/frame/image_difference.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace luxel::frame {

namespace {

// idiff's default -fail and -warn thresholds: any difference of one 8-bit step (1/255) is over.
constexpr float kIdiffThreshold = 1.0e-6f;

void check_same_size(const rasterizer::Image& a, const rasterizer::Image& b) {
  if (a.width <= 0 || a.height <= 0 || a.width != b.width || a.height != b.height)
    throw std::invalid_argument("image difference: sizes " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                " and " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                                " (both must be the same, nonzero)");
}

/// A read-only view of an RGBA8 image as an ImageBuf (no copy). compare() reads through it.
OIIO::ImageBuf wrap(const rasterizer::Image& image) {
  const OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  return OIIO::ImageBuf(spec, const_cast<uint8_t*>(image.rgba.data()));
}

struct Stop {
  int steps;
  std::array<uint8_t, 3> colour;
};

constexpr Stop kRamp[] = {
    {0, {0, 0, 0}},      {1, {0, 0, 128}},     {2, {0, 64, 255}},  {4, {0, 200, 255}},   {8, {0, 255, 0}},
    {16, {255, 255, 0}}, {32, {255, 128, 0}},  {64, {255, 0, 0}},  {128, {255, 255, 255}},
};
static_assert(std::size(kRamp) == kHeatStops.size());

}  // namespace

ImageDifference image_difference(const rasterizer::Image& a, const rasterizer::Image& b) {
  check_same_size(a, b);
  // No relative thresholds (idiff's default -failrelative / -warnrelative 0). One thread:
  // OpenImageIO sums per thread and then adds the partial sums, so more threads could change the
  // last bits of the mean from run to run. (CompareResults::error only says that some value was
  // over the threshold; a failed comparison leaves its message on the images.)
  const OIIO::ImageBuf image_a = wrap(a), image_b = wrap(b);
  const OIIO::ImageBufAlgo::CompareResults r = OIIO::ImageBufAlgo::compare(
      image_a, image_b, kIdiffThreshold, kIdiffThreshold, 0.0f, 0.0f, OIIO::ROI(), /*nthreads=*/1);
  if (image_a.has_error() || image_b.has_error())
    throw std::runtime_error("image difference: " + image_a.geterror() + image_b.geterror());
  ImageDifference d;
  d.pixels = uint64_t(a.width) * uint64_t(a.height);
  d.differing_pixels = r.nfail;
  d.rms_error = r.rms_error;
  d.psnr_db = r.PSNR;  // +infinity for RMS 0
  d.max_error = static_cast<int>(std::lround(r.maxerror * 255.0));
  d.mean_error = r.meanerror * 255.0;
  return d;
}

std::array<uint8_t, 3> heat_colour(int steps) {
  steps = std::max(steps, 0);
  if (steps >= kRamp[std::size(kRamp) - 1].steps) return kRamp[std::size(kRamp) - 1].colour;
  size_t i = 0;
  while (kRamp[i + 1].steps <= steps) ++i;
  const Stop& lo = kRamp[i];
  const Stop& hi = kRamp[i + 1];
  const int span = hi.steps - lo.steps, t = steps - lo.steps;
  std::array<uint8_t, 3> c;
  for (int k = 0; k < 3; ++k)  // integer lerp, rounded to nearest: the same bytes everywhere
    c[k] = static_cast<uint8_t>((lo.colour[k] * (span - t) + hi.colour[k] * t + span / 2) / span);
  return c;
}

rasterizer::Image difference_heat_map(const rasterizer::Image& a, const rasterizer::Image& b) {
  check_same_size(a, b);
  rasterizer::Image heat(a.width, a.height);
  for (size_t p = 0; p < a.rgba.size(); p += 4) {
    int largest = 0;
    for (size_t c = 0; c < 4; ++c) largest = std::max(largest, std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])));
    const std::array<uint8_t, 3> colour = heat_colour(largest);
    std::copy(colour.begin(), colour.end(), heat.rgba.begin() + p);
    heat.rgba[p + 3] = 255;
  }
  return heat;
}

}  // namespace luxel::frame
