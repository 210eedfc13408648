#pragma once
// Private: one post-pass draw counted into a ShaderTally (shader_tally.hpp).

#include "luxel/postfx/shader_tally.hpp"
#include "luxel/shading/cost.hpp"

#include <atomic>
#include <cstdint>
#include <string>

namespace luxel::postfx {

/// Runs `draw(pixels)`, which draws pixel functor PS with `pixels` as its counter (null when the
/// tally counts nothing) and has flushed the context when it returns; then adds PS's entry to the
/// tally: its family, `combo`, the pixels counted, the binary the tally's card runs (PS::kBuilds)
/// and `measure`'s slots on it.
template <class PS, class Draw>
void counted_draw(const ShaderTally& tally, const std::string& combo, shading::Cost (*measure)(shading::ShaderModel),
                  Draw&& draw) {
  if (!tally.uses) return draw(nullptr);
  std::atomic<uint64_t> pixels{0};
  draw(&pixels);
  const shading::ShaderModel binary = *PS::kBuilds.binary_for(tally.model);
  shading::source::add_shader_use(*tally.uses, {PS::kFamily, combo, pixels.load(std::memory_order_relaxed), binary,
                                                measure(binary).total_slots()});
}

}  // namespace luxel::postfx
