#pragma once
// Private: the counted DX9 slots of the frame's combos (combo_spaces.hpp), and which VertexLit
// combos fit a model. Counting runs the shader once on the Counted lane; that code lives in its
// own translation unit, compiled without optimization (frame/CMakeLists.txt): it runs once per
// combo and model (the answers are kept), and compiled with the draws it doubled their build
// time.

#include "luxel/shading/shader_model.hpp"
#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"
#include "luxel/shading/source/water.hpp"

namespace luxel::frame::detail {

/// Counted slots per pixel of the binary of model `binary` of a combo of the frame's space
/// (std::logic_error outside it). Which binary a card runs: binaries.hpp.
int lightmapped_slots(const shading::source::LightmappedCombo& combo, shading::ShaderModel binary);
int vertexlit_slots(const shading::source::VertexLitCombo& combo, shading::ShaderModel binary);
int unlit_slots(const shading::source::UnlitCombo& combo, shading::ShaderModel binary);
int water_slots(const shading::source::WaterCombo& combo, shading::ShaderModel binary);
int sky_slots(shading::ShaderModel binary);

/// Whether a VertexLit combo of the frame's space has a binary of model `binary`: allowed by the
/// SDK's rules and within the model's limits (vertexlit_compiles); false outside the space.
bool vertexlit_fits(const shading::source::VertexLitCombo& combo, shading::ShaderModel binary);

}  // namespace luxel::frame::detail
