#pragma once
// The nine RGB radiance coefficients L_lm of three of Paul Debevec's light probes, published in
// R. Ramamoorthi, P. Hanrahan, "An Efficient Representation for Irradiance Environment Maps",
// SIGGRAPH 2001, pp. 497-500, doi:10.1145/383259.383317 (Table 1, two decimals there).
//
// Numbers with more digits, as circulated in public code reproducing the table (drojdjou/
// squareroot.js, html/src/glsl/light/sphar-{cathedral,eucalyptus,st-peter}.glsl); every value
// rounds to the paper's two-decimal table (cross-checked against xufive/wxgl, wxgl/light.py),
// and the Grace Cathedral column was re-derived from the probe image up to an exposure factor.
// Numeric data, cited as facts. Row order and basis: spherical_harmonics.hpp (the paper's).
// Frame: +x toward the probe image's right, +y up, +z the direction seen at the image's centre
// (the frame of the paper's angular-map probes).
//
// `luxel report speed-error` and tests/shading/sh9_test.cpp use them as environments, and the
// report compares the first with its own projection of grace_probe.hdr.

#include "luxel/shading/source/spherical_harmonics.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>

namespace luxel::shading::source {

struct PublishedProbe {
  const char* name;
  std::array<glm::dvec3, 9> radiance;  ///< L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22
};

inline const PublishedProbe kRamamoorthi2001Probes[] = {
    {"Grace Cathedral",
     {glm::dvec3(0.78908, 0.43710, 0.54161), glm::dvec3(0.39499, 0.34989, 0.60488),
      glm::dvec3(-0.33974, -0.18236, -0.26940), glm::dvec3(-0.29213, -0.05562, 0.00944),
      glm::dvec3(-0.11141, -0.05090, -0.12231), glm::dvec3(-0.26240, -0.22401, -0.47479),
      glm::dvec3(-0.15570, -0.09471, -0.14733), glm::dvec3(0.56014, 0.21444, 0.13915),
      glm::dvec3(0.21205, -0.05432, -0.30374)}},
    {"Eucalyptus Grove",
     {glm::dvec3(0.3783264, 0.4260425, 0.4504587), glm::dvec3(0.2887813, 0.3586803, 0.4147053),
      glm::dvec3(0.0379030, 0.0295216, 0.0098567), glm::dvec3(-0.1033028, -0.1031690, -0.0884924),
      glm::dvec3(-0.0621750, -0.0554432, -0.0396779), glm::dvec3(0.0077820, -0.0148312, -0.0471301),
      glm::dvec3(-0.0935561, -0.1254260, -0.1525629), glm::dvec3(-0.0572703, -0.0502192, -0.0363410),
      glm::dvec3(0.0203348, -0.0044201, -0.0452180)}},
    {"St. Peter's Basilica",
     {glm::dvec3(0.3623915, 0.2624130, 0.2326261), glm::dvec3(0.1759130, 0.1436267, 0.1260569),
      glm::dvec3(-0.0247311, -0.0101253, -0.0010745), glm::dvec3(0.0346500, 0.0223184, 0.0101350),
      glm::dvec3(0.0198140, 0.0144073, 0.0043987), glm::dvec3(-0.0469596, -0.0254485, -0.0117786),
      glm::dvec3(-0.0898667, -0.0760911, -0.0740964), glm::dvec3(0.0050194, 0.0038841, 0.0001374),
      glm::dvec3(-0.0818750, -0.0321501, 0.0033399)}},
};

/// The paper's constants of the irradiance formula (its eq. 13), as printed.
inline constexpr double kPaperC1 = 0.429043, kPaperC2 = 0.511664, kPaperC3 = 0.743125, kPaperC4 = 0.886227,
                        kPaperC5 = 0.247708;

/// A published probe's radiance coefficients as an Sh9.
inline Sh9 published_radiance(const PublishedProbe& probe) {
  Sh9 sh;
  for (size_t i = 0; i < 9; ++i) sh.c[i] = probe.radiance[i];
  return sh;
}

/// A published probe as an environment: its SH9 radiance dips below 0 in places (ringing), and
/// then so does its irradiance for a few normals, where a relative error means nothing. Lifted by
/// a constant (band 0: still band-limited) until its least radiance (over a 64-row grid) is a tenth
/// of its mean.
inline Sh9 physical_radiance(const Sh9& sh) {
  glm::dvec3 least(1e30);
  for_each_sphere_cell(64, [&](const glm::dvec3& d, double) { least = glm::min(least, evaluate(sh, d)); });
  const glm::dvec3 mean = sh.c[0] * Sh9Norm::y00;  // L00 = ∫ L Y00 = Y00 · 4π · mean, Y00² = 1/(4π)
  Sh9 lifted = sh;
  lifted.c[0] += (glm::max(-least, glm::dvec3(0.0)) + mean * 0.1) / Sh9Norm::y00;
  return lifted;
}

}  // namespace luxel::shading::source
