#pragma once
// The catalog of the Source shader families: every family, every static combo, the shader models
// the SDK's rules allow it on (pixel shaders: ps_2_0 / ps_2_b / ps_3_0; the VertexLitGeneric vertex
// shader, family "VertexLitGeneric_vs": vs_2_0 / vs_3_0, counted against the vertex-shader limits
// of shader_model.hpp), how to count its DX9 cost there and how to time it on the two numeric
// lanes. `luxel cost`, its test and anything else that lists the shaders read this one
// list, so a combo added to a family's combo table (kLightmappedCombos, ...) appears everywhere.
//
// Timing: the combine stage only (everything after the independent texture reads), fed texel
// values and interpolants drawn at random in ranges without NaN or denormal slow paths; texture
// sampling is excluded, so that the numbers are the shader's arithmetic on each lane. A number is
// the median over `repeats` runs of `pixels` pixels each, the two lanes taking turns (for a vertex
// shader, read pixel as vertex: its inputs are vertex attributes). compare_lanes feeds both lanes
// the same inputs and compares what they return.

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
  /// The counted cost of its binary of a model (measure(*builds.binary_for(card)) for a card).
  std::function<Cost(ShaderModel)> measure;
  std::function<LaneTimes(int pixels, int repeats)> time;
  /// The combine stage on both lanes over `pixels` pixels of the timing's inputs, compared.
  std::function<LaneAgreement(int pixels)> compare_lanes;
};

/// Every variant of every family, families in a fixed order, combos in their table's order.
const std::vector<ShaderVariant>& shader_catalog();

}  // namespace luxel::shading::source
