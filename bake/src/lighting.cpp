// Direct light with shadow rays, and hits mapped back to luxels.
#include "lighting.hpp"

#include <algorithm>
#include <cmath>

namespace luxel::bake::detail {

namespace {

/// Whether the light reaches p unblocked (shadow ray from the offset origin to the light).
bool visible(const Context& c, glm::vec3 origin, const LightSample& ls) {
  const float tmax = std::isinf(ls.distance) ? std::numeric_limits<float>::infinity() : ls.distance - c.in.epsilon;
  if (!(tmax > 0)) return true;
  return !c.rays.occluded(origin, ls.to_light, 0.0f, tmax);
}

}  // namespace

Rgb4 direct_light(const Context& c, glm::vec3 p, glm::vec3 normal, glm::vec3 n_geo, const std::array<glm::vec3, 3>& basis,
                  uint64_t& rays) {
  Rgb4 out;
  const glm::vec3 origin = p + n_geo * c.in.epsilon;
  for (const scenes::Light& l : c.scene.lights) {
    LightSample ls;
    if (!light_at(l, p, ls)) continue;
    if (glm::dot(n_geo, ls.to_light) <= 0.0f) continue;
    const float cf = std::max(0.0f, glm::dot(normal, ls.to_light));
    float cb[3];
    for (int k = 0; k < 3; ++k) cb[k] = std::max(0.0f, glm::dot(basis[size_t(k)], ls.to_light));
    if (cf <= 0 && cb[0] <= 0 && cb[1] <= 0 && cb[2] <= 0) continue;
    ++rays;
    if (!visible(c, origin, ls)) continue;
    out.v[0] += ls.intensity * cf;
    for (int k = 0; k < 3; ++k) out.v[size_t(k) + 1] += ls.intensity * cb[k];
  }
  return out;
}

glm::vec3 direct_flat(const Context& c, glm::vec3 p, glm::vec3 normal, glm::vec3 n_geo, uint64_t& rays) {
  glm::vec3 out(0.0f);
  const bool surface = glm::dot(n_geo, n_geo) > 0;
  const glm::vec3 origin = surface ? p + n_geo * c.in.epsilon : p;
  for (const scenes::Light& l : c.scene.lights) {
    LightSample ls;
    if (!light_at(l, p, ls)) continue;
    if (surface && glm::dot(n_geo, ls.to_light) <= 0.0f) continue;
    const float cf = std::max(0.0f, glm::dot(normal, ls.to_light));
    if (cf <= 0) continue;
    ++rays;
    if (visible(c, origin, ls)) out += ls.intensity * cf;
  }
  return out;
}

void hit_geometry(const scenes::Scene& scene, const Hit& h, glm::vec3& point, glm::vec3& n_geo) {
  const scenes::Mesh& m = scene.meshes[size_t(h.mesh)];
  const glm::vec3 p0 = m.positions[m.vertex_of_corner(3 * size_t(h.triangle))];
  const glm::vec3 p1 = m.positions[m.vertex_of_corner(3 * size_t(h.triangle) + 1)];
  const glm::vec3 p2 = m.positions[m.vertex_of_corner(3 * size_t(h.triangle) + 2)];
  point = (1.0f - h.u - h.v) * p0 + h.u * p1 + h.v * p2;
  const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
  const float len = glm::length(n);
  n_geo = len > 0 ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
  if (!h.front) n_geo = -n_geo;
}

int64_t texel_of_hit(const Context& c, const Hit& h) {
  const auto* uv = c.uvs[size_t(h.mesh)];
  if (!uv || c.grid.width == 0) return -1;
  const scenes::Mesh& m = c.scene.meshes[size_t(h.mesh)];
  const glm::vec2 t0 = (*uv)[m.vertex_of_corner(3 * size_t(h.triangle))];
  const glm::vec2 t1 = (*uv)[m.vertex_of_corner(3 * size_t(h.triangle) + 1)];
  const glm::vec2 t2 = (*uv)[m.vertex_of_corner(3 * size_t(h.triangle) + 2)];
  const glm::vec2 t = (1.0f - h.u - h.v) * t0 + h.u * t1 + h.v * t2;
  if (!(t.x >= 0.0f && t.x <= 1.0f && t.y >= 0.0f && t.y <= 1.0f)) return -1;
  const int x = std::clamp(int(t.x * float(c.grid.width)), 0, c.grid.width - 1);
  const int y = std::clamp(int(t.y * float(c.grid.height)), 0, c.grid.height - 1);
  return int64_t(y) * c.grid.width + x;
}

glm::vec3 final_radiance(const Context& c, const std::vector<glm::vec3>& flat, const std::optional<Hit>& hit, glm::vec3 dir,
                         uint64_t& rays, bool& back) {
  back = false;
  if (!hit) return c.in.sky(dir);
  if (!hit->front) {
    back = true;
    return glm::vec3(0.0f);
  }
  const size_t m = size_t(hit->mesh);
  glm::vec3 radiance = c.in.emissive[m];
  if (c.in.roles[m] == MeshRole::lightmapped) {
    const int64_t t = texel_of_hit(c, *hit);
    if (t >= 0 && !flat.empty()) radiance += c.in.albedo[m] * flat[size_t(t)];
  } else if (c.in.roles[m] == MeshRole::diffuse) {
    glm::vec3 hp, ng;
    hit_geometry(c.scene, *hit, hp, ng);
    radiance += c.in.albedo[m] * direct_flat(c, hp, ng, ng, rays);
  }
  return radiance;
}

int strata_side(int samples) { return std::max(1, int(std::lround(std::sqrt(double(std::max(samples, 1)))))); }

}  // namespace luxel::bake::detail
