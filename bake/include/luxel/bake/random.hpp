#pragma once
// Counter-based random numbers: every number is a pure function of a key (what it is for: luxel
// or cube sample, ray index, bounce, dimension) and the bake's seed, never of a thread's state, so
// a bake's bytes do not depend on thread count or scheduling. The mix is SplitMix64's finalizer
// (Steele, Lea, Flood 2014) applied to the key words in turn; it passes BigCrush as a counter-
// based generator, which is all stratified jitter asks.

#include <cstdint>

namespace luxel::bake {

inline constexpr uint64_t mix64(uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// What a random number is for. `stream` separates users of the same indices (lightmap rays,
/// cube rays, supersampling).
struct RandomKey {
  uint64_t seed = 0;
  uint32_t stream = 0;
  uint64_t item = 0;     ///< luxel index in the atlas, or cube sample index
  uint32_t sample = 0;   ///< ray index within the item
  uint32_t bounce = 0;
};

/// The uniform number in [0, 1) for `key` and dimension `dim` (24 bits, exactly representable).
inline float random01(const RandomKey& key, uint32_t dim) {
  uint64_t h = mix64(key.seed ^ (uint64_t(key.stream) << 32));
  h = mix64(h ^ key.item);
  h = mix64(h ^ ((uint64_t(key.sample) << 32) | (uint64_t(key.bounce) << 8) | dim));
  return float(h >> 40) * (1.0f / 16777216.0f);
}

}  // namespace luxel::bake
