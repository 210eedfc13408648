#pragma once
// The bake's stages, in the order bake.cpp runs them.

#include "lighting.hpp"

#include "luxel/bake/bake.hpp"

#include <span>
#include <string>
#include <vector>

namespace luxel::bake::detail {

/// Direct light, bounces until the stopping rule, supersampling, border rings, half rounding.
LightmapAtlas bake_lightmaps(const Context& c, BakeStats& stats, std::vector<std::string>& warnings);

/// Fills the texels next to covered ones from them, `rings` times (lightmaps.hpp "Borders").
/// `coverage` is updated (empty -> border).
void dilate(std::vector<std::vector<glm::vec3>*> maps, std::vector<LuxelCoverage>& coverage, int width, int height,
            int rings);

/// The ambient cubes of the scene's irradiance volume, with the final lightmaps.
AmbientCubes bake_ambient_cubes(const Context& c, const LightmapAtlas& atlas, BakeStats& stats,
                                std::vector<std::string>& warnings);

/// Cubes at `points` by the same rule, with their own random stream.
PointCubes point_cubes(const Context& c, const LightmapAtlas& atlas, std::span<const glm::vec3> points);

/// irradiance_at's rule at `points`, with the final flat map of `atlas` (bake.hpp).
std::vector<glm::vec3> point_irradiance(const Context& c, const LightmapAtlas& atlas, std::span<const SurfacePoint> points);

}  // namespace luxel::bake::detail
