// The lightmap stage: the lights (delta, shadow rays), then gathered bounces until vrad's stopping
// rule, then supersampling where the direct light's gradient asks, border rings and rounding to
// half. lightmaps.hpp states every rule; this file keeps to it.
#include "stages.hpp"

#include "luxel/bake/rnm_basis.hpp"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>

namespace luxel::bake::detail {

namespace {

constexpr uint64_t kChunk = 256;  // luxels per work item: fixed, so sums never depend on threads
constexpr uint32_t kStreamGather = 1;

/// One bounce of gathering for every luxel. bounce 0: sky and emitters; bounce k >= 1: albedo x
/// the previous bounce's flat map (`previous`, bordered) at what the rays hit.
std::vector<Rgb4> gather(const Context& c, int bounce, const std::vector<glm::vec3>* previous, Counters& counters) {
  const auto& luxels = c.grid.luxels;
  std::vector<Rgb4> out(luxels.size());
  const int n = strata_side(c.settings.samples);
  const auto& basis = rnm_basis();
  const std::string phase = bounce == 0 ? "sky and emitters" : "bounce " + std::to_string(bounce);
  parallel_chunks(luxels.size(), kChunk, c.threads, phase, c.progress, counters,
                  [&](uint64_t, uint64_t begin, uint64_t end) {
    uint64_t rays = 0;
    for (uint64_t li = begin; li < end; ++li) {
      const Luxel& l = luxels[li];
      const glm::vec3 origin = l.position + l.geometric_normal * c.in.epsilon;
      glm::vec3 sum[4] = {};
      double weight[4] = {};
      // The sky in the basis maps, by vrad's rule (lightmaps.hpp): its sums over the rays each
      // basis direction sees, their counts, and the count of the rays n sees.
      glm::vec3 sky_sum[3] = {};
      int sky_rays[3] = {}, seen = 0;
      for (int j = 0; j < n * n; ++j) {
        const RandomKey key{c.settings.seed, kStreamGather, l.texel, uint32_t(j), uint32_t(bounce)};
        const glm::vec3 local = uniform_hemisphere(stratified(key, j, n));
        const float z = local.z;
        const glm::vec3 dir = local.x * l.tangent + local.y * l.bitangent + local.z * l.normal;
        float w[4] = {z, 0, 0, 0};
        for (int k = 0; k < 3; ++k) w[k + 1] = std::max(0.0f, glm::dot(basis[size_t(k)], local));
        for (int k = 0; k < 4; ++k) weight[k] += w[k];
        if (bounce == 0 && z > 0.0f) {
          ++seen;
          for (int k = 0; k < 3; ++k) sky_rays[k] += w[k + 1] > 0.0f ? 1 : 0;
        }
        // Directions below the geometric surface see its back: black, no ray needed.
        if (glm::dot(dir, l.geometric_normal) <= 0.0f) continue;
        ++rays;
        const std::optional<Hit> hit = c.rays.intersect(origin, dir, 0.0f, std::numeric_limits<float>::infinity());
        glm::vec3 radiance(0.0f);
        if (!hit) {
          if (bounce == 0) {
            const glm::vec3 sky = c.in.sky(dir);
            sum[0] += sky * w[0];
            for (int k = 0; k < 3; ++k) sky_sum[k] += sky * w[k + 1];
          }
          continue;
        } else if (hit->front) {
          const size_t m = size_t(hit->mesh);
          if (bounce == 0) {
            radiance = c.in.emissive[m];
          } else if (c.in.roles[m] == MeshRole::lightmapped) {
            const int64_t t = texel_of_hit(c, *hit);
            if (t >= 0) radiance = c.in.albedo[m] * (*previous)[size_t(t)];
          } else if (bounce == 1 && c.in.roles[m] == MeshRole::diffuse) {
            glm::vec3 p, ng;
            hit_geometry(c.scene, *hit, p, ng);
            radiance = c.in.albedo[m] * direct_flat(c, p, ng, ng, rays);
          }
        }
        for (int k = 0; k < 4; ++k) sum[k] += radiance * w[k];
      }
      Rgb4& o = out[li];
      for (int k = 0; k < 4; ++k) {
        const double scale = k == 0 ? 1.0 : kBasisSkyFactor;
        if (weight[k] > 0) o.v[size_t(k)] = sum[k] * float(scale / weight[k]);
      }
      // weight[0] sums n . w over every ray, and every ray lies in n's hemisphere.
      for (int k = 0; k < 3; ++k)
        if (sky_rays[k] > 0 && weight[0] > 0)
          o.v[size_t(k) + 1] += sky_sum[k] * float(double(seen) / (double(sky_rays[k]) * weight[0]));
      counters.done.fetch_add(1, std::memory_order_relaxed);
    }
    counters.rays.fetch_add(rays, std::memory_order_relaxed);
  });
  return out;
}

/// The lights' direct light at every luxel center, then supersampled where neighbours differ.
std::vector<Rgb4> direct(const Context& c, BakeStats& stats, Counters& counters) {
  const auto& luxels = c.grid.luxels;
  std::vector<Rgb4> out(luxels.size());
  parallel_chunks(luxels.size(), kChunk, c.threads, "direct light", c.progress, counters,
                  [&](uint64_t, uint64_t begin, uint64_t end) {
    uint64_t rays = 0;
    for (uint64_t i = begin; i < end; ++i) {
      const Luxel& l = luxels[i];
      out[i] = direct_light(c, l.position, l.normal, l.geometric_normal, l.basis, rays);
      counters.done.fetch_add(1, std::memory_order_relaxed);
    }
    counters.rays.fetch_add(rays, std::memory_order_relaxed);
  });
  const int n = c.settings.supersample;
  if (n <= 1 || c.scene.lights.empty()) return out;
  // Which luxels to supersample: a 4-neighbour (covered) differs by more than the threshold.
  std::vector<uint32_t> flagged;
  const int w = c.grid.width, h = c.grid.height;
  const float threshold = c.settings.supersample_threshold;
  for (size_t i = 0; i < luxels.size(); ++i) {
    const int x = int(luxels[i].texel % uint32_t(w)), y = int(luxels[i].texel / uint32_t(w));
    const float a = luminance(out[i].v[0]);
    const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
    for (int k = 0; k < 4; ++k) {
      if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
      const int32_t j = c.grid.at[size_t(ny[k]) * size_t(w) + size_t(nx[k])];
      if (j < 0) continue;
      const float b = luminance(out[size_t(j)].v[0]);
      if (std::abs(a - b) > threshold * std::max(a, b) && std::abs(a - b) > 1e-6f) {
        flagged.push_back(uint32_t(i));
        break;
      }
    }
  }
  stats.supersampled = flagged.size();
  Counters ss;
  parallel_chunks(flagged.size(), 64, c.threads, "supersampling", c.progress, ss, [&](uint64_t, uint64_t begin, uint64_t end) {
    uint64_t rays = 0;
    for (uint64_t f = begin; f < end; ++f) {
      const Luxel& l = luxels[flagged[f]];
      Rgb4 sum;
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx) {
          const glm::vec3 p = l.position + l.dpdx * ((sx + 0.5f) / n - 0.5f) + l.dpdy * ((sy + 0.5f) / n - 0.5f);
          const Rgb4 d = direct_light(c, p, l.normal, l.geometric_normal, l.basis, rays);
          for (int k = 0; k < 4; ++k) sum.v[size_t(k)] += d.v[size_t(k)];
        }
      for (int k = 0; k < 4; ++k) out[flagged[f]].v[size_t(k)] = sum.v[size_t(k)] / float(n * n);
      ss.done.fetch_add(1, std::memory_order_relaxed);
    }
    ss.rays.fetch_add(rays, std::memory_order_relaxed);
  });
  counters.rays += ss.rays.load();
  return out;
}

/// Luminance x area over all luxels, summed per chunk and then over chunks in order.
double energy(const Context& c, const std::vector<Rgb4>& v) {
  double total = 0;
  for (size_t begin = 0; begin < v.size(); begin += kChunk) {
    double chunk = 0;
    for (size_t i = begin; i < std::min(v.size(), begin + kChunk); ++i)
      chunk += double(luminance(v[i].v[0])) * double(c.grid.luxels[i].area);
    total += chunk;
  }
  return total;
}

float to_half(float x) {
  if (!(x > 0.0f)) return 0.0f;  // negative light cannot arise; NaN would be a bug: black, not poison
  return glm::unpackHalf1x16(glm::packHalf1x16(std::min(x, 65504.0f)));
}

}  // namespace

void dilate(std::vector<std::vector<glm::vec3>*> maps, std::vector<LuxelCoverage>& coverage, int width, int height,
            int rings) {
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<uint32_t> fill;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        if (coverage[size_t(y) * size_t(width) + size_t(x)] != LuxelCoverage::empty) continue;
        bool near = false;
        for (int dy = -1; dy <= 1 && !near; ++dy)
          for (int dx = -1; dx <= 1 && !near; ++dx) {
            const int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;
            near = coverage[size_t(yy) * size_t(width) + size_t(xx)] != LuxelCoverage::empty;
          }
        if (near) fill.push_back(uint32_t(y * width + x));
      }
    for (std::vector<glm::vec3>* map : maps)
      for (uint32_t i : fill) {
        const int x = int(i % uint32_t(width)), y = int(i / uint32_t(width));
        glm::vec3 sum(0.0f);
        int count = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;
            const size_t j = size_t(yy) * size_t(width) + size_t(xx);
            if (coverage[j] == LuxelCoverage::empty) continue;
            sum += (*map)[j];
            ++count;
          }
        (*map)[i] = sum / float(count);
      }
    for (uint32_t i : fill) coverage[i] = LuxelCoverage::border;
  }
}

LightmapAtlas bake_lightmaps(const Context& c, BakeStats& stats, std::vector<std::string>& warnings) {
  LightmapAtlas atlas;
  atlas.width = c.grid.width, atlas.height = c.grid.height;
  const size_t texels = size_t(atlas.width) * size_t(atlas.height);
  const auto& luxels = c.grid.luxels;
  stats.luxels = luxels.size();

  // Bounce 0: the lights, plus sky and emitters.
  Counters direct_counters, sky_counters;
  std::vector<Rgb4> total = direct(c, stats, direct_counters);
  const std::vector<Rgb4> sky = gather(c, 0, nullptr, sky_counters);
  stats.rays += direct_counters.rays + sky_counters.rays;
  for (size_t i = 0; i < luxels.size(); ++i)
    for (int k = 0; k < 4; ++k) total[i].v[size_t(k)] += sky[i].v[size_t(k)];
  double so_far = energy(c, total);
  stats.bounce_energy.push_back(so_far);

  // Bounces: each gathers the previous one's flat map (with border rings, so hits near a chart's
  // edge read written luxels).
  std::vector<Rgb4> previous = total;
  std::vector<LuxelCoverage> coverage(texels, LuxelCoverage::empty);
  for (const Luxel& l : luxels) coverage[l.texel] = LuxelCoverage::covered;
  int bounce = 1;
  bool converged = so_far <= 0;  // nothing lit: nothing to bounce
  for (; !converged && bounce <= c.settings.max_bounces; ++bounce) {
    std::vector<glm::vec3> flat(texels, glm::vec3(0.0f));
    for (size_t i = 0; i < luxels.size(); ++i) flat[luxels[i].texel] = previous[i].v[0];
    std::vector<LuxelCoverage> cov = coverage;
    dilate({&flat}, cov, atlas.width, atlas.height, 2);
    Counters counters;
    std::vector<Rgb4> added = gather(c, bounce, &flat, counters);
    stats.rays += counters.rays;
    const double e = energy(c, added);
    stats.bounce_energy.push_back(e);
    for (size_t i = 0; i < luxels.size(); ++i)
      for (int k = 0; k < 4; ++k) total[i].v[size_t(k)] += added[i].v[size_t(k)];
    converged = e < double(c.settings.stop_fraction) * so_far;
    so_far += e;
    previous = std::move(added);
    stats.bounces = bounce;
  }
  if (!converged)
    warnings.push_back(c.scene.name + ": the bounces did not fall below " + std::to_string(c.settings.stop_fraction) +
                       " of the light within " + std::to_string(c.settings.max_bounces) + " bounces (albedo near 1?)");

  for (auto& m : atlas.maps) m.assign(texels, glm::vec3(0.0f));
  for (size_t i = 0; i < luxels.size(); ++i)
    for (int k = 0; k < 4; ++k) atlas.maps[size_t(k)][luxels[i].texel] = total[i].v[size_t(k)];
  atlas.coverage = std::move(coverage);
  dilate({&atlas.maps[0], &atlas.maps[1], &atlas.maps[2], &atlas.maps[3]}, atlas.coverage, atlas.width, atlas.height, 2);
  for (auto& m : atlas.maps)
    for (glm::vec3& v : m) v = {to_half(v.r), to_half(v.g), to_half(v.b)};
  return atlas;
}

}  // namespace luxel::bake::detail
