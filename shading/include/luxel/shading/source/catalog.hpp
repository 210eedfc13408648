#pragma once
// The catalog of the Source shaders: every static combo of every family of the registry
// (registry.hpp) and the post shaders without static combos, with the cards the SDK's rules allow
// each on (pixel shaders: ps_2_0 / ps_2_b / ps_3_0; the VertexLitGeneric vertex shader, family
// "VertexLitGeneric_vs": vs_2_0 / vs_3_0, counted against the vertex-shader limits of
// shader_model.hpp), its counted DX9 cost there and its combine stage compiled once per numeric
// lane. `luxel cost`, the report, their tests and the shader benchmark read this one list.
//
// Timing: the combine stage only (everything after the independent texture reads), fed texel
// values and interpolants drawn at random in ranges without NaN or denormal slow paths; texture
// sampling is excluded, so that the numbers are the shader's arithmetic on each lane (one call
// through the entry point per stamp, or per pixel on the scalar lane, included). For a vertex
// shader read pixel as vertex: its inputs are vertex attributes.

#include "luxel/shading/cost.hpp"
#include "luxel/shading/shader_model.hpp"
#include "luxel/shading/source/binaries.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace luxel::shading::source {

/// ns per pixel (per vertex for a vertex shader) of one variant on each numeric lane.
struct LaneTimes {
  double simd_ns = 0.0;
  double scalar_ns = 0.0;
};

/// How far a variant's SIMD lane is from its scalar lane on the same inputs (the scalar lane is
/// the reference: one pixel at a time, in float). Both lanes run the same IEEE operations in the
/// same order, so every field is 0 unless a lane's implementation of an operation differs.
struct LaneAgreement {
  uint64_t pixels = 0;           ///< pixels compared
  uint64_t differing = 0;        ///< pixels whose result differs in any channel's bits
  double max_abs = 0.0;          ///< the largest difference of a channel (infinite: one lane NaN)
  int max_steps = 0;             ///< the same after each result is clamped to [0, 1] and rounded to 8 bits
};

/// One static combo of one family.
struct ShaderVariant {
  std::string family;               ///< "LightmappedGeneric", "VertexLitGeneric", ...
  std::string option;               ///< the family's name for `luxel cost --shader`: "lightmapped", ...
  std::string variant;              ///< the combo's name
  /// The cards it runs on: those the SDK builds a binary for (builds) that the combo's rules allow
  /// it on. Pixel-shader cards ps_2_0 / ps_2_b / ps_3_0, or vertex-shader vs_2_0 / vs_3_0.
  std::vector<ShaderModel> models;
  ShaderBuilds builds;  ///< its SDK binaries: a card runs builds.binary_for(card)
  /// The counted cost of its binary of a model (measure(*builds.binary_for(card)) for a card):
  /// the registry's count (registry.hpp) for a combo of a family's space.
  std::function<Cost(ShaderModel)> measure;
  int inputs = 0;  ///< values per pixel its entry points read
  /// The combine stage on the SIMD lane: one stamp of simd::kLanes pixels, inputs input-major
  /// (in[i * kLanes + pixel]), rgba out channel-major (out[c * kLanes + pixel]).
  void (*shade_simd)(const float* in, float* out) = nullptr;
  /// The same on the scalar lane, one pixel: in[i], out[c].
  void (*shade_scalar)(const float* in, float* out) = nullptr;
};

/// Every variant of every family: for a family with static combos, every combo of its space in
/// the registry (registry.hpp), in the space's order; families in a fixed order.
const std::vector<ShaderVariant>& shader_catalog();

/// The variant's entry points on `pixels` pixels of inputs drawn at random (the same for both
/// lanes, in ranges without NaN or denormal slow paths), timed: the median over `repeats` runs,
/// the lanes taking turns.
LaneTimes time_lanes(const ShaderVariant& v, int pixels, int repeats);
/// Which inputs compare_lanes feeds: the timing's, or one in four of them replaced by a value that
/// breaks careless arithmetic (zeros of both signs, denormals, 1e30, 65504, NaN, infinities).
enum class LaneInputs { timing, hard };
/// The same inputs through both entry points, compared.
LaneAgreement compare_lanes(const ShaderVariant& v, int pixels, LaneInputs inputs = LaneInputs::timing);

}  // namespace luxel::shading::source
