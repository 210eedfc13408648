#pragma once
// The HLSL-like lane language of luxel::shading, all of it: write a shader as a template over a
// lane L (float, simd::Float or Counted) with these types and functions.
//
//   lane.hpp          the lanes and their masks
//   vector.hpp        float2..float4, bool2..bool4, arithmetic, swizzles
//   matrix.hpp        float3x3, float4x4, mul, transpose
//   intrinsics.hpp    saturate, lerp, dot, normalize, pow, select...
//   constants.hpp     constant<L>(): the shader's constant registers
//   textures.hpp      samplers and tex2D/texCUBE/tex3D
//   counted.hpp       the Counted lane
//   cost.hpp          measure() and fits(): cost of a shader on a DX9 model
//   shader_model.hpp  the ps_2_0 / ps_2_b / ps_3_0 / vs_2_0 / vs_3_0 limits
//
// Write shaders inside namespace luxel (or a namespace nested in it, with `using namespace
// luxel::shading;` there): a using-directive at global scope makes select and pow ambiguous with
// POSIX ::select and C's ::pow. Use float literals (0.5f): a double literal promotes the float
// lane's arithmetic to double and the lanes would no longer agree.

#include "luxel/shading/constants.hpp"
#include "luxel/shading/cost.hpp"
#include "luxel/shading/counted.hpp"
#include "luxel/shading/intrinsics.hpp"
#include "luxel/shading/lane.hpp"
#include "luxel/shading/matrix.hpp"
#include "luxel/shading/shader_model.hpp"
#include "luxel/shading/textures.hpp"
#include "luxel/shading/vector.hpp"
