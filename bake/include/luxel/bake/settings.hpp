#pragma once
// What a bake is asked to do: sample counts, the stopping rule, the ambient-cube mode, limits.
// Every field enters the bake's hash (storage.hpp) except `threads` and `max_memory_bytes`, which
// never change a byte.

#include "luxel/scenes/memory_limit.hpp"

#include <glm/vec3.hpp>

#include <cstdint>

namespace luxel::bake {

struct BakeSettings {
  /// Hemisphere rays per luxel and bounce (rounded to a square, n x n strata). The gathered light
  /// (sky, emissive surfaces, bounced light) converges as 1/sqrt(samples).
  int samples = 256;
  /// vrad's stopping rule: bounces continue until one adds less than this fraction of the light
  /// gathered so far (summed over all luxels, luminance x luxel area)...
  float stop_fraction = 0.01f;
  /// ...or until this many bounces, with a warning (albedo near 1 converges slowly).
  int max_bounces = 64;
  /// Direct light from the scene's lights is supersampled n x n over a luxel's footprint where it
  /// differs from a neighbour's by more than `supersample_threshold` (relative), as vrad does
  /// where the gradient asks; 1 turns it off.
  int supersample = 4;
  float supersample_threshold = 0.25f;
  /// Sky radiance read from the sky texture is clamped to this: a sun drawn into the sky texture
  /// is the directional light's job, and hitting its few texels by chance only adds noise.
  float sky_max_radiance = 16.0f;

  /// Rays per ambient-cube sample (rounded to a square, n x n strata over the sphere).
  int cube_samples = 256;
  /// false (default): the cubes hold what the engine expects of them, everything but the direct
  /// light of the scene's lights (which models get as local lights): sky, emissive surfaces and
  /// lit surfaces seen from the sample. true: the direct light of the lights added too.
  bool cubes_all_light = false;
  /// Irradiance-volume spacing (inches) used when the scene's volume gives none (<= 0); the
  /// issue's default is 4 x 4 x 8 feet.
  glm::vec3 default_volume_spacing{48.0f, 48.0f, 96.0f};

  /// Luxel size in inches for charts the baker makes (meshes without uv1) and for reading the
  /// density of uv1 charts; 0 = the scene's `lightmap_luxel_size`.
  float luxel_size = 0.0f;
  /// Faces whose normals differ by less than this (degrees) join one chart.
  float chart_angle_degrees = 1.0f;
  /// The memory limit (scenes/memory_limit.hpp): the four lightmaps plus the bake's per-luxel
  /// working set may not exceed this many bytes; a bigger atlas is a BakeError naming its size.
  uint64_t max_memory_bytes = scenes::kDefaultMemoryLimit;

  /// Worker threads (std::thread); 0 = std::thread::hardware_concurrency(). Never changes a byte.
  int threads = 0;
  /// Seed of the counter-based random numbers (random.hpp).
  uint64_t seed = 0;

  /// `--quick`: 64 rays per luxel, 5 % stopping rule, 2x2 supersampling, 64 rays per cube.
  static BakeSettings quick() {
    BakeSettings s;
    s.samples = 64;
    s.stop_fraction = 0.05f;
    s.supersample = 2;
    s.cube_samples = 64;
    return s;
  }
};

}  // namespace luxel::bake
