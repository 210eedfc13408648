#pragma once
// Private: pixel functors that the tile rasterizer calls through a pointer instead of inlining.
//
// The tile rasterizer is the library's largest template: inlined, each pixel functor compiles
// its own, once per sample count and depth path, and a frame of Source shaders has dozens of
// static combos. Only a kTrivial functor (draw.hpp) is cheap enough that the stamp loop's
// overheads weigh as much as its shading; every other one does enough per stamp that one
// indirect call more is lost in it. So draw() inlines kTrivial functors and wraps every other
// in a CalledPixelShader<N>, whose draw command (one per varying count N) is compiled once, in
// the library (src/called_draw.cpp.in). The pixels are the same either way: the same template
// code runs on the same values.

#include "luxel/rasterizer/detail/command_queue.hpp"
#include "luxel/rasterizer/state.hpp"

#include <memory>
#include <vector>

namespace luxel::rasterizer {
template <int N>
struct PixelInput;
struct PixelOutput;
}  // namespace luxel::rasterizer

namespace luxel::rasterizer::detail {

struct DrawPlan;

/// A pixel functor with N varyings behind a pointer. Its constants say what the wrapped functor
/// *may* do; can_discard() and writes_depth() say what it does.
template <int N>
struct CalledPixelShader {
  static constexpr bool kCanDiscard = true, kWritesDepth = true;
  using Shade = void (*)(const void* functor, const PixelInput<N>& in, PixelOutput& out);

  std::shared_ptr<const void> functor;  ///< a copy: the draw runs at the next flush, after draw() returns
  Shade shade = nullptr;
  bool discards = false;      ///< the functor's kCanDiscard
  bool depth_written = false; ///< the functor's kWritesDepth

  void operator()(const PixelInput<N>& in, PixelOutput& out) const { shade(functor.get(), in, out); }

  template <class PS>
  static CalledPixelShader of(const PS& ps) {
    return {std::make_shared<const PS>(ps),
            [](const void* f, const PixelInput<N>& in, PixelOutput& out) { (*static_cast<const PS*>(f))(in, out); },
            PS::kCanDiscard, PS::kWritesDepth};
  }
};

template <class PS>
inline constexpr bool kCalledPixelShader = false;
template <int N>
inline constexpr bool kCalledPixelShader<CalledPixelShader<N>> = true;

/// Whether the draw's functor may kill lanes / writes depth: known at compile time for an inlined
/// functor, recorded for a called one.
template <class PS>
bool can_discard(const PS& ps) {
  if constexpr (kCalledPixelShader<PS>) return ps.discards;
  else return PS::kCanDiscard;
}
template <class PS>
bool writes_depth(const PS& ps) {
  if constexpr (kCalledPixelShader<PS>) return ps.depth_written;
  else return PS::kWritesDepth;
}

/// The draw command of a called shader; defined and instantiated for N = 0..kMaxVaryings in the
/// library only, so that no other translation unit compiles its tile rasterizers.
template <int N>
std::unique_ptr<Command> make_called_draw_command(const DrawPlan& plan, const PipelineState& state,
                                                  const CalledPixelShader<N>& ps, std::vector<ChunkBins*> chunks,
                                                  int query_slot);

}  // namespace luxel::rasterizer::detail
