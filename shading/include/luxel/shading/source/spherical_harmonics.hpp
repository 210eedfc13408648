#pragma once
// SH9 ambient: irradiance as nine spherical-harmonic coefficients per color channel (bands
// l = 0..2), the option ps_3_0 offers beside the ambient cube (docs/fidelity.md#ambient-cube).
//
// The method is Ramamoorthi & Hanrahan, "An Efficient Representation for Irradiance Environment
// Maps", SIGGRAPH 2001: irradiance E(n) = ∫ L(ω) max(0, n·ω) dω is the radiance L convolved with
// the clamped cosine, whose SH coefficients vanish fast with the band, so projecting L onto bands
// 0..2 (L_lm = ∫ L Y_lm dω) and scaling each band by the cosine lobe's Â_l gives E to a few percent
// for any smooth L: E_lm = Â_l L_lm, Â_0 = π, Â_1 = 2π/3, Â_2 = π/4.
//
// Units. The ambient cube's six colors are cosine-weighted mean radiances (VRAD,
// docs/fidelity.md#irradiance-volume-and-lights), i.e. E(n)/π for n along an axis, and the shader
// multiplies the cube's value by the albedo: a Lambert surface's exitance. The SH9 path produces the
// same quantity, E(n)/π, so it is a drop-in for the cube (VertexLitCombo::sh9_ambient) and the two can
// be compared directly.
//
// CPU side (double): the basis, projection of sampled radiance (sphere_quadrature.hpp: a
// function on an equal-area grid, or an environment image's pixels), the cosine convolution,
// an ambient cube's SH9 (so cube data — VRAD's samples, folded lights — can feed the SH9 combo),
// and the ambient cube VRAD would compute from the same radiance (vrad's cosine-weighted average
// per side), for comparing the two.
//
// Pixel-shader side: the irradiance polynomial the coefficients expand to,
//   E(n)/π = k0 + k1 x + k2 y + k3 z + k4 xy + k5 yz + k6 z² + k7 xz + k8 (x² − y²),
// one float3 constant register per k (9 registers), evaluated in 11 slots (mul n², mul n·n.yzx,
// add x²−y², 8 mad) against the cube's 9 slots and 6 registers. Packed per channel instead
// (Sloan, "Stupid Spherical Harmonics Tricks", 2008: per channel one float4 for bands 0-1 and one
// for four band-2 terms, plus a float3 for x²−y²) the same data takes 7 registers, evaluated with
// six dp4s on (n, 1) and n.xyzz·n.yzzx — about as many slots (not implemented or measured here).
// ps_3_0 has 224 constant registers, so saving two buys nothing; one rgb register per term keeps
// every step an rgb mad, which is also what the SIMD lanes evaluate without shuffles.
// Why ps_3_0 only: see VertexLitCombo::valid (a choice; the budget would allow ps_2_b).
//
// Linear SH (SH4): the same polynomial cut after band 1, four registers and three mads; the
// cheapest basis `luxel report speed-error` compares, not a combo of the shaders.

#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/sphere_quadrature.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <numbers>

namespace luxel::shading::source {

// ---- Basis (R&H 2001, the paper's order and normalisation) --------------------------------------

/// Coefficient order: L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22 (the paper's table rows).
inline constexpr int kSh9Band[9] = {0, 1, 1, 1, 2, 2, 2, 2, 2};

/// Normalisation constants of the real SH basis: Y00 = ½√(1/π), Y1m = √(3/(4π)) × {y, z, x},
/// Y2-2, Y2-1, Y21 = ½√(15/π) × {xy, yz, xz}, Y20 = ¼√(5/π)(3z² − 1), Y22 = ¼√(15/π)(x² − y²).
/// The paper prints them rounded: 0.282095, 0.488603, 1.092548, 0.315392, 0.546274.
struct Sh9Norm {
  static inline const double y00 = 0.5 * std::sqrt(1.0 / std::numbers::pi);
  static inline const double y1 = std::sqrt(3.0 / (4.0 * std::numbers::pi));
  static inline const double y2_cross = 0.5 * std::sqrt(15.0 / std::numbers::pi);
  static inline const double y20 = 0.25 * std::sqrt(5.0 / std::numbers::pi);
  static inline const double y22 = 0.25 * std::sqrt(15.0 / std::numbers::pi);
};

/// The nine basis functions at a unit direction.
inline std::array<double, 9> sh9_basis(const glm::dvec3& d) {
  const double x = d.x, y = d.y, z = d.z;
  return {Sh9Norm::y00,
          Sh9Norm::y1 * y,
          Sh9Norm::y1 * z,
          Sh9Norm::y1 * x,
          Sh9Norm::y2_cross * x * y,
          Sh9Norm::y2_cross * y * z,
          Sh9Norm::y20 * (3.0 * z * z - 1.0),
          Sh9Norm::y2_cross * x * z,
          Sh9Norm::y22 * (x * x - y * y)};
}

/// Â_l: the clamped cosine max(0, cos θ)'s SH coefficients, as the factor they scale band l by
/// (R&H 2001, eq. 8-9 with the √(4π/(2l+1)) folded in).
inline constexpr double kCosineLobe[3] = {std::numbers::pi, 2.0 * std::numbers::pi / 3.0, std::numbers::pi / 4.0};

/// Nine RGB coefficients of a function over the sphere (radiance L_lm or irradiance E_lm).
struct Sh9 {
  std::array<glm::dvec3, 9> c{};
};

/// Σ c_lm Y_lm(d): the band-limited function at a unit direction.
inline glm::dvec3 evaluate(const Sh9& sh, const glm::dvec3& d) {
  const std::array<double, 9> y = sh9_basis(d);
  glm::dvec3 r(0.0);
  for (int i = 0; i < 9; ++i) r += sh.c[static_cast<size_t>(i)] * y[static_cast<size_t>(i)];
  return r;
}

/// Irradiance coefficients from radiance coefficients: E_lm = Â_l L_lm.
inline Sh9 convolve_cosine(const Sh9& radiance) {
  Sh9 e;
  for (size_t i = 0; i < 9; ++i) e.c[i] = radiance.c[i] * kCosineLobe[kSh9Band[i]];
  return e;
}

// ---- Projection (over samples: sphere_quadrature.hpp) ------------------------------------------

/// L_lm = ∫ L(ω) Y_lm(ω) dω ≈ Σ L_i Y_lm(ω_i) Δω_i.
inline Sh9 project_sh9(const SampledRadiance& samples) {
  Sh9 sh;
  for (const RadianceSample& s : samples) {
    const glm::dvec3 v = s.radiance * s.solid_angle;
    const std::array<double, 9> y = sh9_basis(s.direction);
    for (size_t i = 0; i < 9; ++i) sh.c[i] += v * y[i];
  }
  return sh;
}

/// The same for a function over directions (unit dvec3 -> dvec3), by the equal-area grid.
template <class Function>
  requires std::invocable<Function, const glm::dvec3&>
inline Sh9 project_sh9(Function&& f, int rows = 256) {
  return project_sh9(sample_sphere_grid(f, rows));
}

/// The ambient cube VRAD computes at a sample (docs/fidelity.md#irradiance-volume-and-lights):
/// per side j, C_j = Σ L_i c_ij / Σ c_ij over ray directions with c_ij = dot(dir_i, axis_j) > 0.
/// VRAD fires 162 rays; here the rays are the samples, each weighted by its solid angle (equal on the grid, so
/// equal weights as in VRAD's sum), i.e. the dense limit: C_j = E(axis_j) / π, the
/// cosine-weighted mean radiance.
inline AmbientCube fit_ambient_cube(const SampledRadiance& samples) {
  std::array<glm::dvec3, 6> sum{};
  std::array<double, 6> weight{};
  for (const RadianceSample& s : samples) {
    for (int a = 0; a < 3; ++a) {
      const size_t side = static_cast<size_t>(2 * a + (s.direction[a] >= 0.0 ? 0 : 1));
      const double c = std::abs(s.direction[a]) * s.solid_angle;
      sum[side] += s.radiance * c;
      weight[side] += c;
    }
  }
  AmbientCube cube;
  for (size_t j = 0; j < 6; ++j) cube.color[j] = glm::vec3(sum[j] / weight[j]);
  return cube;
}

/// The same for a function over directions, by the equal-area grid.
template <class Radiance>
  requires std::invocable<Radiance, const glm::dvec3&>
inline AmbientCube fit_ambient_cube(Radiance&& radiance, int rows = 256) {
  return fit_ambient_cube(sample_sphere_grid(radiance, rows));
}

/// The irradiance SH9 of an ambient cube, read as what VRAD makes it (above): six irradiance samples,
/// C[a±] = E(±axis_a)/π. With S_a = (C[a+] + C[a−])/2 and D_a = (C[a+] − C[a−])/2, the SH9 function
/// E/π = Σ_a S_a n_a² + D_a n_a passes exactly through the six samples (n = ±axis_a gives S_a ± D_a)
/// and spends its 9 coefficients as SH9 irradiance does: band 0 and the z², x²−y² terms from the
/// sides' means, band 1 from their differences; the xy, yz, xz terms, which six axis samples cannot
/// see, are 0. So an environment whose irradiance has no cross terms is recovered exactly
/// (sh9_test.cpp), and a cube with equal opposite sides is reproduced everywhere (its n² blend is
/// then this same polynomial). Not the least-squares projection of the cube's own blend
/// Σ n_a² C[a±]: that smooths the odd part n_a|n_a| to (3/4) n_a and so misses the samples.
inline Sh9 sh9_from_ambient_cube(const AmbientCube& cube) {
  constexpr double pi = std::numbers::pi;
  glm::dvec3 s[3], d[3];
  for (int a = 0; a < 3; ++a) {
    const glm::dvec3 plus(cube.color[static_cast<size_t>(2 * a)]), minus(cube.color[static_cast<size_t>(2 * a + 1)]);
    s[a] = (plus + minus) * 0.5;
    d[a] = (plus - minus) * 0.5;
  }
  // Σ S_a n_a² in the basis (unit n): ⟨n_a², Y00⟩ = Y00·4π/3; ⟨z², Y20⟩ = Y20·16π/15,
  // ⟨x², Y20⟩ = ⟨y², Y20⟩ = −½ of that; ⟨x², Y22⟩ = −⟨y², Y22⟩ = Y22·8π/15; D_a n_a = (D_a / Y1) Y1(a).
  Sh9 e;  // band-1 order is y, z, x
  e.c[0] = (s[0] + s[1] + s[2]) * (Sh9Norm::y00 * 4.0 * pi / 3.0);
  e.c[1] = d[1] / Sh9Norm::y1;
  e.c[2] = d[2] / Sh9Norm::y1;
  e.c[3] = d[0] / Sh9Norm::y1;
  e.c[6] = (s[2] - (s[0] + s[1]) * 0.5) * (Sh9Norm::y20 * 16.0 * pi / 15.0);
  e.c[8] = (s[0] - s[1]) * (Sh9Norm::y22 * 8.0 * pi / 15.0);
  for (glm::dvec3& c : e.c) c *= pi;  // E/π -> E
  return e;
}

// ---- Pixel shader ------------------------------------------------------------------------------

/// The nine float3 constant registers of the SH9 ambient: the polynomial coefficients k0..k8 of
/// E(n)/π above, rgb each.
struct Sh9Ambient {
  std::array<glm::vec3, 9> k{};
};

/// Expands irradiance coefficients E_lm into the shader's polynomial (divided by π: the cube's
/// units). With E_lm = Â_l L_lm these are R&H's c1..c5 formula: c1 = Â_2·Y22-norm = 0.429043,
/// c2 = Â_1·Y1-norm / 2 = 0.511664, c3 = 3·Â_2·Y20-norm = 0.743125, c4 = Â_0·Y00 = 0.886227,
/// c5 = Â_2·Y20-norm = 0.247708.
inline Sh9Ambient sh9_ambient_constants(const Sh9& irradiance) {
  const auto& e = irradiance.c;
  const double inv_pi = 1.0 / std::numbers::pi;
  const glm::dvec3 k[9] = {
      e[0] * Sh9Norm::y00 - e[6] * Sh9Norm::y20,  // 1: Y00 and the −1 of Y20
      e[3] * Sh9Norm::y1,                         // x
      e[1] * Sh9Norm::y1,                         // y
      e[2] * Sh9Norm::y1,                         // z
      e[4] * Sh9Norm::y2_cross,                   // xy
      e[5] * Sh9Norm::y2_cross,                   // yz
      e[6] * (3.0 * Sh9Norm::y20),                // z²
      e[7] * Sh9Norm::y2_cross,                   // xz
      e[8] * Sh9Norm::y22,                        // x² − y²
  };
  Sh9Ambient r;
  for (size_t i = 0; i < 9; ++i) r.k[i] = glm::vec3(k[i] * inv_pi);
  return r;
}

/// E(n)/π from the nine registers, for a unit normal n. 11 slots on ps_3_0 (measured in
/// sh9_test.cpp and shown by `luxel cost`). A zero normal (normalize(0) = 0) gives k0 where the
/// cube gives black: both are arbitrary for a normal that has no direction.
template <Lane L>
inline float3<L> sh9_ambient_light(const float3<L>& n, const Sh9Ambient& sh) {
  const float3<L> n2 = n * n;
  const float3<L> cross = n * n.yzx();  // xy, yz, zx
  const L x2_minus_y2 = n2.x - n2.y;
  return constant<L>(sh.k[0]) + n.x * constant<L>(sh.k[1]) + n.y * constant<L>(sh.k[2]) +
         n.z * constant<L>(sh.k[3]) + cross.x * constant<L>(sh.k[4]) + cross.y * constant<L>(sh.k[5]) +
         n2.z * constant<L>(sh.k[6]) + cross.z * constant<L>(sh.k[7]) + x2_minus_y2 * constant<L>(sh.k[8]);
}

// ---- Linear SH (bands 0-1) -----------------------------------------------------------------------

/// Four float3 constant registers: E(n)/π truncated to bands 0 and 1, k0 + k1 x + k2 y + k3 z. Four
/// RGB coefficients, the linear SH that Max Payne 2 is said to have stored (no source for that is at
/// hand here), beside the cube's six and SH9's nine.
struct Sh4Ambient {
  std::array<glm::vec3, 4> k{};
};

/// R&H's irradiance formula truncated to band 1: E(n) = Â_0 L00 Y00 + Â_1 Σ L1m Y1m(n), from the
/// irradiance coefficients E_lm = Â_l L_lm (bands 0-1 of them; band 2 is dropped, not refitted).
inline Sh4Ambient sh4_ambient_constants(const Sh9& irradiance) {
  const auto& e = irradiance.c;
  const double inv_pi = 1.0 / std::numbers::pi;
  Sh4Ambient r;
  r.k[0] = glm::vec3(e[0] * (Sh9Norm::y00 * inv_pi));
  r.k[1] = glm::vec3(e[3] * (Sh9Norm::y1 * inv_pi));  // x
  r.k[2] = glm::vec3(e[1] * (Sh9Norm::y1 * inv_pi));  // y
  r.k[3] = glm::vec3(e[2] * (Sh9Norm::y1 * inv_pi));  // z
  return r;
}

/// E(n)/π from the four registers, for a unit normal n: three mads.
template <Lane L>
inline float3<L> sh4_ambient_light(const float3<L>& n, const Sh4Ambient& sh) {
  return constant<L>(sh.k[0]) + n.x * constant<L>(sh.k[1]) + n.y * constant<L>(sh.k[2]) + n.z * constant<L>(sh.k[3]);
}

}  // namespace luxel::shading::source
