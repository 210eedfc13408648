#pragma once
// The bloom amount and its smoothing from frame to frame (docs/fidelity.md#bloom, GetBloomAmount in
// viewpostprocess.cpp): the vertical blur multiplies the bloom by it.
//
//   smoothed_t = scale * 0.05 + 0.95 * smoothed_{t-1}      (mat_bloomamount_rate 0.05; smoothed_0 = 1)
//   amount_t   = smoothed_t * (0.3 when the HDR type is NONE, else 1) * scalefactor_scalar
//
// scale is the env_tonemap_controller's custom bloom scale when set, else mat_bloomscale (1); 0.3
// is mat_non_hdr_bloom_scalefactor, scalefactor_scalar mat_bloom_scalefactor_scalar (1). The
// smoothing runs once per frame whatever the frame's duration, so it is frame-rate dependent, as
// in the SDK. A renderer keeps one BloomAmount per sequence and advances it once per frame.

#include "luxel/shading/source/hdr_type.hpp"

namespace luxel::postfx {

struct BloomAmount {
  static constexpr float kRate = 0.05f;            ///< mat_bloomamount_rate
  static constexpr float kNonHdrFactor = 0.3f;     ///< mat_non_hdr_bloom_scalefactor

  float smoothed = 1.0f;  ///< carried between frames

  /// One frame: moves the smoothed value toward `scale` and returns this frame's amount.
  float advance(float scale, shading::source::HdrType hdr, float scalefactor_scalar = 1.0f) {
    smoothed = scale * kRate + (1.0f - kRate) * smoothed;
    return smoothed * (hdr == shading::source::HdrType::none ? kNonHdrFactor : 1.0f) * scalefactor_scalar;
  }
};

}  // namespace luxel::postfx
