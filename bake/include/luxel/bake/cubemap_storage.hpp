#pragma once
// Baked cube maps on disk, beside the bake they were rendered with (storage.hpp), and when to
// reuse them. The cubes are rendered by the frame (frame/cubemaps.hpp), which also computes the
// hash of what they read; this file only keeps them:
//   cubemap_N.exr
//       sample N's cube: OpenEXR, RGB half float, linear, the six faces stacked top to bottom in
//       D3D order (+X, -X, +Y, -Y, +Z, -Z), each face's top row first;
//   cubemaps.json
//       the index: {"format": "luxel-cubemaps", "version", "hash" (16 hex digits), "names",
//       "files", "face_sizes", "exposures"}.
// Written after the cubes and whole (a bake cut short leaves no index, so it is never reused).

#include "luxel/scenes/scene.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace luxel::bake {

/// Cube maps as kept: one linear float cube texture per sample, and the exposures they were merged from.
struct StoredCubemaps {
  std::vector<scenes::Texture> cubes;  ///< shape cube, linear, six square rgba32f faces each
  std::vector<float> exposures;        ///< the bracket's tone-map scales, for the record
};

/// Writes `cubes` into `directory` (created if missing) under `hash`. Throws std::runtime_error
/// "PATH: problem" when it cannot, or when a cube is not six square float faces of one size.
void save_cubemaps(const StoredCubemaps& cubes, uint64_t hash, const std::string& directory);

/// The cubes kept in `directory` if their index's hash is `hash`; nullopt when there are none or
/// they are for other inputs. The textures hold name, shape, color space and faces (sampler state
/// is the baker's to set). Throws std::runtime_error "FILE: problem" for damaged cubes.
std::optional<StoredCubemaps> load_cubemaps(const std::string& directory, uint64_t hash);

}  // namespace luxel::bake
