#pragma once
// Source's HDR modes (SOURCE_FACTS §6.1, HDRType_t): which one is active changes constants the
// C++ side sends (the water's reflection exposure §6.4, the luminance-range scale §7.1), never the
// shaders' code.

namespace luxel::shading::source {

enum class HdrType {
  none,      ///< LDR: tone-map scale stays 1
  integer,   ///< 8-bit back buffer, tone map inside every shader (c30)
  floating,  ///< legacy float render target, tone-mapped in a final blit
};

}  // namespace luxel::shading::source
