#pragma once
// Private: the combos the frame compiles a draw for, per family: the part of the registry's space
// (shading/source/registry.hpp) its materials can ask for. Each family's draws (source_draws.hpp)
// compile in their own file; VertexLitGeneric's in two halves, so that they build in parallel.

#include "luxel/shading/source/registry.hpp"

namespace luxel::frame::detail {

using namespace shading::source;

/// Every LightmappedGeneric combo.
inline constexpr auto kLightmappedDrawn = kLightmappedSpace;

/// Every per-pixel VertexLitGeneric combo: without an env map (vertexlit_draws.cpp) and with one
/// (vertexlit_envmap_draws.cpp).
inline constexpr auto kVertexLitPlainDrawn = subset<kVertexLitSpace, [](const VertexLitCombo& c) { return !c.envmap; }>();
inline constexpr auto kVertexLitEnvmapDrawn = subset<kVertexLitSpace, [](const VertexLitCombo& c) { return c.envmap; }>();

/// UnlitGeneric and DIFFUSELIGHTING without a detail texture (the adapter feeds no detail
/// coordinate, and no scene material asks for one).
inline constexpr auto kUnlitDrawn = subset<kUnlitSpace, [](const UnlitCombo& c) { return c.detail == UnlitDetail::none; }>();

/// Every Water combo.
inline constexpr auto kWaterDrawn = kWaterSpace;

}  // namespace luxel::frame::detail
