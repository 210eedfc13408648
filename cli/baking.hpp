#pragma once
// What `luxel bake` and the commands that render share: where a scene's bake is kept, the
// progress display, and baking on demand (a render of a scene whose materials need baked data
// that the scene lacks bakes it first, or loads the bake kept from before).

#include "luxel/bake/bake.hpp"
#include "luxel/bake/folder_lock.hpp"
#include "luxel/frame/cubemaps.hpp"
#include "luxel/scenes/scene.hpp"

#include <string>

namespace luxel::cli {

/// Where the bake of scene argument `scene` goes when no folder is given: beside a scene file
/// (scene.gltf -> scene.bake/); for built-in scenes $XDG_CACHE_HOME/luxel/bake/NAME (or
/// ~/.cache/...). Empty when there is nowhere to put it (no HOME nor XDG_CACHE_HOME).
std::string default_bake_folder(const std::string& scene);

/// Progress on stderr: on a terminal one line rewritten in place; otherwise a line per phase.
bake::ProgressFn bake_progress_printer();

/// "1.23 Mrays/s".
std::string ray_rate(double rays, double seconds);

/// Whether rendering `scene` needs a bake it does not have: LightmappedGeneric meshes without
/// Scene::lightmaps, an irradiance volume without cubes while VertexLitGeneric meshes read it, or
/// cube-map samples without their cube.
bool needs_bake(const scenes::Scene& scene);

/// The lock on bake folder `folder` (bake/folder_lock.hpp), saying on stderr when it waits for
/// another process. Throws std::runtime_error when the folder cannot be created.
bake::FolderLock lock_bake_folder(const std::string& folder, const char* command);

/// Loads the bake of `scene` kept in `folder` if it is for these inputs, else bakes (with
/// progress) and keeps it there; then attaches it, and then its cube maps the same way
/// (bake_and_attach_cubemaps); all under the folder's lock. `command` prefixes the messages on stderr. Throws
/// std::runtime_error (bake::BakeError included) naming the problem.
void bake_and_attach(scenes::Scene& scene, const std::string& folder, const bake::BakeSettings& settings,
                     const frame::CubemapSettings& cube_settings, const char* command);

/// The cube maps of `scene`'s cube-map samples (frame/cubemaps.hpp), rendered from the scene as it
/// is (its lightmaps attached): loaded from `folder` when kept there for these inputs (unless
/// `force`), else rendered with progress on `threads` threads and kept there; then attached.
/// Nothing for a scene without samples. Returns whether they were rendered. The caller holds the
/// folder's lock. Throws
/// std::runtime_error or std::invalid_argument naming the problem.
bool bake_and_attach_cubemaps(scenes::Scene& scene, const std::string& folder, const frame::CubemapSettings& settings,
                              int threads, const char* command, bool force = false);

}  // namespace luxel::cli
