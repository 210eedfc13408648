#pragma once
// Source's HDR modes (docs/fidelity.md#tone-mapping, HDRType_t): which one is active changes
// constants the C++ side sends (the water's reflection exposure, #water; the luminance-range
// scale, #auto-exposure), never the shaders' code.

namespace luxel::shading::source {

enum class HdrType {
  none,      ///< LDR: tone-map scale stays 1
  integer,   ///< 8-bit back buffer, tone map inside every shader (c30)
  floating,  ///< legacy float render target, tone-mapped in a final blit
};

}  // namespace luxel::shading::source
