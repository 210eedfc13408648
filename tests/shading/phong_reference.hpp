#pragma once
// The Phong ("skin") shader's lighting in double precision, written from docs/fidelity.md#phong
// (not from the shader code): the oracle of the Phong tests.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace luxel::shading::source::testing {

/// One directional light and the material of the skin shader, in double, from docs/fidelity.md#phong
/// (written from the formulas, not from the shader code).
struct PhongReference {
  glm::dvec3 light_dir{0.0, 0.0, 1.0};  // unit, toward the light
  glm::dvec3 light_color{1.0};
  glm::dvec3 base{0.0};
  double mask = 1.0;                    // the specular mask: base alpha, or the normal map's alpha
  glm::dvec4 exponent_texel{1.0};       // r: exponent 1 + 149 r, a: rim mask
  bool exponent_texture = false;
  double exponent_constant = 5.0;
  glm::dvec3 tint{1.0};
  double boost = 1.0;
  double fresnel_min = 0.0, fresnel_mid = 0.5, fresnel_max = 1.0;
  bool rim = false;
  double rim_exponent = 4.0, rim_boost = 1.0;
  bool rim_mask = false;
  glm::dvec3 rim_ambient{0.0};          // the ambient cube along V (one color: tests keep it uniform)

  glm::dvec3 operator()(const glm::dvec3& normal, const glm::dvec3& view) const {
    const glm::dvec3 n = glm::normalize(normal), v = glm::normalize(view), l = light_dir;
    const double n_dot_l = glm::dot(n, l);
    const double h = std::clamp(0.5 * n_dot_l + 0.5, 0.0, 1.0);
    const glm::dvec3 diffuse = base * light_color * (h * h);
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    const double r_dot_l = std::clamp(glm::dot(r, l), 0.0, 1.0);
    const double exponent = exponent_texture ? 1.0 + 149.0 * exponent_texel.x : exponent_constant;
    const glm::dvec3 lit = light_color * std::clamp(n_dot_l, 0.0, 1.0);
    glm::dvec3 spec = lit * std::pow(r_dot_l, exponent);
    // Fresnel: f = sat(1 − N·V)², then piecewise linear through (0, min), (0.5, mid), (1, max).
    const double one_minus = std::clamp(1.0 - glm::dot(n, v), 0.0, 1.0);
    const double f = one_minus * one_minus;
    const double fresnel = f < 0.5 ? fresnel_min + (fresnel_mid - fresnel_min) * (f / 0.5)
                                   : fresnel_mid + (fresnel_max - fresnel_mid) * ((f - 0.5) / 0.5);
    spec *= mask * fresnel * boost;
    if (rim) {
      const double m = (rim_mask ? exponent_texel.w : 1.0) * std::pow(one_minus, 4.0);
      const glm::dvec3 rim_light = lit * std::pow(r_dot_l, rim_exponent) * m;
      spec = glm::max(spec, rim_light);
      spec += rim_ambient * rim_boost * std::clamp(m * n.z, 0.0, 1.0);
    }
    return diffuse + spec * tint;
  }
};

}  // namespace luxel::shading::source::testing
