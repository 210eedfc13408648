#pragma once
// The DX9 shader models luxel's shaders are written for, and what each allows: the table fxc
// checks a compiled shader against. One row per model, every number cited.
//
// Sources (Microsoft's Direct3D 9 assembly reference, learn.microsoft.com/windows/win32/direct3dhlsl):
//  [slots]   "Pixel Shader Differences" / "Vertex Shader Differences", Instruction Slots:
//            ps_2_0 32 texture + 64 arithmetic; ps_2_x >= 96 up to D3DPSHADERCAPS2_0.NumInstructionSlots
//            (512 for the ps_2_b profile); ps_3_0 >= 512; vs_2_0 256; vs_3_0 >= 512.
//  [regs]    same pages, Features: ps_2_0 12 temps (r#), 32 float constants (c#), 8 texcoords (t#);
//            the HLSL profile table (ps_2_b: 32 temps, 32 constants; ps_3_0: 32 temps, 224
//            constants, 10 input registers).
//  [texld]   "texld - ps_2_0 and up": without D3DPSHADERCAPS2_0_NODEPENDENTREADLIMIT a texture
//            instruction may be dependent up to third order, i.e. 4 levels of texture indirection
//            (ps_2_0, and ps_2_b which keeps the limit of 4); ps_3_0 has none.
//  [mods]    "Pixel/Vertex Shader Source Register Modifiers": negate on every version, _abs only on
//            ps_3_0 / vs_3_0. "Instruction modifiers": _sat on every ps_2_0+ instruction except frc,
//            sincos and tex*; on vertex shaders only from vs_3_0.
//  [output]  "Output Color Register": in shader model 2, oC# can only be written with mov.
//  [tex ops] texldb (tex2Dbias) and texldp exist from ps_2_0; texldl (tex2Dlod) only in ps_3_0 and
//            vs_3_0; texldd (tex2Dgrad) in ps_2_a and ps_3_0, "not supported by ps_2_b".
//  [vs]      vs_2_0: 12 temps, >= 256 constants, no texture sampling, no cmp; vs_3_0: 32 temps,
//            >= 256 constants, 4 vertex texture samplers (texldl only). The temps: "D3DVS20CAPS"
//            (D3DVS20_MIN_NUMTEMPS 12, what vs_2_0 guarantees; vs_2_x may offer up to 32) and
//            "Vertex Shader Differences", vs_3_0 Features (temporary registers increased to 32).
//
// Limits are the guaranteed minimums (a ps_3_0 card may offer more slots; fxc targets 512).

#include <stdexcept>
#include <string>
#include <string_view>

namespace luxel::shading {

enum class ShaderModel { ps_2_0, ps_2_b, ps_3_0, vs_2_0, vs_3_0 };

inline constexpr int kUnlimited = 1 << 30;

/// What one shader model allows. A limit of kUnlimited means the model has none.
struct ShaderModelCaps {
  ShaderModel model;
  std::string_view name;
  bool pixel;                  ///< pixel shader (else vertex shader)
  int arithmetic_slots;        ///< arithmetic budget on its own (ps_2_0: 64), else kUnlimited
  int texture_slots;           ///< texture budget on its own (ps_2_0: 32), else kUnlimited
  int total_slots;             ///< arithmetic + texture together
  int temps;                   ///< temporary registers r#
  int constants;               ///< float4 constant registers c# (uniforms + literals)
  int texture_indirections;    ///< levels of dependent texture reads (first read counts 1)
  int samplers;                ///< sampler registers s#
  int inputs;                  ///< interpolated input registers (t# + v#, or v#)
  bool abs_modifier;           ///< `_abs` source modifier: abs() is free
  bool sat_modifier;           ///< `_sat` result modifier: saturate() of a fresh result is free
  bool cmp;                    ///< has cmp (pixel shaders); vertex shaders select with sge/slt + lrp
  bool output_by_mov_only;     ///< shader model 2: every output costs one mov
  bool arbitrary_swizzle;      ///< texture coordinates may be swizzled without a mov
  bool texldl;                 ///< tex2Dlod
  bool texldd;                 ///< tex2Dgrad
  bool texture_fetch;          ///< can sample textures at all
};

inline constexpr ShaderModelCaps kShaderModels[] = {
    // model             name     pixel arith tex  total temps consts indirections  samp in
    {ShaderModel::ps_2_0, "ps_2_0", true, 64, 32, 96, 12, 32, 4, 16, 10,
     /*abs*/ false, /*sat*/ true, /*cmp*/ true, /*mov out*/ true, /*swizzle*/ false,
     /*texldl*/ false, /*texldd*/ false, /*fetch*/ true},
    {ShaderModel::ps_2_b, "ps_2_b", true, kUnlimited, kUnlimited, 512, 32, 32, 4, 16, 10,
     false, true, true, true, false, false, false, true},
    {ShaderModel::ps_3_0, "ps_3_0", true, kUnlimited, kUnlimited, 512, 32, 224, kUnlimited, 16, 10,
     true, true, true, false, true, true, true, true},
    {ShaderModel::vs_2_0, "vs_2_0", false, kUnlimited, kUnlimited, 256, 12, 256, kUnlimited, 0, 16,
     false, false, false, false, true, false, false, false},
    {ShaderModel::vs_3_0, "vs_3_0", false, kUnlimited, kUnlimited, 512, 32, 256, kUnlimited, 4, 16,
     true, true, false, false, true, true, false, true},
};

constexpr const ShaderModelCaps& caps(ShaderModel model) {
  return kShaderModels[static_cast<int>(model)];
}

static_assert(caps(ShaderModel::ps_2_0).arithmetic_slots + caps(ShaderModel::ps_2_0).texture_slots ==
              caps(ShaderModel::ps_2_0).total_slots);
static_assert(caps(ShaderModel::ps_3_0).constants == 224 && caps(ShaderModel::ps_2_b).constants == 32);
static_assert(caps(ShaderModel::vs_3_0).model == ShaderModel::vs_3_0, "rows in enum order");
static_assert(caps(ShaderModel::vs_2_0).total_slots == 256 && caps(ShaderModel::vs_2_0).temps == 12);
static_assert(caps(ShaderModel::vs_3_0).total_slots == 512 && caps(ShaderModel::vs_3_0).temps == 32);

/// The model named `name` ("ps_2_0", "vs_3_0", ...); throws std::invalid_argument for any other.
inline ShaderModel parse_model(std::string_view name) {
  for (const ShaderModelCaps& c : kShaderModels)
    if (c.name == name) return c.model;
  throw std::invalid_argument("unknown shader model '" + std::string(name) + "'");
}

/// The same, for the pixel-shader models only (ps_2_0, ps_2_b, ps_3_0).
inline ShaderModel parse_pixel_model(std::string_view name) {
  const ShaderModel m = parse_model(name);
  if (!caps(m).pixel) throw std::invalid_argument("'" + std::string(name) + "' is not a pixel-shader model");
  return m;
}

}  // namespace luxel::shading
