#pragma once
// Bakes on disk, and when to reuse them.
//
// A bake directory holds
//   lightmap_flat.exr, lightmap_basis0.exr, lightmap_basis1.exr, lightmap_basis2.exr
//       the four maps (lightmaps.hpp): OpenEXR, RGB half float, linear, irradiance / pi, the
//       atlas's top row first (uv1 v = 0); written only when the scene has lightmapped meshes;
//   bake.json
//       the index: {"format": "luxel-bake", "version", "scene", "hash" (16 hex digits), "settings",
//       "lightmaps": {"width", "height", "files", "unit", "luxels", "generated_uv1_meshes"},
//       "volume": {"min", "max", "spacing", "counts", "cubes": [[[r, g, b] x 6], ...],
//       "valid": [0/1, ...]}, "stats", "warnings"}.
//   .lock
//       what luxel processes using the folder take in turn (folder_lock.hpp).
// Generated charts are not stored: they are a deterministic function of what the hash covers,
// and are made again on loading.
//
// The hash (64-bit FNV-1a) covers everything the bake reads: every mesh's positions, normals,
// tangents, uv1, indices, material and model membership; the materials' family, color, emissive,
// base texture pixels; the lights; the sky texture and background; the irradiance volume's grid;
// the scene's luxel size; all settings but `threads`; and the format version.

#include "luxel/bake/bake.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace luxel::bake {

inline constexpr int kBakeFormatVersion = 2;

/// The hash of what a bake of `scene` with `settings` reads.
uint64_t bake_input_hash(const scenes::Scene& scene, const BakeSettings& settings);

/// Writes `result` into `directory` (created if missing). Throws std::runtime_error
/// "DIR: problem" when it cannot.
void save_bake(const BakeResult& result, const scenes::Scene& scene, const BakeSettings& settings,
               const std::string& directory);

/// The bake stored in `directory` if its index's hash is `hash`; nullopt when there is none or it
/// is for other inputs. Throws std::runtime_error "FILE: problem" for a damaged bake.
std::optional<BakeResult> load_bake(const std::string& directory, const scenes::Scene& scene,
                                    const BakeSettings& settings);

}  // namespace luxel::bake
