// The baker's ray kernel: Embree closest-hit and occlusion queries on the courtyard, from points
// just above its lightmapped surfaces in uniform hemisphere directions (the gather's pattern), one
// thread. Items per second = rays per second per core. Whole-bake timings: bench/README.md.

#include "machine.hpp"

#include "luxel/bake/rays.hpp"
#include "luxel/bake/random.hpp"
#include "luxel/scenes/builtin.hpp"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace {

using namespace luxel;

struct Rays {
  scenes::Scene scene = scenes::make_builtin_scene("courtyard");
  std::vector<glm::vec3> origin, dir;
  std::unique_ptr<bake::RayScene> rays;

  Rays() {
    std::vector<char> all(scene.meshes.size(), 1);
    rays = std::make_unique<bake::RayScene>(scene, all, all);
    // 64k rays from random points of the floor and walls (meshes 0 and 1), upper hemisphere.
    for (uint32_t i = 0; origin.size() < 65536; ++i) {
      const scenes::Mesh& m = scene.meshes[i % 2];
      const size_t t = size_t(bake::random01({0, 9, i, 0, 0}, 0) * float(m.triangle_count()));
      const glm::vec3 p0 = m.positions[m.vertex_of_corner(3 * t)], p1 = m.positions[m.vertex_of_corner(3 * t + 1)],
                      p2 = m.positions[m.vertex_of_corner(3 * t + 2)];
      float a = bake::random01({0, 9, i, 1, 0}, 0), b = bake::random01({0, 9, i, 2, 0}, 0);
      if (a + b > 1) a = 1 - a, b = 1 - b;
      const glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
      const float z = bake::random01({0, 9, i, 3, 0}, 0), phi = 6.2831853f * bake::random01({0, 9, i, 4, 0}, 0);
      glm::vec3 d(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
      const glm::vec3 t1 = glm::normalize(std::abs(n.x) < 0.9f ? glm::cross(n, glm::vec3(1, 0, 0)) : glm::cross(n, glm::vec3(0, 1, 0)));
      const glm::vec3 t2 = glm::cross(n, t1);
      origin.push_back(p0 + a * (p1 - p0) + b * (p2 - p0) + n * 0.05f);
      dir.push_back(d.x * t1 + d.y * t2 + d.z * n);
    }
  }
};

Rays& rays() {
  static Rays r;
  return r;
}

void BM_BakeClosestHit(benchmark::State& state) {
  Rays& r = rays();
  size_t i = 0, hits = 0;
  for (auto _ : state) {
    hits += r.rays->intersect(r.origin[i], r.dir[i], 0.0f, INFINITY).has_value();
    i = (i + 1) & 65535;
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(int64_t(state.iterations()));
  state.SetLabel(luxel::bench::machine_line());
}
BENCHMARK(BM_BakeClosestHit);

void BM_BakeOcclusion(benchmark::State& state) {
  Rays& r = rays();
  size_t i = 0, blocked = 0;
  for (auto _ : state) {
    blocked += r.rays->occluded(r.origin[i], r.dir[i], 0.0f, 512.0f);
    i = (i + 1) & 65535;
  }
  benchmark::DoNotOptimize(blocked);
  state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_BakeOcclusion);

void BM_BakeBuildCourtyardBvh(benchmark::State& state) {
  const scenes::Scene scene = scenes::make_builtin_scene("courtyard");
  std::vector<char> all(scene.meshes.size(), 1);
  for (auto _ : state) {
    bake::RayScene r(scene, all, all);
    benchmark::DoNotOptimize(&r);
  }
}
BENCHMARK(BM_BakeBuildCourtyardBvh)->Unit(benchmark::kMillisecond);

}  // namespace
