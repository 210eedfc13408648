#pragma once
// The Phong ("skin") shader's lighting in double precision, written from docs/fidelity.md#phong
// and #phong-defaults (not from the shader code): the oracle of the Phong tests.

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace luxel::shading::source::testing {

/// One directional light and the material of the skin shader, in double, from docs/fidelity.md#phong
/// (written from the formulas, not from the shader code). The normal is the one the shader ends
/// up with (the normal map's, or the vertex normal under $basemapalphaphongmask and on the fast path).
struct PhongReference {
  glm::dvec3 light_dir{0.0, 0.0, 1.0};  // unit, toward the light
  glm::dvec3 light_color{1.0};
  glm::dvec3 base{0.0};
  double base_alpha = 1.0;
  double normal_alpha = 1.0;              // the normal map's alpha (the full path's mask)
  bool base_map_alpha_phong_mask = false;  // the full path's mask from the base alpha instead
  /// FASTPATH_NOBUMP: mask = base alpha, exponent max(c, 0), tint 1, no rim.
  bool fast_path = false;
  glm::dvec4 exponent_texel{1.0};  // r: exponent 1 + 149 r, g: albedo tint, a: rim mask (white: none)
  double exponent_constant = -1.0;  // c.w: >= 0 the exponent, else from the texel ($phongexponent unset)
  double exponent_factor = 0.0;     // $phongexponentfactor: not 0, the exponent is 1 + factor r (full path)
  glm::dvec3 tint{1.0};             // $phongtint; r < 0: the albedo tint lerp(1, base, texel g)
  double boost = 1.0;
  double fresnel_min = 0.0, fresnel_mid = 0.5, fresnel_max = 1.0;
  bool rim = false;
  double rim_exponent = 4.0, rim_boost = 1.0;
  bool rim_mask = false;
  glm::dvec3 rim_ambient{0.0};  // the ambient cube along V (one color: tests keep it uniform)

  double mask() const { return fast_path || base_map_alpha_phong_mask ? base_alpha : normal_alpha; }
  double exponent() const {
    if (fast_path) return std::max(exponent_constant, 0.0);
    if (exponent_factor != 0.0) return 1.0 + exponent_factor * exponent_texel.x;
    return exponent_constant >= 0.0 ? exponent_constant : 1.0 + 149.0 * exponent_texel.x;
  }
  glm::dvec3 specular_tint() const {
    if (fast_path) return glm::dvec3(1.0);
    return tint.r >= 0.0 ? tint : glm::mix(glm::dvec3(1.0), base, exponent_texel.y);
  }

  /// The Fresnel ranges: f = sat(1 − N·V)², then piecewise linear through (0, min), (0.5, mid),
  /// (1, max). n and v unit.
  double fresnel(const glm::dvec3& n, const glm::dvec3& v) const {
    const double one_minus = std::clamp(1.0 - glm::dot(n, v), 0.0, 1.0);
    const double f = one_minus * one_minus;
    return f < 0.5 ? fresnel_min + (fresnel_mid - fresnel_min) * (f / 0.5)
                   : fresnel_mid + (fresnel_max - fresnel_mid) * ((f - 0.5) / 0.5);
  }

  glm::dvec3 operator()(const glm::dvec3& normal, const glm::dvec3& view) const {
    const glm::dvec3 n = glm::normalize(normal), v = glm::normalize(view), l = light_dir;
    const double n_dot_l = glm::dot(n, l);
    const double h = std::clamp(0.5 * n_dot_l + 0.5, 0.0, 1.0);
    const glm::dvec3 diffuse = base * light_color * (h * h);
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    const double r_dot_l = std::clamp(glm::dot(r, l), 0.0, 1.0);
    const glm::dvec3 lit = light_color * std::clamp(n_dot_l, 0.0, 1.0);
    glm::dvec3 spec = lit * std::pow(r_dot_l, exponent());
    const double one_minus = std::clamp(1.0 - glm::dot(n, v), 0.0, 1.0);
    spec *= mask() * fresnel(n, v) * boost;
    if (rim && !fast_path) {
      const double m = (rim_mask ? exponent_texel.w : 1.0) * std::pow(one_minus, 4.0);
      const glm::dvec3 rim_light = lit * std::pow(r_dot_l, rim_exponent) * m;
      spec = glm::max(spec, rim_light);
      spec += rim_ambient * rim_boost * std::clamp(m * n.z, 0.0, 1.0);
    }
    return diffuse + spec * specular_tint();
  }
};

}  // namespace luxel::shading::source::testing
