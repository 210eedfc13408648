// The bake's driver: checks, inputs, luxels, rays, then the stages (bake.hpp).
#include "luxel/bake/bake.hpp"

#include "stages.hpp"

#include "luxel/scenes/memory_limit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace luxel::bake {

namespace {

using namespace detail;

void check_settings(const scenes::Scene& scene, const BakeSettings& s) {
  auto fail = [&](const std::string& what) { throw BakeError(scene.name + ": bake settings: " + what); };
  if (s.samples < 1 || s.samples > 1 << 16) fail("samples must be 1 to 65536, not " + std::to_string(s.samples));
  if (s.cube_samples < 1 || s.cube_samples > 1 << 16) fail("cube samples must be 1 to 65536, not " + std::to_string(s.cube_samples));
  if (!(s.stop_fraction > 0.0f && s.stop_fraction < 1.0f)) fail("the stopping fraction must lie in (0, 1)");
  if (s.max_bounces < 0 || s.max_bounces > 1000) fail("max bounces must be 0 to 1000");
  if (s.supersample < 1 || s.supersample > 16) fail("supersampling must be 1 to 16 a side");
  if (!(s.supersample_threshold >= 0.0f)) fail("the supersampling threshold must not be negative");
  if (!(s.sky_max_radiance > 0.0f)) fail("the sky clamp must be positive");
  if (!(s.chart_angle_degrees >= 0.0f && s.chart_angle_degrees < 90.0f)) fail("the chart angle must be 0 to 90 degrees");
  if (s.threads < 0) fail("threads must not be negative");
  for (int a = 0; a < 3; ++a)
    if (!(s.default_volume_spacing[a] > 0.0f) || !std::isfinite(s.default_volume_spacing[a]))
      fail("the default volume spacing must be positive");
}

/// validate() and check_settings(), their refusals as BakeError.
void check_inputs(const scenes::Scene& scene, const BakeSettings& settings) {
  try {
    scenes::validate(scene);
  } catch (const std::exception& e) {
    throw BakeError(e.what());
  }
  check_settings(scene, settings);
}

/// The worker threads `settings` asks for (0: one per core).
int thread_count(const BakeSettings& settings) {
  return std::clamp(settings.threads > 0 ? settings.threads : int(std::thread::hardware_concurrency()), 1, 256);
}

/// The rays' scene: every mesh the inputs see and let occlude, but `unseen`.
RayScene ray_scene(const scenes::Scene& scene, const Inputs& in, std::span<const int> unseen = {}) {
  std::vector<char> visible(scene.meshes.size()), occluding(scene.meshes.size());
  for (size_t i = 0; i < scene.meshes.size(); ++i) visible[i] = in.visible(i), occluding[i] = in.occluding(i);
  for (const int m : unseen)
    if (m >= 0 && size_t(m) < scene.meshes.size()) visible[size_t(m)] = occluding[size_t(m)] = 0;
  return RayScene(scene, visible, occluding);
}

/// An upper bound of the bytes the bake holds per atlas texel: the four maps, the working flat
/// map, coverage, the luxel index, the claim, and (at most one per texel) a luxel with its three
/// per-bounce records.
constexpr uint64_t kBytesPerTexel = 4 * 12 + 2 * 12 + 2 + 4 + 20 + sizeof(Luxel) + 3 * sizeof(Rgb4);

}  // namespace

GeneratedCharts plan_charts(const scenes::Scene& scene, const BakeSettings& settings) {
  const float luxel_size = settings.luxel_size > 0 ? settings.luxel_size : scene.lightmap_luxel_size;
  const Inputs in = prepare_inputs(scene, settings);
  std::vector<char> which(scene.meshes.size(), 0);
  bool missing = false;
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const scenes::Mesh& m = scene.meshes[i];
    if (in.roles[i] != MeshRole::lightmapped || m.triangle_count() == 0) continue;
    which[i] = 1;
    missing |= m.uv1.size() != m.positions.size();
  }
  if (!missing || !(luxel_size > 0.0f) || !std::isfinite(luxel_size)) {
    GeneratedCharts none;
    none.meshes.resize(scene.meshes.size());
    return none;
  }
  return make_charts(scene, which, luxel_size, settings.chart_angle_degrees, kMaxAtlasSide);
}

BakeResult bake(const scenes::Scene& original, const BakeSettings& settings, const ProgressFn& progress) {
  const auto start = std::chrono::steady_clock::now();
  check_inputs(original, settings);
  BakeResult result;
  std::vector<std::string>& warnings = result.warnings;
  const float luxel_size = settings.luxel_size > 0 ? settings.luxel_size : original.lightmap_luxel_size;
  if (!(luxel_size > 0.0f) || !std::isfinite(luxel_size))
    throw BakeError(original.name + ": the luxel size " + std::to_string(luxel_size) + " inches is not a positive number");

  // Charts for meshes without uv1: the bake then reads a copy of the scene with those meshes
  // rebuilt.
  GeneratedCharts charts = plan_charts(original, settings);
  scenes::Scene charted;
  if (charts.atlas_size > 0) {
    charted = original;
    size_t n = 0;
    for (size_t i = 0; i < charts.meshes.size(); ++i)
      if (charts.meshes[i]) charted.meshes[i] = *charts.meshes[i], ++n;
    warnings.push_back(original.name + ": " + std::to_string(n) + " lightmapped meshes got lightmap charts from the baker (" +
                       std::to_string(charts.charts) + " charts, a " + std::to_string(charts.atlas_size) + "-luxel atlas)");
  }
  const scenes::Scene& scene = charts.atlas_size > 0 ? charted : original;
  const Inputs in = prepare_inputs(scene, settings);

  // Which meshes get luxels, through which uv1.
  MeshUvs uvs(scene.meshes.size(), nullptr);
  size_t lightmapped = 0;
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const scenes::Mesh& m = scene.meshes[i];
    if (in.roles[i] != MeshRole::lightmapped || m.triangle_count() == 0 || m.uv1.size() != m.positions.size()) continue;
    uvs[i] = &m.uv1;
    ++lightmapped;
  }

  int side = 0;
  if (lightmapped) {
    side = charts.atlas_size > 0 ? charts.atlas_size : atlas_side_from_uv1(scene, in, uvs, luxel_size);
    if (side == 0) {
      warnings.push_back(scene.name + ": no lightmapped triangle has both area and uv1 area: no lightmaps");
    } else if (side > kMaxAtlasSide) {
      throw BakeError(scene.name + ": at " + std::to_string(luxel_size) + " inches a luxel the lightmap atlas would be " +
                      std::to_string(side) + " luxels on a side, more than " + std::to_string(kMaxAtlasSide));
    } else if (side < 4) {
      warnings.push_back(scene.name + ": at " + std::to_string(luxel_size) + " inches a luxel the lightmap atlas is only " +
                         std::to_string(side) + " x " + std::to_string(side) + " luxels");
    }
    try {
      scenes::check_memory(scene.name, uint64_t(side) * uint64_t(side) * kBytesPerTexel,
                           "a " + std::to_string(side) + " x " + std::to_string(side) +
                               " lightmap atlas; a larger luxel size makes it smaller",
                           settings.max_memory_bytes);
    } catch (const scenes::MemoryLimitError& e) {
      throw BakeError(e.what());
    }
  }

  const bool glows = std::any_of(in.emissive.begin(), in.emissive.end(), [&](glm::vec3 e) { return e != glm::vec3(0.0f); });
  const bool sky = scene.sky_texture >= 0 || scene.background != glm::vec3(0.0f);
  if (scene.lights.empty() && !glows && !sky)
    warnings.push_back(scene.name + ": no lights, no sky and no emissive surfaces: everything bakes black");

  LuxelGrid grid;
  if (side > 0) {
    const auto t0 = std::chrono::steady_clock::now();
    grid = make_luxels(scene, in, uvs, side, side, warnings);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (progress) progress({"luxels", grid.luxels.size(), grid.luxels.size(), 0, s, true});
  }
  const RayScene rays = ray_scene(scene, in);
  const Context ctx{scene, in, rays, grid, uvs, settings, thread_count(settings), progress};

  if (!grid.luxels.empty()) result.lightmaps = bake_lightmaps(ctx, result.stats, warnings);
  result.stats.width = result.lightmaps.width, result.stats.height = result.lightmaps.height;
  if (scene.irradiance_volume) result.cubes = bake_ambient_cubes(ctx, result.lightmaps, result.stats, warnings);
  result.charted_meshes = std::move(charts.meshes);
  result.charted_meshes.resize(scene.meshes.size());
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

namespace {

/// What the queries on a baked scene read: the flat map read back from its texture (attach() and
/// load_bake() give float maps), each lightmapped mesh's uv1 addressing it (no luxels: a hit only
/// looks its texel up). `what` names the query in the refusal of an unbaked scene.
struct BakedFlat {
  LightmapAtlas atlas;
  LuxelGrid grid;
  MeshUvs uvs;
};

BakedFlat baked_flat(const scenes::Scene& scene, const Inputs& in, const std::string& what) {
  BakedFlat out;
  out.uvs.assign(scene.meshes.size(), nullptr);
  const bool lightmapped = std::find(in.roles.begin(), in.roles.end(), MeshRole::lightmapped) != in.roles.end();
  const bool has_flat = scene.lightmaps && scene.lightmaps->flat >= 0 && size_t(scene.lightmaps->flat) < scene.textures.size() &&
                        !scene.textures[size_t(scene.lightmaps->flat)].faces.empty();
  if (lightmapped && !has_flat) throw BakeError(scene.name + ": not baked: " + what + " read its flat lightmap");
  if (!has_flat) return out;
  const scenes::PixelImage& flat = scene.textures[size_t(scene.lightmaps->flat)].faces[0];
  out.atlas.width = out.grid.width = flat.width;
  out.atlas.height = out.grid.height = flat.height;
  const size_t texels = size_t(flat.width) * size_t(flat.height);
  if (flat.rgba32f.size() < 4 * texels) throw BakeError(scene.name + ": its flat lightmap is not a float map of its size");
  out.atlas.maps[0].resize(texels);
  for (size_t t = 0; t < texels; ++t) out.atlas.maps[0][t] = {flat.rgba32f[4 * t], flat.rgba32f[4 * t + 1], flat.rgba32f[4 * t + 2]};
  for (size_t i = 0; i < scene.meshes.size(); ++i)
    if (in.roles[i] == MeshRole::lightmapped && scene.meshes[i].uv1.size() == scene.meshes[i].positions.size())
      out.uvs[i] = &scene.meshes[i].uv1;
  return out;
}

}  // namespace

PointCubes ambient_cubes_at(const scenes::Scene& scene, const BakeSettings& settings, std::span<const glm::vec3> points,
                            std::span<const int> unseen_meshes) {
  check_inputs(scene, settings);
  const Inputs in = prepare_inputs(scene, settings);
  const BakedFlat baked = baked_flat(scene, in, "ambient cubes at points");
  const RayScene rays = ray_scene(scene, in, unseen_meshes);
  const ProgressFn no_progress;
  const Context ctx{scene, in, rays, baked.grid, baked.uvs, settings, thread_count(settings), no_progress};
  return point_cubes(ctx, baked.atlas, points);
}

std::vector<glm::vec3> irradiance_at(const scenes::Scene& scene, const BakeSettings& settings, std::span<const SurfacePoint> points) {
  check_inputs(scene, settings);
  const Inputs in = prepare_inputs(scene, settings);
  const BakedFlat baked = baked_flat(scene, in, "irradiance at points");
  const RayScene rays = ray_scene(scene, in);
  const ProgressFn no_progress;
  const Context ctx{scene, in, rays, baked.grid, baked.uvs, settings, thread_count(settings), no_progress};
  return point_irradiance(ctx, baked.atlas, points);
}

void attach(scenes::Scene& scene, const BakeResult& result) {
  for (size_t i = 0; i < result.charted_meshes.size() && i < scene.meshes.size(); ++i)
    if (result.charted_meshes[i]) scene.meshes[i] = *result.charted_meshes[i];
  const LightmapAtlas& a = result.lightmaps;
  if (a.width > 0) {
    static const char* names[4] = {"bake/lightmap_flat", "bake/lightmap_basis0", "bake/lightmap_basis1", "bake/lightmap_basis2"};
    scenes::Lightmaps lm;
    lm.width = a.width, lm.height = a.height;
    for (int k = 0; k < 4; ++k) {
      scenes::Texture t;
      t.name = names[k];
      t.color_space = scenes::ColorSpace::linear;
      t.wrap_u = t.wrap_v = scenes::Wrap::clamp;
      t.mipmaps = false;
      scenes::PixelImage img;
      img.width = a.width, img.height = a.height;
      img.rgba32f.reserve(size_t(a.width) * size_t(a.height) * 4);
      for (const glm::vec3& v : a.maps[size_t(k)]) img.rgba32f.insert(img.rgba32f.end(), {v.r, v.g, v.b, 1.0f});
      t.faces.push_back(std::move(img));
      scene.textures.push_back(std::move(t));
      const int index = int(scene.textures.size()) - 1;
      if (k == 0) lm.flat = index;
      else lm.textures[size_t(k) - 1] = index;
    }
    scene.lightmaps = lm;
  }
  if (result.cubes) scene.irradiance_volume = result.cubes->volume;
}

}  // namespace luxel::bake
