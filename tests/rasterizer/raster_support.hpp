#pragma once
// Shared helpers of the rasterizer tests: independent oracles written from the Direct3D rules
// (not from the library's internals), functors, and read-back.
//
// Conventions of the oracles (from state.hpp / msaa.hpp, restated here from D3D10):
// - screen space x right, y down; pixel (x, y) covers [x, x+1) x [y, y+1), center (x+.5, y+.5);
// - viewport: x_s = vp.x + (ndc_x + 1) * w/2, y_s = vp.y + (1 - ndc_y) * h/2;
// - vertices snapped to 1/256 pixel, round-half-even of x_s * 256;
// - a sample is covered when it lies strictly inside the triangle, or exactly on a top edge
//   (horizontal, the third vertex below it) or a left edge (not horizontal, interior to its right);
// - sample positions: the D3D10.1 standard patterns (literal tables below, 1/16 pixel from the
//   pixel center).

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/draw_definition.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/simd.hpp"
#include "luxel/rasterizer/state.hpp"

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace luxel::rasterizer::test {

// --- Budget ------------------------------------------------------------------------------------

/// Sanitizer (ASan and TSan: LUXEL_SANITIZE_BUILD) and unoptimized builds run fewer and smaller cases.
#if defined(LUXEL_SANITIZE_BUILD) || !defined(__OPTIMIZE__)
inline constexpr bool kReducedRun = true;
#else
inline constexpr bool kReducedRun = false;
#endif
constexpr int budget(int full, int reduced) { return kReducedRun ? reduced : full; }

// --- D3D10.1 standard sample patterns (independent literal copy) ------------------------------

struct Offset16 {
  int x, y;  ///< 1/16 pixel from the pixel center, x right, y down
};
/// D3D11_STANDARD_MULTISAMPLE_PATTERN positions for 1, 2, 4, 8 (and 16, unused) samples.
std::span<const Offset16> d3d_pattern(int samples);

/// Absolute sample position in subpixels (1/256 pixel).
inline int64_t sample_sub_x(int px, Offset16 o) { return int64_t(px) * 256 + 128 + 16 * o.x; }
inline int64_t sample_sub_y(int py, Offset16 o) { return int64_t(py) * 256 + 128 + 16 * o.y; }

// --- Numbers -------------------------------------------------------------------------------------

/// Round half to even, in double (no dependence on the FP rounding mode).
int64_t round_half_even(double v);
/// Round-half-even of v * 255 for v in [0, 1] (NaN -> 0), the UNORM8 rule of D3D10.
int unorm8(double v);
/// sRGB transfer functions, exact formulas, in double.
double srgb_to_linear(double s);
double linear_to_srgb(double l);

inline uint32_t rgba8(int r, int g, int b, int a) {
  return uint32_t(r) | uint32_t(g) << 8 | uint32_t(b) << 16 | uint32_t(a) << 24;
}
inline int channel(uint32_t v, int c) { return int((v >> (8 * c)) & 255u); }

// --- Viewport and pixel rectangle ----------------------------------------------------------------

/// The viewport transform of a draw, in double.
struct ViewportMap {
  double x = 0, y = 0, w = 0, h = 0;  ///< resolved (width 0 = target width)
  ViewportMap() = default;
  ViewportMap(const Viewport& vp, int target_w, int target_h);

  glm::dvec2 screen_from_ndc(double nx, double ny) const { return {x + (nx + 1) * w / 2, y + (1 - ny) * h / 2}; }
  /// Clip position (w = clip_w) that the library maps exactly onto screen point (sx, sy): the
  /// caller keeps sx, sy on the 2^-10 pixel grid within 2^14 pixels of the viewport origin and
  /// uses a power-of-two viewport size, so that every float operation of the transform is
  /// exact. Records a test failure if that is not so.
  glm::vec4 clip_from_screen(double sx, double sy, float z = 0.5f, float clip_w = 1.0f) const;
};

struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< half-open
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};
/// True when the sample lies in the viewport rectangle [x, x + w) x [y, y + h).
bool inside_viewport(const ViewportMap& m, int px, int py, Offset16 o);
/// Pixels a draw may write: the target, the pixels the viewport rectangle overlaps (state.hpp;
/// exact pixel bounds for the whole-pixel viewports of D3D9/10) and the scissor.
PixelRect writable_rect(const PipelineState& state, int target_w, int target_h);

// --- Coverage oracles ---------------------------------------------------------------------------

enum class Cover : uint8_t { Out = 0, In = 1, Unknown = 2 };

/// A triangle on snapped vertices (subpixels), evaluated exactly in int64 with the top-left rule.
struct ExactTriangle {
  int64_t X[3] = {}, Y[3] = {};
  int64_t area2 = 0;  ///< > 0: clockwise on screen (y down)

  ExactTriangle() = default;
  ExactTriangle(const int64_t X_[3], const int64_t Y_[3]);
  /// From screen positions (pixels), snapping each to 1/256 pixel with round-half-even.
  static ExactTriangle from_screen(const glm::dvec2 v[3]);
  bool covers(int64_t sx, int64_t sy) const;
  bool edge_is_top_left(int i) const;  ///< edge v[i] -> v[(i+1)%3]
};

/// A convex polygon known only up to eps pixels (clipped or perspective-divided in float by the
/// library): samples farther than eps from its boundary are In or Out, the others Unknown.
struct FuzzyPolygon {
  std::vector<glm::dvec2> v;  ///< pixels, either winding
  double area2 = 0;           ///< signed doubled area, > 0 clockwise on screen
  double eps = 1.0 / 64;
  Cover classify(double x, double y) const;
};

/// What one submitted triangle covers, as the oracle sees it (after culling and clipping).
struct RefPrimitive {
  bool exact = true;
  bool empty = false;           ///< fuzzy: nothing left after clipping
  bool culled = false;          ///< known to be culled or degenerate (covers nothing)
  bool winding_unknown = false; ///< fuzzy with near-zero area: culling may go either way
  ExactTriangle tri;
  FuzzyPolygon poly;
  int bx0 = 0, by0 = 0, bx1 = 0, by1 = 0;  ///< pixel bounds of possible coverage (half-open)

  Cover cover(int px, int py, Offset16 o) const;
};

/// An exactly representable triangle given in screen pixels (w = 1, no clipping).
RefPrimitive make_exact_primitive(const glm::dvec2 screen[3], CullMode cull);
/// A triangle (or any convex planar polygon) given in clip space, clipped in double against near
/// (z >= 0) and far (z <= w), projected with `map`; known up to eps pixels.
RefPrimitive make_fuzzy_primitive(std::span<const glm::vec4> clip, const ViewportMap& map, CullMode cull, double eps);

/// The primitive under another cull mode.
RefPrimitive with_cull(RefPrimitive p, CullMode cull);

/// Calls fn(px, py, s, cover) for every sample of `rect` that the primitive may cover.
void for_each_sample(const RefPrimitive& p, const PixelRect& rect, int samples,
                     const std::function<void(int, int, int, Cover)>& fn);

// --- Clip-space polygon clipping in double (for fuzzy oracles) ----------------------------------

/// Sutherland-Hodgman against dot(plane, v) >= 0.
std::vector<glm::dvec4> clip_polygon(const std::vector<glm::dvec4>& poly, const glm::dvec4& plane);
std::vector<glm::dvec4> clip_near_far(const std::vector<glm::dvec4>& poly);

// --- Functors -------------------------------------------------------------------------------------

/// Vertices from arrays: position and N float4 varyings per vertex.
template <int N>
struct ArrayVS {
  static constexpr int kVaryings = N;
  const glm::vec4* positions = nullptr;
  const std::array<glm::vec4, N>* varyings = nullptr;
  void operator()(uint32_t i, VertexOutput<N>& out) const {
    out.position = positions[i];
    if constexpr (N > 0) {
      if (varyings) {
        out.varyings = varyings[i];
      } else {
        out.varyings.fill(glm::vec4(0.0f));
      }
    }
  }
};
/// Positions and one (zero) varying; ArrayVS<0> is the varying-free case.
using PositionVS = ArrayVS<1>;

/// Writes one constant color.
struct ConstantPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  glm::vec4 color{1.0f};
  template <int N>
  void operator()(const PixelInput<N>&, PixelOutput& out) const {
    out.color = {simd::Float(color.r), simd::Float(color.g), simd::Float(color.b), simd::Float(color.a)};
  }
};

/// Writes varying 0.
struct VaryingPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  void operator()(const PixelInput<1>& in, PixelOutput& out) const { out.color = in.varyings[0]; }
};

/// Lane values of a SIMD float.
inline std::array<float, simd::kLanes> lanes_of(const simd::Float& v) {
  alignas(64) std::array<float, simd::kLanes> a;
  v.store_aligned(a.data());
  return a;
}
inline simd::Float from_lanes(const std::array<float, simd::kLanes>& a) { return simd::Float::load_unaligned(a.data()); }

// --- Read-back -----------------------------------------------------------------------------------

/// Every sample of a color target, index (y * width + x) * samples + s. Flushes first.
std::vector<uint32_t> read_color(Context& ctx, const ColorTarget& t);
inline size_t sample_index(int w, int samples, int x, int y, int s) {
  return (size_t(y) * w + x) * samples + s;
}

/// Short description of a clip-space triangle, for failure messages.
std::string describe(const glm::vec4 clip[3]);
/// Failure messages, one per line.
std::string join(const std::vector<std::string>& lines);
std::string describe(const glm::dvec2 screen[3]);

}  // namespace luxel::rasterizer::test
