// The SIMD sampling path of the ideal rules (texture.hpp, "Sampling rules"): its own translation
// unit, compiled beside the hardware rules' (texture_sample.cpp).

#include "texture_sample_impl.hpp"

namespace luxel::rasterizer::texture_sampling {
template struct Sampling<IdealRules>;
}  // namespace luxel::rasterizer::texture_sampling
