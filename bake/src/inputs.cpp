// Mesh roles, reflectivity, sky lookup and light falloff (lightmaps.hpp states the rules).
#include "inputs.hpp"

#include "luxel/rasterizer/srgb.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace luxel::bake::detail {

namespace {

using namespace scenes;

/// Texel i of an image, linear: float images as they are, 8-bit ones decoded by their color space
/// (rasterizer/srgb.hpp, the one sRGB decode).
glm::vec3 linear_texel(const PixelImage& img, ColorSpace space, size_t i) {
  if (img.is_hdr()) return {img.rgba32f[4 * i], img.rgba32f[4 * i + 1], img.rgba32f[4 * i + 2]};
  const uint8_t* c = &img.rgba8[4 * i];
  if (space == ColorSpace::srgb)
    return {rasterizer::kSrgbToLinear[c[0]], rasterizer::kSrgbToLinear[c[1]], rasterizer::kSrgbToLinear[c[2]]};
  return glm::vec3(c[0], c[1], c[2]) / 255.0f;
}

/// The mean color of a texture's first image, linear.
glm::vec3 mean_color(const Texture& t) {
  if (t.faces.empty()) return glm::vec3(1.0f);
  const PixelImage& img = t.faces[0];
  const size_t n = size_t(img.width) * size_t(img.height);
  if (n == 0) return glm::vec3(1.0f);
  glm::dvec3 sum(0.0);
  for (size_t i = 0; i < n; ++i) sum += glm::dvec3(linear_texel(img, t.color_space, i));
  return glm::vec3(sum / double(n));
}

}  // namespace

Inputs prepare_inputs(const Scene& scene, const BakeSettings& settings) {
  Inputs in;
  in.scene = &scene;
  in.sky_max = settings.sky_max_radiance;
  const size_t n = scene.meshes.size();
  in.roles.assign(n, MeshRole::diffuse);
  in.albedo.assign(n, glm::vec3(0.0f));
  in.emissive.assign(n, glm::vec3(0.0f));
  const std::vector<char> in_model = scenes::meshes_in_models(scene);
  std::vector<glm::vec3> material_albedo(scene.materials.size());
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    glm::vec3 a(m.color);
    if (m.base.bound()) a *= mean_color(scene.textures[size_t(m.base.texture)]);
    material_albedo[i] = glm::clamp(a, glm::vec3(0.0f), glm::vec3(1.0f));
  }
  for (size_t i = 0; i < n; ++i) {
    const int mi = scene.meshes[i].material;
    const Material def;
    const Material& m = mi >= 0 ? scene.materials[size_t(mi)] : def;
    in.albedo[i] = mi >= 0 ? material_albedo[size_t(mi)] : glm::vec3(1.0f);
    in.emissive[i] = glm::max(m.emissive, glm::vec3(0.0f));
    const bool glows = m.emissive.r > 0 || m.emissive.g > 0 || m.emissive.b > 0;
    if (m.family == ShaderFamily::water || m.family == ShaderFamily::sky || m.alpha == AlphaMode::blend || m.translucent)
      in.roles[i] = MeshRole::ignored;
    else if (m.family == ShaderFamily::unlit_generic)
      in.roles[i] = glows ? MeshRole::emitter : MeshRole::ignored;
    else if (!in_model[i] && m.family == ShaderFamily::lightmapped_generic)
      in.roles[i] = MeshRole::lightmapped;
    else
      in.roles[i] = MeshRole::diffuse;
    if (in.roles[i] == MeshRole::emitter) in.albedo[i] = glm::vec3(0.0f);
  }
  // Ray offset: 2e-5 of the scene's size (float precision at that distance from the origin is
  // ~1e-7 relative), at least 1/100 inch.
  const Bounds b = bounds_of(scene);
  const float extent = b.empty ? 1.0f : std::max({glm::length(b.max), glm::length(b.min), glm::length(b.size())});
  in.epsilon = std::max(0.01f, 2e-5f * extent);
  return in;
}

glm::vec3 Inputs::sky(glm::vec3 d) const {
  const Scene& s = *scene;
  if (s.sky_texture < 0) return s.background;
  const Texture& t = s.textures[size_t(s.sky_texture)];
  if (t.shape != TextureShape::cube || t.faces.size() != 6) return s.background;
  // D3D cube addressing (rasterizer/texture.hpp): the major axis picks the face, then
  // +X (1, -t, -s), -X (-1, -t, s), +Y (s, 1, t), -Y (s, -1, -t), +Z (s, -t, 1), -Z (-s, -t, -1).
  const glm::vec3 a = glm::abs(d);
  int face;
  float s_, t_, m;
  if (a.x >= a.y && a.x >= a.z) {
    m = a.x;
    face = d.x >= 0 ? 0 : 1;
    s_ = d.x >= 0 ? -d.z : d.z;
    t_ = -d.y;
  } else if (a.y >= a.z) {
    m = a.y;
    face = d.y >= 0 ? 2 : 3;
    s_ = d.x;
    t_ = d.y >= 0 ? d.z : -d.z;
  } else {
    m = a.z;
    face = d.z >= 0 ? 4 : 5;
    s_ = d.z >= 0 ? d.x : -d.x;
    t_ = -d.y;
  }
  const PixelImage& img = t.faces[size_t(face)];
  if (img.width <= 0 || img.height <= 0) return s.background;
  const float u = 0.5f * (s_ / m + 1.0f), v = 0.5f * (t_ / m + 1.0f);
  const int x = std::clamp(int(u * img.width), 0, img.width - 1), y = std::clamp(int(v * img.height), 0, img.height - 1);
  const glm::vec3 c = linear_texel(img, t.color_space, size_t(y) * size_t(img.width) + size_t(x));
  return glm::clamp(c, glm::vec3(0.0f), glm::vec3(sky_max));
}

bool light_at(const Light& l, glm::vec3 p, LightSample& out) {
  if (l.type == LightType::directional) {
    const float len = glm::length(l.direction);
    if (!(len > 0)) return false;
    out.to_light = -l.direction / len;
    out.distance = std::numeric_limits<float>::infinity();
    out.intensity = l.color;
    return true;
  }
  const glm::vec3 d = l.position - p;
  const float dist = glm::length(d);
  if (!(dist > 0)) return false;
  if (l.range > 0 && dist > l.range) return false;
  out.to_light = d / dist;
  out.distance = dist;
  const float dd = std::max(dist, 1.0f);
  float scale = 1.0f / (l.constant + l.linear * dd + l.quadratic * dd * dd);
  if (l.type == LightType::spot) {
    const float len = glm::length(l.direction);
    if (!(len > 0)) return false;
    const float cos_a = glm::dot(l.direction / len, -out.to_light);
    const float cos_outer = std::cos(l.outer_cone), cos_inner = std::cos(std::min(l.inner_cone, l.outer_cone));
    if (cos_a <= cos_outer) return false;
    float fringe = 1.0f;
    if (cos_a < cos_inner && cos_inner > cos_outer)
      fringe = std::pow(std::clamp((cos_a - cos_outer) / (cos_inner - cos_outer), 0.0f, 1.0f), l.spot_exponent);
    scale *= fringe * cos_a;
  }
  out.intensity = l.color * scale;
  return true;
}

}  // namespace luxel::bake::detail
