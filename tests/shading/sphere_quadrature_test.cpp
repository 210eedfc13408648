// The ground truth of `luxel report speed-error` and sh9_test.cpp (sphere_quadrature.hpp) against
// closed forms that do not go through it: a uniform sky (E = πL), a sky over one hemisphere
// (E = πL(1 + n·a)/2), a linear radiance 1 + ω·b (E = π + (2π/3) n·b), and a band-limited SH9
// radiance, whose irradiance R&H's formula gives exactly, written out here with the paper's printed
// constants c1..c5. Then SH4 and SH9 as the shader evaluates them (float lanes) against the same
// printed formula in double, the SH4 count, and irradiance_error on numbers worked by hand.

#include "luxel/shading/cost.hpp"
#include "luxel/shading/source/irradiance_error.hpp"
#include "luxel/shading/source/ramamoorthi2001.hpp"
#include "luxel/shading/source/sphere_quadrature.hpp"
#include "luxel/shading/source/spherical_harmonics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace luxel::shading::source {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kRows = 96;  // 96 x 192 cells: the closed forms hold to 1e-3 there, in milliseconds

/// R&H 2001 eq. 13 with the printed constants: E(n) from radiance coefficients L (paper order).
glm::dvec3 paper_irradiance(const std::array<glm::dvec3, 9>& l, const glm::dvec3& n) {
  const double x = n.x, y = n.y, z = n.z;
  return kPaperC1 * l[8] * (x * x - y * y) + kPaperC3 * l[6] * z * z + kPaperC4 * l[0] - kPaperC5 * l[6] +
         2.0 * kPaperC1 * (l[4] * x * y + l[7] * x * z + l[5] * y * z) + 2.0 * kPaperC2 * (l[3] * x + l[1] * y + l[2] * z);
}

/// The same cut after band 1.
glm::dvec3 paper_irradiance_band1(const std::array<glm::dvec3, 9>& l, const glm::dvec3& n) {
  return kPaperC4 * l[0] + 2.0 * kPaperC2 * (l[3] * n.x + l[1] * n.y + l[2] * n.z);
}

float3<float> lane(const glm::dvec3& n) { return {float(n.x), float(n.y), float(n.z)}; }

TEST(SphereQuadrature, UniformRadianceGivesPiL) {
  const SampledRadiance sky = sample_sphere_grid([](const glm::dvec3&) { return glm::dvec3(2.0, 1.0, 0.5); }, kRows);
  double total = 0.0;
  for (const RadianceSample& s : sky) total += s.solid_angle;
  EXPECT_NEAR(total, 4.0 * kPi, 1e-9);
  for (const glm::dvec3& n : fibonacci_normals(50)) {
    const glm::dvec3 e = irradiance(sky, n);
    EXPECT_NEAR(e.x, 2.0 * kPi, 2e-3 * kPi);
    EXPECT_NEAR(e.z, 0.5 * kPi, 5e-4 * kPi);
  }
}

TEST(SphereQuadrature, UpperHemisphereGivesItsClosedForm) {
  // Radiance 1 over z > 0, nothing below: E(n) = π (1 + n_z) / 2.
  const SampledRadiance sky = sample_sphere_grid([](const glm::dvec3& d) { return glm::dvec3(d.z > 0.0 ? 1.0 : 0.0); }, kRows);
  for (const glm::dvec3& n : fibonacci_normals(200)) EXPECT_NEAR(irradiance(sky, n).x, kPi * (1.0 + n.z) / 2.0, 1e-3);
}

TEST(SphereQuadrature, LinearRadianceGivesItsClosedForm) {
  // ∫ (1 + ω·b) max(0, n·ω) dω = π + (2π/3) n·b.
  const glm::dvec3 b(0.3, -0.5, 0.2);
  const SampledRadiance env = sample_sphere_grid([&](const glm::dvec3& d) { return glm::dvec3(1.0 + glm::dot(d, b)); }, kRows);
  for (const glm::dvec3& n : fibonacci_normals(200))
    EXPECT_NEAR(irradiance(env, n).x, kPi + 2.0 * kPi / 3.0 * glm::dot(n, b), 2e-3);
}

TEST(SphereQuadrature, BandLimitedRadianceGivesThePapersIrradiance) {
  for (const PublishedProbe& p : kRamamoorthi2001Probes) {
    const Sh9 radiance = published_radiance(p);
    const SampledRadiance env = sample_sphere_grid([&](const glm::dvec3& d) { return evaluate(radiance, d); }, kRows);
    for (const glm::dvec3& n : fibonacci_normals(100)) {
      const glm::dvec3 e = irradiance(env, n), expected = paper_irradiance(p.radiance, n);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], expected[c], 2e-3) << p.name << " channel " << c;
    }
  }
}

TEST(SphereQuadrature, ShaderSh9AndSh4FollowThePapersFormula) {
  // The shader's float evaluation of R&H's coefficients against eq. 13 in double (and its band-1
  // cut for SH4); the paper's 6-digit constants and float32 leave ~1e-6 of E.
  for (const PublishedProbe& p : kRamamoorthi2001Probes) {
    const Sh9 e = convolve_cosine(published_radiance(p));
    const Sh9Ambient sh9 = sh9_ambient_constants(e);
    const Sh4Ambient sh4 = sh4_ambient_constants(e);
    for (const glm::dvec3& n : fibonacci_normals(100)) {
      const float3<float> a9 = sh9_ambient_light<float>(lane(n), sh9), a4 = sh4_ambient_light<float>(lane(n), sh4);
      const glm::dvec3 e9 = paper_irradiance(p.radiance, n), e4 = paper_irradiance_band1(p.radiance, n);
      EXPECT_NEAR(a9.x * kPi, e9.x, 1e-5) << p.name;
      EXPECT_NEAR(a9.z * kPi, e9.z, 1e-5) << p.name;
      EXPECT_NEAR(a4.x * kPi, e4.x, 1e-5) << p.name;
      EXPECT_NEAR(a4.y * kPi, e4.y, 1e-5) << p.name;
    }
  }
}

TEST(SphereQuadrature, Sh4CostsThreeSlotsAndFourRegisters) {
  const Sh4Ambient sh4{};
  const Cost c = measure(ShaderModel::ps_3_0, [&](CountedInputs& in) { return sh4_ambient_light<Counted>(in.vector<3>(), sh4); });
  EXPECT_EQ(c.arithmetic_slots, 3);  // three mads (ps_2_0 adds the mov to oC0, as for the cube)
  EXPECT_EQ(c.uniform_registers, 4);
}

TEST(SphereQuadrature, CubeFitWeighsSamplesByTheirSolidAngles) {
  // Worked by hand: radiance 1 from +x over 1 sr, radiance 4 from 60° toward +y over 0.5 sr.
  // Side +x: (1·1·1 + 4·cos 60°·0.5) / (1·1 + cos 60°·0.5) = 2 / 1.25; side +y: 4, the one sample it sees.
  const SampledRadiance samples = {{glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(1.0), 1.0},
                                   {glm::dvec3(0.5, std::sqrt(0.75), 0.0), glm::dvec3(4.0), 0.5}};
  const AmbientCube cube = fit_ambient_cube(samples);
  EXPECT_NEAR(cube.color[0].x, 1.6, 1e-6);
  EXPECT_NEAR(cube.color[2].x, 4.0, 1e-6);
}

TEST(IrradianceError, WorkedByHand) {
  // Two normals, E = π and 2π per channel; the approximation is 10 % high on the first, exact on the second.
  const std::vector<glm::dvec3> truth = {glm::dvec3(kPi), glm::dvec3(2.0 * kPi)};
  const std::vector<glm::dvec3> approx = {glm::dvec3(1.1), glm::dvec3(2.0)};
  const IrradianceError e = irradiance_error(truth, approx);
  EXPECT_NEAR(e.max_relative, 0.1, 1e-12);
  EXPECT_NEAR(e.mean_relative, 0.05, 1e-12);
  EXPECT_NEAR(e.rms_relative, std::sqrt(0.01 / 2.0), 1e-12);
  EXPECT_NEAR(e.max_of_peak, 0.1 * kPi / (2.0 * kPi), 1e-12);
  // Tone map: 2 -> 1.0, so 1.0 -> 0.5 and 1.1 -> 0.55: sRGB 188 against 196.
  EXPECT_EQ(e.max_steps, 196 - 188);
}

}  // namespace
}  // namespace luxel::shading::source
