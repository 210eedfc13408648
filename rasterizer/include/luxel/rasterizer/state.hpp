#pragma once
// Fixed-function state of a draw, Direct3D 9 style. Defaults are D3D9's defaults.
//
// Conventions (D3D rules; where D3D9 left a choice to vendors, D3D10's):
// - Screen space: x right, y down, pixel (x, y) covers [x, x+1) x [y, y+1); its center is at
//   (x + 0.5, y + 0.5) (D3D10). D3D9 put pixel centers on integers, so a D3D9 screen position s
//   is the position s + 0.5 here: a D3D9 application gets its exact mapping with
//   Viewport::x = y = +0.5 (the famous half-pixel offset, moved into the viewport).
// - Viewports are whole-pixel rectangles in D3D9 and D3D10 (fractional ones arrived with D3D11).
//   A fractional origin here only shifts the mapping; the pixels that may be written are those
//   the rectangle [x, x + width) x [y, y + height) overlaps, further limited by the scissor.
// - NDC (x, y) in [-1, 1] maps to the viewport with +y at the top; depth z/w in [0, 1] maps to
//   [min_depth, max_depth]. Near (z < 0) and far (z > w) are clipped; depth is interpolated
//   linearly in screen space and clamped to [min_depth, max_depth] per sample.
// - Fill rule: top-left, on vertices snapped to 1/256 pixel.
// - Winding is judged on screen (y down). D3D9 treats clockwise triangles as front faces; set
//   RasterizerState::front_counter_clockwise for glTF/OpenGL-style content.
// - Pixel shaders run once per pixel, at the pixel center (DX9; no centroid), with helper lanes
//   completing 2x2 quads; depth, stencil and coverage are per sample.

#include <glm/vec4.hpp>

#include <cstdint>

namespace luxel::rasterizer {

enum class CullMode : uint8_t { None, CW, CCW };  ///< which winding is culled

enum class CompareFunc : uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

enum class StencilOp : uint8_t { Keep, Zero, Replace, IncrSat, DecrSat, Invert, Incr, Decr };

enum class BlendFactor : uint8_t {
  Zero, One, SrcColor, InvSrcColor, SrcAlpha, InvSrcAlpha, DestAlpha, InvDestAlpha,
  DestColor, InvDestColor, SrcAlphaSat, BlendFactor, InvBlendFactor
};

enum class BlendOp : uint8_t { Add, Subtract, RevSubtract, Min, Max };

/// Channel bits of BlendState::write_mask.
enum ColorWrite : uint8_t { kWriteRed = 1, kWriteGreen = 2, kWriteBlue = 4, kWriteAlpha = 8, kWriteAll = 15 };

struct Viewport {
  float x = 0, y = 0;           ///< top-left corner, pixels
  /// Pixels, at most kMaxTargetSize. 0 (the default) = the target's width or height, per axis,
  /// counted from x or y; negative, NaN and infinite sizes are rejected (std::invalid_argument).
  float width = 0, height = 0;
  float min_depth = 0, max_depth = 1;
};

/// Pixels outside [x0, x1) x [y0, y1) are not drawn when enabled.
struct Scissor {
  bool enable = false;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct RasterizerState {
  CullMode cull = CullMode::CCW;
  bool front_counter_clockwise = false;
  /// D3D9 depth bias: depth += depth_bias + slope_scaled_depth_bias * max(|dz/dx|, |dz/dy|).
  float depth_bias = 0;
  float slope_scaled_depth_bias = 0;
};

struct StencilFace {
  StencilOp fail = StencilOp::Keep;        ///< stencil test failed
  StencilOp depth_fail = StencilOp::Keep;  ///< stencil passed, depth failed
  StencilOp pass = StencilOp::Keep;        ///< both passed
  CompareFunc func = CompareFunc::Always;
};

struct DepthStencilState {
  bool depth_enable = true;  ///< false: no depth test and no depth write (D3D9 ZENABLE)
  bool depth_write = true;
  CompareFunc depth_func = CompareFunc::LessEqual;
  bool stencil_enable = false;
  bool two_sided_stencil = false;  ///< back faces use `back` (D3D9 TWOSIDEDSTENCILMODE)
  uint8_t stencil_ref = 0;
  uint8_t stencil_read_mask = 0xff;
  uint8_t stencil_write_mask = 0xff;
  StencilFace front, back;
};

struct BlendState {
  bool enable = false;
  BlendFactor src = BlendFactor::One, dst = BlendFactor::Zero;
  BlendOp op = BlendOp::Add;
  bool separate_alpha = false;  ///< D3D9 SEPARATEALPHABLENDENABLE
  BlendFactor src_alpha = BlendFactor::One, dst_alpha = BlendFactor::Zero;
  BlendOp op_alpha = BlendOp::Add;
  glm::vec4 blend_factor{1.0f};
  uint8_t write_mask = kWriteAll;
  /// Encode to sRGB on write (D3D9 SRGBWRITEENABLE). Blending then happens in linear space on
  /// decoded destination values (the D3D10 rule; DX9 parts differed).
  bool srgb_write = false;
};

/// DX9 alpha test: the pixel survives when (alpha as 8-bit) func ref.
struct AlphaTestState {
  bool enable = false;
  CompareFunc func = CompareFunc::Always;
  uint8_t ref = 0;
};

struct PipelineState {
  Viewport viewport;
  Scissor scissor;
  RasterizerState rasterizer;
  DepthStencilState depth_stencil;
  BlendState blend;
  AlphaTestState alpha_test;
};

}  // namespace luxel::rasterizer
