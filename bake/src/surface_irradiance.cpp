// Irradiance at surface points for a shading normal (bake.hpp's irradiance_at states the rule).
#include "stages.hpp"

#include <algorithm>
#include <cmath>

namespace luxel::bake::detail {

namespace {

constexpr uint32_t kStreamSurfacePoints = 4;

/// Two unit vectors completing unit `n` to an orthonormal frame (Duff et al. 2017, "Building an
/// orthonormal basis, revisited": no division by a small number for any n).
void frame_around(glm::vec3 n, glm::vec3& t, glm::vec3& b) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z), d = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * d, -sign * n.x);
  b = glm::vec3(d, sign + n.y * n.y * a, -n.y);
}

}  // namespace

std::vector<glm::vec3> point_irradiance(const Context& c, const LightmapAtlas& atlas, std::span<const SurfacePoint> points) {
  std::vector<glm::vec3> out(points.size(), glm::vec3(0.0f));
  const int n = strata_side(c.settings.samples);
  Counters counters;
  parallel_chunks(points.size(), 16, c.threads, "irradiance at points", c.progress, counters,
                  [&](uint64_t, uint64_t begin, uint64_t end) {
    uint64_t rays = 0;
    for (uint64_t i = begin; i < end; ++i) {
      const SurfacePoint& s = points[i];
      glm::vec3 t, b;
      frame_around(s.geometric_normal, t, b);
      const glm::vec3 origin = s.position + s.geometric_normal * c.in.epsilon;
      glm::vec3 sum(0.0f);
      double weight = 0;
      for (int j = 0; j < n * n; ++j) {
        // Uniform over the hemisphere above the geometric surface, as the lightmaps' gather.
        const RandomKey key{c.settings.seed, kStreamSurfacePoints, i, uint32_t(j), 0};
        const glm::vec3 local = uniform_hemisphere(stratified(key, j, n));
        const glm::vec3 dir = local.x * t + local.y * b + local.z * s.geometric_normal;
        const float w = std::max(0.0f, glm::dot(s.normal, dir));
        weight += w;
        if (w <= 0.0f) continue;  // no weight: its radiance does not count
        ++rays;
        const std::optional<Hit> hit = c.rays.intersect(origin, dir, 0.0f, std::numeric_limits<float>::infinity());
        bool back = false;
        sum += final_radiance(c, atlas.maps[0], hit, dir, rays, back) * w;
      }
      // Self-normalized: the weight's exact integral over the hemisphere, (1/pi) of the clamped
      // cosine about `normal` above the geometric plane, is the tilted-plane factor (1 + cos)/2.
      const double exact = 0.5 * (1.0 + double(std::clamp(glm::dot(s.normal, s.geometric_normal), -1.0f, 1.0f)));
      if (weight > 0) out[i] = sum * float(exact / weight);
      out[i] += direct_flat(c, s.position, s.normal, s.geometric_normal, rays);
      counters.done.fetch_add(1, std::memory_order_relaxed);
    }
    counters.rays.fetch_add(rays, std::memory_order_relaxed);
  });
  return out;
}

}  // namespace luxel::bake::detail
