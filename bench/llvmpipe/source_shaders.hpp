#pragma once
// W4's GLSL: luxel's Source pixel shaders (shading/include/luxel/shading/source/
// lightmapped_generic.hpp, vertexlit_generic.hpp, unlit_generic.hpp, common.hpp, fog.hpp) ported
// line for line, one program per combo through #defines.

#include <string>

namespace luxel::llvmpipe {

/// The vertex shader every W4 program shares (the linker drops what a combo does not read).
const std::string& source_vertex_shader();

/// The pixel shader of one combo: `defines` is a block of `#define NAME` lines (workload_source.cpp
/// lists them: the family, its combo's parts, the fog).
std::string source_fragment_shader(const std::string& defines);

}  // namespace luxel::llvmpipe
