#pragma once
// Where the post passes report the shaders they ran when a frame counts them
// (frame::FrameSettings::count_shading, Renderer::shader_uses): a pass given a tally with a list
// counts the pixels each of its draws shades (the pixel functor's counter,
// shading/source/shader_use.hpp) and adds each shader to the list, with the SDK binary the
// tally's card runs (shading/source/binaries.hpp) and that binary's counted DX9 slots (the
// shader's measure_* function, which the shading catalog lists). A
// pass given the default tally counts nothing.

#include "luxel/shading/shader_model.hpp"
#include "luxel/shading/source/shader_use.hpp"

#include <vector>

namespace luxel::postfx {

struct ShaderTally {
  std::vector<shading::source::ShaderUse>* uses = nullptr;    ///< null: count nothing
  shading::ShaderModel model = shading::ShaderModel::ps_2_0;  ///< the card's pixel-shader model
};

}  // namespace luxel::postfx
