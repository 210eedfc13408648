#pragma once
// How far apart two 8-bit RGBA frames are: the numbers `luxel compare` reports per pair of shader
// models (and the speed-vs-error report will), and a heat map that shows where.
//
// The numbers mean exactly what OpenImageIO's `idiff A B` prints, because they are computed by
// the function idiff itself calls (ImageBufAlgo::compare, OpenImageIO 2.4), with idiff's default
// thresholds (1e-6). Channel values are read as idiff reads an 8-bit file: v / 255 in [0, 1], and
// ALL FOUR channels count, alpha included, as idiff counts every channel of the file. With e_i the
// absolute difference of value i of N = pixels x 4 values:
//
//   mean error  = sum(e_i) / N                     (idiff: "Mean error")
//   RMS error   = sqrt(sum(e_i^2) / N)             (idiff: "RMS error")
//   PSNR        = 20 log10(1 / RMS) decibels       (idiff: "Peak SNR"; peak = 1.0, full scale)
//   max error   = max(e_i)                         (idiff: "Max error")
//   differing   = pixels in which any channel differs by more than 1e-6, i.e. by at least one
//                 8-bit step                       (idiff: "N pixels (P%) over 1e-06")
//
// ImageDifference gives mean and max error scaled to 8-bit steps (x 255): a max error of 3 means
// some channel of some pixel is 3 steps off. Identical images have RMS 0: their PSNR is +infinity
// (idiff prints only "PASS" for them). Because alpha counts, an image whose alpha is 255
// everywhere in both frames has its mean error diluted by 3/4 against an RGB-only mean, as idiff's.
//
// Values are compared as stored (straight alpha). idiff run on the two images written as PNG files
// agrees wherever alpha is 255; where it is lower, OpenImageIO reads the file's colour premultiplied
// by alpha, so idiff compares other colour values there. (The Source frame leaves alpha below 255
// in a few pixels: 467 of 230400 in builtin:courtyard at 640x360.)
//
// The numbers are computed on one thread in a fixed order, so they are the same on every run.

#include "luxel/rasterizer/image.hpp"

#include <array>
#include <cstdint>

namespace luxel::frame {

struct ImageDifference {
  double psnr_db = 0;             ///< 20 log10(1 / RMS error), RMS on [0, 1] values; +infinity when identical
  double rms_error = 0;           ///< on [0, 1] values, as idiff prints it
  int max_error = 0;              ///< largest channel difference, in 8-bit steps (0..255)
  double mean_error = 0;          ///< mean channel difference over all pixels and 4 channels, in 8-bit steps
  uint64_t pixels = 0;            ///< width x height
  uint64_t differing_pixels = 0;  ///< pixels with any channel (alpha included) differing

  /// differing_pixels / pixels, in [0, 1] (idiff prints it as a percentage).
  double differing_share() const { return pixels ? double(differing_pixels) / double(pixels) : 0.0; }
  bool identical() const { return differing_pixels == 0; }
};

/// Compares `a` and `b`, which must have the same nonzero size (else std::invalid_argument).
ImageDifference image_difference(const rasterizer::Image& a, const rasterizer::Image& b);

/// The heat map's colour for a difference of `steps` 8-bit steps (negative is taken as 0). A fixed
/// ramp, doubling per stop so that a 1-step difference is as visible as a 100-step one:
///
///   steps   0      1          2      4      8      16      32      64     >= 128
///   colour  black  dark blue  blue   cyan   green  yellow  orange  red    white
///
/// linear in `steps` between stops (rounded to nearest), so every step count has its own shade.
std::array<uint8_t, 3> heat_colour(int steps);

/// The stops of heat_colour's ramp, in steps, for a legend.
inline constexpr std::array<int, 9> kHeatStops = {0, 1, 2, 4, 8, 16, 32, 64, 128};

/// Per pixel, the largest channel difference between `a` and `b` (alpha included, as
/// image_difference counts it) through heat_colour; opaque. Same size rules as image_difference.
rasterizer::Image difference_heat_map(const rasterizer::Image& a, const rasterizer::Image& b);

}  // namespace luxel::frame
