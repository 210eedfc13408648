// SH9 ambient (spherical_harmonics.hpp) against ground-truth irradiance, beside the ambient cube.
//
// Ground truth: E(n) = ∫ L(ω) max(0, n·ω) dω by quadrature in double (sphere_quadrature.hpp on an
// equal-area grid, 192 x 384 cells; checked against closed forms in sphere_quadrature_test.cpp,
// and here against a grid twice as fine) for
// radiance environments made here: a sky over ground, the same with a small bright sun, strong
// directional colours, and the three light probes of Ramamoorthi & Hanrahan 2001 rebuilt from
// their published coefficients (band-limited, so SH9 must match them to quadrature accuracy: the
// sharp test of the cosine-lobe constants). Each environment is fitted the two ways — the cube
// as VRAD fills it (docs/fidelity.md#irradiance-volume-and-lights, dense-ray limit), SH9 by projection
// and the cosine convolution — and both are evaluated with the shader's own float code over 1,000
// normals. Errors (irradiance_error.hpp): relative to E per channel (max, RMS), and in 8-bit steps
// after FinalOutput's linear tone-map scale (brightest true value -> 1.0) and sRGB encoding.
// Also: the basis and constants against the paper's, the cube read as SH9, and the cost of both
// in DX9 slots and registers (and why the combo is ps_3_0 only).

#include "luxel/shading/cost.hpp"
#include "luxel/shading/source/irradiance_error.hpp"
#include "luxel/shading/source/ramamoorthi2001.hpp"
#include "luxel/shading/source/sphere_quadrature.hpp"
#include "luxel/shading/source/spherical_harmonics.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace luxel::shading::source {
namespace {

using Radiance = std::function<glm::dvec3(const glm::dvec3&)>;

constexpr double kPi = std::numbers::pi;
constexpr int kGridRows = 192;

/// An environment sampled once on the quadrature grid; irradiance(n) integrates it.
class GroundTruth {
 public:
  GroundTruth(const Radiance& radiance, int rows) : samples_(sample_sphere_grid(radiance, rows)) {}
  glm::dvec3 irradiance(const glm::dvec3& n) const { return source::irradiance(samples_, n); }

 private:
  SampledRadiance samples_;
};

// ---- Environments ------------------------------------------------------------------------------

glm::dvec3 sky_over_ground(const glm::dvec3& d) {
  const glm::dvec3 zenith(0.30, 0.45, 0.90), horizon(0.85, 0.85, 0.80), ground(0.22, 0.18, 0.14);
  const double up = std::max(0.0, d.z);
  const glm::dvec3 sky = horizon + (zenith - horizon) * std::sqrt(up);
  const double t = std::clamp((d.z + 0.1) / 0.2, 0.0, 1.0);  // a soft horizon 11.5 degrees wide
  const double s = t * t * (3.0 - 2.0 * t);
  return ground + (sky - ground) * s;
}

/// A sun of angular radius ~3.6 degrees (radiance e^((cos γ − 1)/0.002)) delivering ~4x the sky's
/// zenith irradiance, 50 degrees above the horizon.
glm::dvec3 sky_with_sun(const glm::dvec3& d) {
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.6, 0.3, 1.0));
  const double lobe = std::exp((glm::dot(d, sun) - 1.0) / 0.002);
  return sky_over_ground(d) + glm::dvec3(1.0, 0.9, 0.75) * (600.0 * lobe);
}

/// Strong colours from different directions over a dim floor.
glm::dvec3 coloured_lights(const glm::dvec3& d) {
  const double red = std::pow(std::max(0.0, d.x), 4.0);
  const double green = std::pow(std::max(0.0, glm::dot(d, glm::normalize(glm::dvec3(0.0, -1.0, 1.0)))), 8.0);
  const double blue = std::pow(std::max(0.0, -d.z), 2.0);
  return glm::dvec3(3.0, 0.2, 0.1) * red + glm::dvec3(0.1, 2.5, 0.3) * green + glm::dvec3(0.1, 0.3, 1.5) * blue +
         glm::dvec3(0.03);
}

/// What SH9 must achieve on an environment: bounds on max and RMS |ΔE|/E, max |ΔE| / peak E, and
/// 8-bit steps. Smooth lighting: within a few percent (R&H 2001). Band-limited (the published
/// probes): exact but for float32 and the quadrature. A small sun or tight colour lobes are not
/// band-limited: SH9 rings into the dim directions, where |ΔE|/E grows large; its error stays a
/// few percent of the peak, and far below the cube's.
struct Sh9Bound {
  double max_relative, rms_relative, max_of_peak;
  int max_steps;
};

struct Environment {
  std::string name;
  Radiance radiance;
  Sh9Bound bound;
};

std::vector<Environment> environments() {
  std::vector<Environment> r = {{"sky over ground", sky_over_ground, {0.03, 0.005, 0.01, 2}},
                                {"sky with sun", sky_with_sun, {0.75, 0.25, 0.08, 25}},
                                {"coloured lights", coloured_lights, {0.40, 0.05, 0.02, 10}}};
  for (const PublishedProbe& p : kRamamoorthi2001Probes) {
    const Sh9 sh = physical_radiance(published_radiance(p));
    r.push_back({std::string(p.name) + " (R&H 2001 SH9)", [sh](const glm::dvec3& d) { return evaluate(sh, d); },
                 {1e-3, 1e-4, 1e-4, 1}});
  }
  return r;
}

// ---- Error measurement ---------------------------------------------------------------------------

/// The error of `approx` (E/π from a shader, per unit normal) against the ground truth `truth` (E).
template <class Approx>
IrradianceError measure_error(const std::vector<glm::dvec3>& normals, const std::vector<glm::dvec3>& truth, Approx&& approx) {
  std::vector<glm::dvec3> values;
  for (const glm::dvec3& n : normals) values.push_back(approx(n));
  return irradiance_error(truth, values);
}

float3<float> lane(const glm::dvec3& n) {
  return float3<float>(static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z));
}
glm::dvec3 unlane(const float3<float>& v) { return glm::dvec3(v.x, v.y, v.z); }

struct Comparison {
  IrradianceError cube, sh9, sh9_of_cube;
};

Comparison compare(const Environment& env, const std::vector<glm::dvec3>& normals) {
  const GroundTruth truth_grid(env.radiance, kGridRows);
  std::vector<glm::dvec3> truth;
  for (const glm::dvec3& n : normals) truth.push_back(truth_grid.irradiance(n));
  for (const glm::dvec3& e : truth) EXPECT_GT(std::min({e.x, e.y, e.z}), 0.0) << env.name << ": relative error needs E > 0";

  const AmbientCube cube = fit_ambient_cube(env.radiance, kGridRows);
  const Sh9Ambient sh9 = sh9_ambient_constants(convolve_cosine(project_sh9(env.radiance, kGridRows)));
  const Sh9Ambient sh9_of_cube = sh9_ambient_constants(sh9_from_ambient_cube(cube));
  Comparison r;
  r.cube = measure_error(normals, truth, [&](const glm::dvec3& n) { return unlane(ambient_light<float>(lane(n), cube)); });
  r.sh9 = measure_error(normals, truth, [&](const glm::dvec3& n) { return unlane(sh9_ambient_light<float>(lane(n), sh9)); });
  r.sh9_of_cube = measure_error(normals, truth,
                                [&](const glm::dvec3& n) { return unlane(sh9_ambient_light<float>(lane(n), sh9_of_cube)); });
  auto show = [](const char* what, const IrradianceError& e) {
    std::printf("  %-16s max %7.3f%%  rms %7.3f%%  max/peak %7.3f%%  %3d steps\n", what, 100 * e.max_relative,
                100 * e.rms_relative, 100 * e.max_of_peak, e.max_steps);
  };
  std::printf("%s\n", env.name.c_str());
  show("ambient cube", r.cube);
  show("SH9", r.sh9);
  show("SH9 of the cube", r.sh9_of_cube);
  return r;
}

// ---- The basis and the constants -----------------------------------------------------------------

TEST(Sh9, BasisNormalisationRoundsToThePapersConstants) {
  EXPECT_NEAR(Sh9Norm::y00, 0.282095, 5e-7);
  EXPECT_NEAR(Sh9Norm::y1, 0.488603, 5e-7);
  EXPECT_NEAR(Sh9Norm::y2_cross, 1.092548, 5e-7);
  EXPECT_NEAR(Sh9Norm::y20, 0.315392, 5e-7);
  EXPECT_NEAR(Sh9Norm::y22, 0.546274, 5e-7);
}

TEST(Sh9, ShaderPolynomialHasThePapersIrradianceConstants) {
  // One unit radiance coefficient at a time through convolve_cosine and the register expansion:
  // the polynomial's coefficients times π must be R&H's c1..c5 (eq. 13).
  auto registers_for = [](int coefficient) {
    Sh9 l;
    l.c[static_cast<size_t>(coefficient)] = glm::dvec3(1.0);
    return sh9_ambient_constants(convolve_cosine(l));
  };
  auto times_pi = [](const glm::vec3& k) { return static_cast<double>(k.x) * kPi; };
  // The paper computed c1..c5 from its 6-digit normalisations (0.315392 · 3 · π/4 = 0.743125 where
  // the exact value is 0.7431238), so they can differ from ours by a unit of the 6th digit.
  constexpr double kTol = 2e-6;
    EXPECT_NEAR(times_pi(registers_for(0).k[0]), kPaperC4, kTol);        // c4 L00
  EXPECT_NEAR(times_pi(registers_for(3).k[1]), 2.0 * kPaperC2, kTol);  // 2 c2 L11 x
  EXPECT_NEAR(times_pi(registers_for(1).k[2]), 2.0 * kPaperC2, kTol);  // 2 c2 L1-1 y
  EXPECT_NEAR(times_pi(registers_for(2).k[3]), 2.0 * kPaperC2, kTol);  // 2 c2 L10 z
  EXPECT_NEAR(times_pi(registers_for(4).k[4]), 2.0 * kPaperC1, kTol);  // 2 c1 L2-2 xy
  EXPECT_NEAR(times_pi(registers_for(5).k[5]), 2.0 * kPaperC1, kTol);  // 2 c1 L2-1 yz
  EXPECT_NEAR(times_pi(registers_for(6).k[6]), kPaperC3, kTol);        // c3 L20 z²
  EXPECT_NEAR(times_pi(registers_for(6).k[0]), -kPaperC5, kTol);       // − c5 L20
  EXPECT_NEAR(times_pi(registers_for(7).k[7]), 2.0 * kPaperC1, kTol);  // 2 c1 L21 xz
  EXPECT_NEAR(times_pi(registers_for(8).k[8]), kPaperC1, kTol);        // c1 L22 (x² − y²)
}

TEST(Sh9, ProjectionRecoversThePublishedCoefficients) {
  for (const PublishedProbe& p : kRamamoorthi2001Probes) {
    const Sh9 published = published_radiance(p);
    const Sh9 projected = project_sh9([&](const glm::dvec3& d) { return evaluate(published, d); }, kGridRows);
    for (size_t i = 0; i < 9; ++i)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(projected.c[i][c], published.c[i][c], 5e-5) << p.name << " coefficient " << i;
  }
}

// ---- The ground truth itself ---------------------------------------------------------------------

TEST(Sh9, GroundTruthIsConvergedOnItsGrid) {
  // Halving the cell size changes E by less than 0.05% anywhere, for the hardest environment (the sun).
  const GroundTruth coarse(sky_with_sun, kGridRows), fine(sky_with_sun, 2 * kGridRows);
  double worst = 0.0;
  for (const glm::dvec3& n : fibonacci_normals(64)) {
    const glm::dvec3 a = coarse.irradiance(n), b = fine.irradiance(n);
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a[c] - b[c]) / b[c]);
  }
  EXPECT_LT(worst, 5e-4);
}

// ---- SH9 and the ambient cube against the ground truth ---------------------------------------------

TEST(Sh9, ErrorAgainstGroundTruthIrradiance) {
  const std::vector<glm::dvec3> normals = fibonacci_normals(1000);
  for (const Environment& env : environments()) {
    const Comparison r = compare(env, normals);
    SCOPED_TRACE(env.name);
    EXPECT_LT(r.sh9.max_relative, env.bound.max_relative);
    EXPECT_LT(r.sh9.rms_relative, env.bound.rms_relative);
    EXPECT_LT(r.sh9.max_of_peak, env.bound.max_of_peak);
    EXPECT_LE(r.sh9.max_steps, env.bound.max_steps);
    // The cube is worse everywhere, by a wide margin.
    EXPECT_GT(r.cube.max_relative, 3.0 * r.sh9.max_relative);
    EXPECT_GT(r.cube.rms_relative, 3.0 * r.sh9.rms_relative);
    EXPECT_GT(r.cube.max_steps, r.sh9.max_steps);
    // Reading the cube's six values as irradiance samples through SH9 (sh9_from_ambient_cube)
    // beats the cube's own n² blend on average; not asserted for the sun, which sits between the
    // axes, where the gain is marginal (measured: 65.1% against 66.2% RMS).
    if (env.name != "sky with sun") {
      EXPECT_LT(r.sh9_of_cube.rms_relative, r.cube.rms_relative);
    }
  }
}

// ---- The cube's own SH9 --------------------------------------------------------------------------

TEST(Sh9, CubeSh9PassesThroughTheSixSides) {
  AmbientCube cube;
  cube.color = {glm::vec3(1.0f, 0.2f, 0.1f), glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0.5f, 0.5f, 2.0f),
                glm::vec3(0.1f, 0.1f, 0.1f), glm::vec3(0.0f, 1.0f, 1.0f), glm::vec3(3.0f, 0.0f, 0.2f)};
  const Sh9Ambient sh9 = sh9_ambient_constants(sh9_from_ambient_cube(cube));
  for (int j = 0; j < 6; ++j) {
    glm::dvec3 n(0.0);
    n[j / 2] = j % 2 == 0 ? 1.0 : -1.0;
    const glm::dvec3 v = unlane(sh9_ambient_light<float>(lane(n), sh9));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c], cube.color[static_cast<size_t>(j)][c], 2e-6) << "side " << j;
  }
}

TEST(Sh9, CubeOfAnEnvironmentWithoutCrossTermsGivesItsExactSh9) {
  // Grace Cathedral without its xy, yz, xz coefficients: the cube VRAD would fit (dense limit), read
  // back as SH9, is that radiance's SH9 irradiance.
  Sh9 radiance = physical_radiance(published_radiance(kRamamoorthi2001Probes[0]));
  radiance.c[4] = radiance.c[5] = radiance.c[7] = glm::dvec3(0.0);
  const Sh9 expected = convolve_cosine(radiance);
  const Sh9 from_cube = sh9_from_ambient_cube(fit_ambient_cube([&](const glm::dvec3& d) { return evaluate(radiance, d); }));
  for (size_t i = 0; i < 9; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(from_cube.c[i][c], expected.c[i][c], 1e-4) << "coefficient " << i;
}

TEST(Sh9, CubeWithEqualOppositeSidesIsReproducedExactly) {
  // Its n² blend is a degree-2 polynomial, inside bands 0-2; only the sides' differences are smoothed.
  AmbientCube cube;
  cube.color = {glm::vec3(1.0f, 0.5f, 0.2f), glm::vec3(1.0f, 0.5f, 0.2f), glm::vec3(0.1f, 0.9f, 0.3f),
                glm::vec3(0.1f, 0.9f, 0.3f), glm::vec3(2.0f, 0.0f, 0.7f), glm::vec3(2.0f, 0.0f, 0.7f)};
  const Sh9Ambient sh9 = sh9_ambient_constants(sh9_from_ambient_cube(cube));
  for (const glm::dvec3& n : fibonacci_normals(500)) {
    const glm::dvec3 a = unlane(sh9_ambient_light<float>(lane(n), sh9)), b = ambient_light_reference(n, cube);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 2e-6);
  }
}

// ---- Cost ----------------------------------------------------------------------------------------

TEST(Sh9, SlotsAndRegistersBesideTheCube) {
  const AmbientCube cube{};
  const Sh9Ambient sh9{};
  const Cost c = measure(ShaderModel::ps_3_0, [&](CountedInputs& in) { return ambient_light<Counted>(in.vector<3>(), cube); });
  const Cost s = measure(ShaderModel::ps_3_0, [&](CountedInputs& in) { return sh9_ambient_light<Counted>(in.vector<3>(), sh9); });
  std::printf("ps_3_0 ambient: cube %d slots %d registers, SH9 %d slots %d registers\n", c.arithmetic_slots,
              c.uniform_registers, s.arithmetic_slots, s.uniform_registers);
  EXPECT_EQ(c.arithmetic_slots, 9);
  EXPECT_EQ(c.uniform_registers, 6);
  EXPECT_EQ(s.arithmetic_slots, 11);  // mul n², mul n·n.yzx, add x²−y², 8 mad
  EXPECT_EQ(s.uniform_registers, 9);
}

TEST(Sh9, ComboOnlyOnPs30ThoughItsBudgetFitsPs2b) {
  constexpr VertexLitCombo kFourSh9{4, true, true, true, true, false, true};
  constexpr VertexLitCombo kAmbientSh9{0, false, false, false, true, true, true};
  for (ShaderModel m : {ShaderModel::ps_2_0, ShaderModel::ps_2_b}) {
    EXPECT_FALSE(kFourSh9.valid(m));
    EXPECT_FALSE(kAmbientSh9.valid(m));
  }
  EXPECT_TRUE(kFourSh9.valid(ShaderModel::ps_3_0));
  // The refusal is the choice, not a limit: the largest combo, with SH9, needs 3 constants
  // and 4 slots (2 per evaluation: N, and V for the rim) more than with the cube, and still fits
  // ps_2_b's 32 constants and 512 slots.
  constexpr VertexLitCombo kFourCube{4, true, true, true, true, false, false};
  const Cost with_cube = measure_vertexlit_generic<kFourCube>(ShaderModel::ps_2_b);
  const Cost with_sh9 = measure_vertexlit_generic<kFourSh9>(ShaderModel::ps_2_b);
  std::printf("4 lights+bump+phong+exptex+rim on ps_2_b: cube %d constants %d slots, SH9 %d constants %d slots\n",
              with_cube.constant_registers(), with_cube.total_slots(), with_sh9.constant_registers(),
              with_sh9.total_slots());
  EXPECT_EQ(with_sh9.uniform_registers - with_cube.uniform_registers, 3);
  EXPECT_TRUE(fits(with_sh9, caps(ShaderModel::ps_2_b))) << describe(with_sh9);
}

}  // namespace
}  // namespace luxel::shading::source
