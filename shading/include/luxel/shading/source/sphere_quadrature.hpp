#pragma once
// Radiance over the sphere as samples (direction, radiance, solid angle), and the irradiance they
// give: the ground truth the ambient cube, SH4 and SH9 are judged against (spherical_harmonics.hpp,
// `luxel report speed-error`).
//
// Samples come from a function on an equal-area grid (sample_sphere_grid) or from the pixels of an
// environment image with their solid angles (cli/report/environment_image.hpp). The irradiance of
// a set of samples is the quadrature E(n) = Σ L_i max(0, n·ω_i) Δω_i in double: each sample's
// radiance over its cell, the cosine taken at the cell's centre, so it converges with the cell
// size (the kink of max(0, ·) at the horizon costs most: 6e-4 of E for a uniform 64 x 32 image,
// under 5e-4 on the 192-row grid: sh9_test.cpp).
// Checked against closed forms (uniform radiance, a hemisphere, a linear radiance, a band-limited
// SH9 radiance through R&H's printed formula) in tests/shading/sphere_quadrature_test.cpp, which
// does not use the code it checks for its expected values.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace luxel::shading::source {

/// Radiance L arriving from `direction` (unit) over a solid angle (steradians).
struct RadianceSample {
  glm::dvec3 direction{0.0, 0.0, 1.0};
  glm::dvec3 radiance{0.0};
  double solid_angle = 0.0;
};

using SampledRadiance = std::vector<RadianceSample>;

/// Calls f(direction, solid angle) for the cells of an equal-area sphere grid: `rows` bands uniform
/// in z = cos θ (Archimedes: equal z-steps cut equal areas) × 2·rows steps in φ, each cell sampled
/// at its centre. Every cell has the same solid angle 4π / (2 rows²); a band edge lies on z = 0, so
/// hemispheres split exactly along cells.
template <class F>
inline void for_each_sphere_cell(int rows, F&& f) {
  const int cols = 2 * rows;
  const double d_omega = 4.0 * std::numbers::pi / (static_cast<double>(rows) * cols);
  for (int i = 0; i < rows; ++i) {
    const double z = 1.0 - (i + 0.5) * 2.0 / rows;
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int j = 0; j < cols; ++j) {
      const double phi = (j + 0.5) * 2.0 * std::numbers::pi / cols;
      f(glm::dvec3(s * std::cos(phi), s * std::sin(phi), z), d_omega);
    }
  }
}

/// A radiance function (unit dvec3 -> dvec3) sampled at the cells of the grid above.
template <class Radiance>
inline SampledRadiance sample_sphere_grid(Radiance&& radiance, int rows) {
  SampledRadiance samples;
  samples.reserve(static_cast<size_t>(rows) * 2 * static_cast<size_t>(rows));
  for_each_sphere_cell(rows, [&](const glm::dvec3& d, double d_omega) { samples.push_back({d, radiance(d), d_omega}); });
  return samples;
}

/// E(n) = Σ L_i max(0, n·ω_i) Δω_i for a unit normal n, in double.
inline glm::dvec3 irradiance(const SampledRadiance& samples, const glm::dvec3& n) {
  glm::dvec3 e(0.0);
  for (const RadianceSample& s : samples) {
    const double c = glm::dot(n, s.direction);
    if (c > 0.0) e += s.radiance * (c * s.solid_angle);
  }
  return e;
}

/// `count` unit normals spread evenly over the sphere (the Fibonacci lattice: equal steps in z,
/// the golden angle in φ), the same list for the same count.
inline std::vector<glm::dvec3> fibonacci_normals(int count) {
  std::vector<glm::dvec3> r;
  r.reserve(static_cast<size_t>(std::max(count, 0)));
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (i + 0.5) * 2.0 / count;
    const double s = std::sqrt(1.0 - z * z);
    r.emplace_back(s * std::cos(golden * i), s * std::sin(golden * i), z);
  }
  return r;
}

}  // namespace luxel::shading::source
