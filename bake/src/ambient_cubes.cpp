// The ambient-cube stage (ambient_cubes.hpp states the rules).
#include "stages.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

namespace luxel::bake::detail {

namespace {

constexpr uint32_t kStreamCubes = 2;
constexpr uint32_t kStreamPointCubes = 3;
constexpr uint64_t kMaxCubeSamples = uint64_t(1) << 22;
const glm::vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

}  // namespace

/// The cube at `p` from n x n stratified rays over the sphere (ambient_cubes.hpp's rule), random
/// numbers keyed by (stream, index); `back` counts the rays that hit back faces.
scenes::AmbientCube gather_cube(const Context& c, const LightmapAtlas& atlas, glm::vec3 p, uint32_t stream, uint64_t index,
                                int n, uint64_t& rays, uint32_t& back) {
  glm::vec3 sum[6] = {};
  double weight[6] = {};
  for (int j = 0; j < n * n; ++j) {
    const RandomKey key{c.settings.seed, stream, index, uint32_t(j), 0};
    const glm::vec2 xi = stratified(key, j, n);
    const float z = 1.0f - 2.0f * xi.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 6.2831853f * xi.y;
    const glm::vec3 dir(r * std::cos(phi), r * std::sin(phi), z);
    ++rays;
    const std::optional<Hit> hit = c.rays.intersect(p, dir, 0.0f, std::numeric_limits<float>::infinity());
    bool back_face = false;
    const glm::vec3 radiance = final_radiance(c, atlas.maps[0], hit, dir, rays, back_face);
    back += back_face ? 1 : 0;
    for (int f = 0; f < 6; ++f) {
      const float w = std::max(0.0f, glm::dot(dir, kAxes[f]));
      sum[f] += radiance * w;
      weight[f] += w;
    }
  }
  scenes::AmbientCube cube;
  for (int f = 0; f < 6; ++f) cube[size_t(f)] = weight[f] > 0 ? sum[f] * float(1.0 / weight[f]) : glm::vec3(0.0f);
  if (c.settings.cubes_all_light)
    for (int f = 0; f < 6; ++f) cube[size_t(f)] += direct_flat(c, p, kAxes[f], glm::vec3(0.0f), rays);
  return cube;
}

AmbientCubes bake_ambient_cubes(const Context& c, const LightmapAtlas& atlas, BakeStats& stats,
                                std::vector<std::string>& warnings) {
  AmbientCubes out;
  scenes::IrradianceVolume& vol = out.volume;
  vol = *c.scene.irradiance_volume;
  vol.cubes.clear();
  for (int a = 0; a < 3; ++a)
    if (!(vol.spacing[a] > 0) || !std::isfinite(vol.spacing[a])) vol.spacing[a] = c.settings.default_volume_spacing[a];
  if (vol.counts.x <= 0 || vol.counts.y <= 0 || vol.counts.z <= 0) {
    for (int a = 0; a < 3; ++a) {
      const double n = std::floor(double(vol.max[a] - vol.min[a]) / double(vol.spacing[a])) + 1.0;
      if (!(n >= 1.0) || n > double(kMaxCubeSamples))
        throw BakeError(c.scene.name + ": the irradiance volume's bounds and spacing give no usable grid");
      vol.counts[a] = int(n);
    }
  }
  const uint64_t count = uint64_t(vol.counts.x) * uint64_t(vol.counts.y) * uint64_t(vol.counts.z);
  if (count > kMaxCubeSamples)
    throw BakeError(c.scene.name + ": the irradiance volume has " + std::to_string(count) + " samples, more than " +
                    std::to_string(kMaxCubeSamples));
  vol.cubes.assign(count, scenes::AmbientCube{});
  out.valid.assign(count, 0);
  std::vector<uint32_t> backfaces(count, 0);

  const int n = strata_side(c.settings.cube_samples);
  Counters counters;
  parallel_chunks(count, 16, c.threads, "ambient cubes", c.progress, counters, [&](uint64_t, uint64_t begin, uint64_t end) {
    uint64_t rays = 0;
    for (uint64_t s = begin; s < end; ++s) {
      const int ix = int(s % uint64_t(vol.counts.x)), iy = int((s / uint64_t(vol.counts.x)) % uint64_t(vol.counts.y)),
                iz = int(s / (uint64_t(vol.counts.x) * uint64_t(vol.counts.y)));
      glm::vec3 p = vol.min + vol.spacing * glm::vec3(ix, iy, iz);
      for (int a = 0; a < 3; ++a) {
        // A point on a face of the volume's box moves 1 inch inward (ambient_cubes.hpp).
        if (std::abs(p[a] - vol.min[a]) < 1e-3f && vol.max[a] > vol.min[a]) p[a] += 1.0f;
        else if (std::abs(p[a] - vol.max[a]) < 1e-3f && vol.max[a] > vol.min[a]) p[a] -= 1.0f;
      }
      uint32_t back = 0;
      vol.cubes[s] = gather_cube(c, atlas, p, kStreamCubes, s, n, rays, back);
      backfaces[s] = back;
      out.valid[s] = back * 4 <= uint32_t(n * n) ? 1 : 0;  // more than 25 % back faces: inside
      counters.done.fetch_add(1, std::memory_order_relaxed);
    }
    counters.rays.fetch_add(rays, std::memory_order_relaxed);
  });
  stats.rays += counters.rays;
  stats.cube_samples = count;

  // Samples inside solid geometry take the cube of the nearest valid one: breadth-first over the
  // grid from all valid samples at once (6-neighbours, in index order: deterministic).
  std::deque<uint64_t> queue;
  std::vector<char> reached(out.valid.begin(), out.valid.end());
  for (uint64_t s = 0; s < count; ++s)
    if (out.valid[s]) queue.push_back(s);
  stats.cube_samples_inside = count - queue.size();
  if (queue.empty()) {
    for (auto& cube : vol.cubes) cube = scenes::AmbientCube{};
    warnings.push_back(c.scene.name + ": every ambient-cube sample is inside solid geometry; the cubes are black");
    return out;
  }
  const int64_t nx = vol.counts.x, ny = vol.counts.y, nz = vol.counts.z;
  while (!queue.empty()) {
    const uint64_t s = queue.front();
    queue.pop_front();
    const int64_t x = int64_t(s) % nx, y = (int64_t(s) / nx) % ny, z = int64_t(s) / (nx * ny);
    const int64_t nb[6][3] = {{x - 1, y, z}, {x + 1, y, z}, {x, y - 1, z}, {x, y + 1, z}, {x, y, z - 1}, {x, y, z + 1}};
    for (const auto& q : nb) {
      if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= nx || q[1] >= ny || q[2] >= nz) continue;
      const uint64_t t = uint64_t(q[0] + nx * (q[1] + ny * q[2]));
      if (reached[t]) continue;
      reached[t] = 1;
      vol.cubes[t] = vol.cubes[s];
      queue.push_back(t);
    }
  }
  return out;
}

PointCubes point_cubes(const Context& c, const LightmapAtlas& atlas, std::span<const glm::vec3> points) {
  PointCubes out;
  out.cubes.resize(points.size());
  out.valid.resize(points.size());
  const int n = strata_side(c.settings.cube_samples);
  Counters counters;
  parallel_chunks(points.size(), 1, c.threads, "ambient cubes at points", c.progress, counters,
                  [&](uint64_t, uint64_t begin, uint64_t end) {
                    uint64_t rays = 0;
                    for (uint64_t i = begin; i < end; ++i) {
                      uint32_t back = 0;
                      // Every point the same directions (common random numbers): nearby points
                      // differ by their light, not by their noise.
                      out.cubes[i] = gather_cube(c, atlas, points[i], kStreamPointCubes, 0, n, rays, back);
                      out.valid[i] = back * 4 <= uint32_t(n * n) ? 1 : 0;
                      counters.done.fetch_add(1, std::memory_order_relaxed);
                    }
                    counters.rays.fetch_add(rays, std::memory_order_relaxed);
                  });
  return out;
}

}  // namespace luxel::bake::detail
