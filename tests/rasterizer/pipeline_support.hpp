#pragma once
// A scalar reference of the per-sample output merger (Direct3D 9 semantics, written from the
// D3D9 documentation): alpha test, texkill, stencil test with read/write masks and the eight
// ops on fail / depth-fail / pass (two-sided by winding), the eight depth compare functions with
// depth write on/off and depth clamping to the viewport range, blending with every D3D9 factor
// and op (min/max ignore factors), separate alpha, color write mask, sRGB write (blend in linear
// space, encode after), and occlusion counting. Random small scenes are rendered by the library
// and by this reference and compared sample by sample.
//
// Exactness: triangles have constant depth from a dyadic set and dyadic viewport depth ranges,
// so every depth is exact in float; colors are mostly k/255. Where the library's float
// arithmetic legitimately rounds differently from the double reference, the reference keeps
// both neighbours: a blended or converted value whose exact value*255 lies within 1e-3 of a
// rounding boundary (x.5), or within 0.03 for sRGB encoding (the library encodes through a
// 16-bit linear table: <= 12.92 * 0.5/65535 * 255 = 0.025 steps of error). Those candidates are
// carried forward per sample (a set of possible values), so later blends stay exact.

#include "raster_support.hpp"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace luxel::rasterizer::test {

/// The test pixel shader: a pure function of the pixel and the draw's parameters, run by the
/// library's pixel functor (ScenePS) and by the reference alike.
struct ShadeParams {
  uint32_t seed = 0;
  bool discard = false;      ///< some pixels texkill
  bool write_depth = false;  ///< outputs depth (from a set that includes values outside [0, 1])
  bool allow_nan = true;     ///< some color channels are NaN
  bool trivial = false;      ///< drawn by a functor that declares kTrivial (draw.hpp), unless it discards or writes depth
};
struct ShadeResult {
  float color[4];
  bool discard;
  float depth;
};
ShadeResult shade(const ShadeParams& p, int x, int y);

struct SceneTriangle {
  glm::dvec2 screen[3];  ///< exact (1/16 pixel grid)
  float z;               ///< constant NDC depth
};

struct SceneDraw {
  PipelineState state;
  ShadeParams shade;
  std::vector<SceneTriangle> triangles;
  bool counted = false;  ///< inside the occlusion query
};

struct Scene {
  int width = 48, height = 40, samples = 1;
  bool has_color = true, has_depth_stencil = true;
  glm::vec4 clear_color{0.0f};
  float clear_depth = 1.0f;
  uint8_t clear_stencil = 0;
  std::vector<SceneDraw> draws;
  std::string describe() const;
};

/// A random scene; `samples` 1, 2, 4 or 8.
Scene random_scene(uint32_t seed, int samples);

struct SceneOutput {
  std::vector<uint32_t> color;  ///< read_color order; empty without a color target or when discarded
  std::vector<float> depth;     ///< empty when discarded
  std::vector<uint8_t> stencil;
  std::vector<uint8_t> resolved;  ///< the color target resolved (RGBA8 rows); empty without one
  uint64_t query = 0;
};
/// How render_scene ends the frame.
enum class SceneEnd {
  keep,     ///< flush, read every sample back, resolve
  discard,  ///< discard() both targets and resolve: their samples may live in tile memory
};
/// Renders with the library.
SceneOutput render_scene(Context& ctx, const Scene& scene, SceneEnd end = SceneEnd::keep);

struct SceneReference {
  std::vector<std::vector<uint32_t>> color;  ///< possible values per sample
  std::vector<float> depth;
  std::vector<uint8_t> stencil;
  uint64_t query = 0;
  uint64_t ambiguous_samples = 0;            ///< samples with more than one possible color
};
SceneReference reference_scene(const Scene& scene);

/// Compares; returns the number of mismatching samples (plus one for a wrong query count) and
/// appends up to max_messages descriptions.
int compare_scene(const Scene& scene, const SceneOutput& out, const SceneReference& ref, std::vector<std::string>& messages,
                  int max_messages);

// Pieces of the reference, exposed for focused tests.
bool ref_compare(CompareFunc f, double a, double b);
uint8_t ref_stencil_op(StencilOp op, uint8_t v, uint8_t ref);
/// Possible results (one or two per channel) of writing `src` over `dst` with `b` (the write
/// mask applied).
std::vector<uint32_t> ref_output(const BlendState& b, const float src[4], uint32_t dst);

}  // namespace luxel::rasterizer::test
