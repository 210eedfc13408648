#pragma once
// How far an ambient term (cube, SH4, SH9: E/π as the shader computes it) is from the true
// irradiance E over a set of normals: relative to E per normal and channel (max, mean, RMS), as a
// fraction of the brightest E, and in 8-bit steps on screen after FinalOutput's linear tone-map
// scale that puts the brightest true E/π at 1.0 and sRGB encoding (docs/fidelity.md#tone-mapping). The
// steps are what a viewer sees; the relative error is what R&H and Probulator report.
// Relative errors need E > 0 (any non-negative radiance that is not black over a hemisphere);
// a channel with E <= 0 makes them infinite.

#include "luxel/shading/source/common.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <vector>

namespace luxel::shading::source {

struct IrradianceError {
  double max_relative = 0.0;   ///< max over normals and channels of |ΔE| / E
  double mean_relative = 0.0;  ///< mean of the same
  double rms_relative = 0.0;   ///< root mean square of the same
  double max_of_peak = 0.0;    ///< max |ΔE| / the brightest E
  int max_steps = 0;           ///< 8-bit sRGB steps after the tone-map scale
};

/// `truth[i]`: E at normal i; `approx_over_pi[i]`: the approximation's E/π there (the shader's
/// units). The two lists have one entry per normal.
inline IrradianceError irradiance_error(const std::vector<glm::dvec3>& truth, const std::vector<glm::dvec3>& approx_over_pi) {
  constexpr double kPi = std::numbers::pi;
  double brightest = 0.0;
  for (const glm::dvec3& e : truth) brightest = std::max({brightest, e.x, e.y, e.z});
  const double tone_map = kPi / brightest;  // FinalOutput's linear scale: brightest E/π -> 1.0
  IrradianceError err;
  double sum = 0.0, sum_sq = 0.0;
  for (size_t i = 0; i < truth.size(); ++i) {
    const glm::dvec3 a = approx_over_pi[i] * kPi;
    for (int c = 0; c < 3; ++c) {
      const double diff = std::abs(a[c] - truth[i][c]);
      const double rel = truth[i][c] > 0.0 ? diff / truth[i][c] : HUGE_VAL;
      err.max_relative = std::max(err.max_relative, rel);
      err.max_of_peak = std::max(err.max_of_peak, diff / brightest);
      sum += rel;
      sum_sq += rel * rel;
      const int steps = std::abs(int(srgb8_reference(a[c] / kPi * tone_map)) - int(srgb8_reference(truth[i][c] / kPi * tone_map)));
      err.max_steps = std::max(err.max_steps, steps);
    }
  }
  const double n = 3.0 * static_cast<double>(truth.size());
  err.mean_relative = sum / n;
  err.rms_relative = std::sqrt(sum_sq / n);
  return err;
}

}  // namespace luxel::shading::source
