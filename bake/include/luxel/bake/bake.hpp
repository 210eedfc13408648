#pragma once
// luxel's vrad: bakes a scene's RNM lightmaps (lightmaps.hpp) and ambient cubes
// (ambient_cubes.hpp) on the CPU, through Embree (rays.hpp), deterministically.
//
// Conventions: the scene's (scene.hpp): inches, right-handed, +Z up, linear HDR colors. Results
// are in the shaders' lightmap unit, irradiance / pi.
//
// Stages, a file each under src/: inputs (mesh roles, albedo, sky, light falloff), charts
// (uv1 for meshes that have none), luxels (uv1 triangles -> luxel sample points and frames),
// lightmaps (direct light, gathered bounces, stopping rule, supersampling, dilation),
// ambient_cubes, storage (EXR + JSON index, the input hash), parallel (fixed work partition).
//
// Determinism: work is split into fixed chunks of luxels or cube samples, independent of the
// thread count; every random number is a function of (seed, luxel or sample, ray, bounce)
// (random.hpp); every sum over the atlas is taken per chunk and then over chunks in order. The
// same scene and settings give the same bytes with any `threads`.
//
// Lightmap UVs: each world LightmappedGeneric mesh's uv1, the atlas square, its side read from the
// uv1 density at the luxel size (the median over triangles of sqrt(world area / uv area) / size);
// when any such mesh lacks uv1, charts made by the baker for all of them (charts.hpp).
//
// Bad input: a scene without lightmapped meshes, lights, sky or emission, degenerate or
// zero-uv-area triangles, uv1 outside [0, 1] or overlapping, bounces cut by max_bounces: warnings
// in BakeResult::warnings (the bake goes on). A scene that validate() refuses, a luxel size that
// is not a positive finite number, an atlas beyond kMaxAtlasSide or the memory cap: BakeError.

#include "luxel/bake/ambient_cubes.hpp"
#include "luxel/bake/charts.hpp"
#include "luxel/bake/lightmaps.hpp"
#include "luxel/bake/settings.hpp"
#include "luxel/scenes/scene.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace luxel::bake {

/// The largest atlas side (the image reader's limit, scenes/image_io.hpp).
inline constexpr int kMaxAtlasSide = 16384;

/// A bake that cannot be done: one line naming the scene and the problem.
struct BakeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Where a bake is, for a progress display. Called from the calling thread only: at least once a
/// phase, with `finished` at its end, and every ~100 ms in between.
struct Progress {
  std::string_view phase;   ///< "luxels", "direct", "bounce 1", ..., "ambient cubes"
  uint64_t done = 0, total = 0;  ///< work items (luxels or cube samples) of this phase
  uint64_t rays = 0;        ///< rays traced in this phase so far
  double seconds = 0;       ///< time in this phase so far
  bool finished = false;
};
using ProgressFn = std::function<void(const Progress&)>;

struct BakeStats {
  int width = 0, height = 0;  ///< atlas
  uint64_t luxels = 0;        ///< covered texels
  int bounces = 0;            ///< indirect bounces done (after the direct light)
  std::vector<double> bounce_energy;  ///< light added by the direct pass (index 0) and each bounce
  uint64_t rays = 0;          ///< all rays, shadow rays included
  uint64_t supersampled = 0;  ///< luxels whose direct light was supersampled
  uint64_t cube_samples = 0, cube_samples_inside = 0;
  double seconds = 0;
};

struct BakeResult {
  LightmapAtlas lightmaps;             ///< empty (0 x 0) when the scene has no lightmapped mesh
  std::optional<AmbientCubes> cubes;   ///< when the scene has an irradiance volume
  /// Per mesh: the mesh rebuilt with charts the baker made (charts.hpp: unwelded, with uv1) when
  /// some lightmapped mesh had no uv1; nullopt where the scene's mesh was used as it is.
  std::vector<std::optional<scenes::Mesh>> charted_meshes;
  BakeStats stats;
  std::vector<std::string> warnings;   ///< one line each, naming the scene
};

/// Bakes `scene` (unchanged). Throws BakeError (see above).
BakeResult bake(const scenes::Scene& scene, const BakeSettings& settings, const ProgressFn& progress = {});

/// The charts bake() makes for `scene`: when any world LightmappedGeneric mesh lacks uv1, every
/// such mesh is charted (one atlas for all; luxel size from the settings, else the scene);
/// otherwise no mesh (atlas_size 0, all nullopt). Throws BakeError as bake() does.
GeneratedCharts plan_charts(const scenes::Scene& scene, const BakeSettings& settings);

/// The ambient cube at each of `points` in a baked scene (one that attach() has given its
/// lightmaps and charts), computed as an irradiance-volume sample is (ambient_cubes.hpp: the
/// scene's sky, emitters and lights, the flat lightmap where a ray hits a lightmapped surface)
/// from settings.cube_samples rays a point, the same directions at every point (a random stream
/// of their own: points along a path differ by their light, not by their noise); no sample inside
/// geometry is replaced. What the volume's nearest and trilinear lookups approximate at a model's
/// position: with many rays, the exact ambient light there. `unseen_meshes` are passed through
/// by the rays: the model whose light is wanted (its centroid lies inside its own surfaces, which
/// are not its ambient light). Deterministic for any thread count. Throws BakeError as bake()
/// does for a scene or settings it refuses, and for a scene with lightmapped meshes but no flat
/// lightmap (not baked).
PointCubes ambient_cubes_at(const scenes::Scene& baked, const BakeSettings& settings, std::span<const glm::vec3> points,
                            std::span<const int> unseen_meshes = {});

/// A point on a surface, and the normal the light arriving there is wanted for.
struct SurfacePoint {
  glm::vec3 position{0.0f};
  glm::vec3 geometric_normal{0.0f, 0.0f, 1.0f};  ///< unit, the front side: light counts from above it only
  glm::vec3 normal{0.0f, 0.0f, 1.0f};            ///< unit: the shading normal (a bump map's, in world space)
};

/// The light arriving at each of `points` for its shading normal, in the lightmaps' unit: what a
/// luxel there would hold if its flat map were about that normal,
///   (1/pi) integral over the hemisphere above geometric_normal of L(w) max(0, normal . w) dw
/// plus each light as a delta (color x falloff x max(0, normal . L), when the light is above the
/// geometric surface and no occluder lies between). L(w) is what a ray brings back once the bake
/// is final, the ambient cubes' rule (ambient_cubes.hpp: sky, emitters, the flat lightmap where
/// it hits a lightmapped surface, the direct light on other diffuse surfaces). settings.samples
/// rays a point, n x n strata uniform over the hemisphere (a random stream of their own; point i's
/// numbers are keyed by i and settings.seed), self-normalized with the weight's exact integral
/// (1 + normal . geometric_normal) / 2, so that a uniform sky is exact for any normal. What
/// radiosity normal mapping and the flat lightmap approximate for a bumped normal, computed per
/// point. Deterministic for any thread count. Throws BakeError as ambient_cubes_at does.
std::vector<glm::vec3> irradiance_at(const scenes::Scene& baked, const BakeSettings& settings, std::span<const SurfacePoint> points);

/// Attaches a bake to its scene: the four maps as linear rgba32f textures and Lightmaps, the
/// cubes into the irradiance volume, charted meshes in place of the scene's.
void attach(scenes::Scene& scene, const BakeResult& result);

}  // namespace luxel::bake
