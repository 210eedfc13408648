#pragma once
// What a frame reports of the shaders it ran (frame::Renderer::shader_uses, `luxel render
// --stats`): per shader combo, the pixels it shaded, the SDK binary the frame's card runs for it
// (binaries.hpp) and that binary's counted DX9 slots per pixel, for the 3D draws (adapter.hpp) and
// the post passes (postfx) alike.
//
// Counting: a pixel functor with a `pixels` counter set adds each invocation's covered lanes to it
// (count_pixels; relaxed atomics, so the sum is the same whatever the thread count; unset by
// default, since it costs a contended add per stamp). Helper lanes are not counted.

#include "luxel/shading/lane.hpp"
#include "luxel/shading/shader_model.hpp"

#include <atomic>
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

namespace luxel::shading::source {

struct ShaderUse {
  std::string family;   ///< the shading catalog's family name (catalog.hpp): "LightmappedGeneric", "bloomadd", ...
  std::string combo;    ///< the combo's name in the catalog
  uint64_t pixels = 0;  ///< pixels it shaded (covered pixels, helper lanes not counted)
  /// The model of the binary the frame's card runs (a ps_3_0 card runs LightmappedGeneric's ps20b)
  ShaderModel binary = ShaderModel::ps_2_0;
  int slots = 0;  ///< that binary's counted DX9 instruction slots per pixel (arithmetic + texture)
};

/// The combo name of a shader without static combos (the post passes' bloom and grain shaders).
inline constexpr const char* kSingleCombo = "default";

/// Adds `use` to `uses`: its pixels to the entry of the same family and combo, else as a new
/// entry at the end (the list keeps the order of first use).
void add_shader_use(std::vector<ShaderUse>& uses, const ShaderUse& use);

/// One invocation's count (above): adds the covered lanes `live` to `pixels` when it is set.
inline void count_pixels(std::atomic<uint64_t>* pixels, simd::LaneBits live) {
  if (pixels) pixels->fetch_add(static_cast<uint64_t>(std::popcount(live)), std::memory_order_relaxed);
}

}  // namespace luxel::shading::source
