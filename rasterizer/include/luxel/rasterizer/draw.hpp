#pragma once
// Drawing: indexed triangle lists through a vertex functor and a pixel functor.
//
//   VertexFunctor: struct with `static constexpr int kVaryings` (0..kMaxVaryings) and
//     void operator()(uint32_t vertex_index, VertexOutput<kVaryings>& out) const;
//   It writes the clip-space position and the float4 interpolants of one vertex. It is called
//   from several threads at once (and possibly more than once per vertex), so it must be a pure
//   function of the index. It may also say where a vertex's inputs start:
//     const void* input(uint32_t vertex_index) const;
//   the front end then prefetches them a batch of triangles ahead (a vertex stream larger than
//   the caches, as W2's 48 MB, otherwise stalls every vertex on memory).
//
//   PixelFunctor: struct with `static constexpr bool kCanDiscard` (texkill/clip: it may set
//   PixelOutput::discard), `static constexpr bool kWritesDepth` (it sets PixelOutput::depth) and
//     void operator()(const PixelInput<N>& in, PixelOutput& out) const;
//   It shades one stamp: simd::kLanes pixels as 2x2 quads (see simd.hpp), interpolants already
//   perspective-correct at pixel centers. Lanes outside `in.live` are helpers: they complete a
//   quad for derivatives and are never written. A functor of a few instructions (an interpolant
//   or a constant out, as depth-only, UI and the W1/W2 workloads' shaders) may say so:
//     static constexpr bool kTrivial = true;
//   then a stamp whose samples all failed the early depth test is shaded with no live lane
//   (writing nothing) instead of branched around: on depth-mixed geometry that branch
//   mispredicts often, and a misprediction costs more than such a shader. Its draws also test
//   depth with the compare function compiled in (FastPath::FixedDepthPaths), which pays where
//   per-stamp overheads weigh as much as the shading and costs compile time everywhere else.
//   Only kTrivial functors are inlined into a tile rasterizer of their own; every other functor
//   is called through a pointer from tile rasterizers that the library compiles once per varying
//   count (detail/called_shader.hpp): a draw with a new shader compiles its vertex functor's front
//   end and nothing of the tile loop. Either way the draw keeps a copy of the pixel functor until
//   it has run (at the context's next flush).
//
// The pipeline: vertex functor -> clip (near, far, guard band) -> snap to 1/256 pixel -> cull ->
// setup -> bin into tiles -> per tile, in submission order: coverage per sample, early depth /
// stencil when the pixel functor can neither discard nor write depth (and alpha test is off),
// pixel functor, late depth/stencil otherwise, blend, write. Output bytes do not depend on the
// number of threads. The same draw writes an rgba8 or an rgba32f color target (framebuffer.hpp),
// chosen per draw by the target's format: the pixel functor does not know which.

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/limits.hpp"
#include "luxel/rasterizer/simd.hpp"
#include "luxel/rasterizer/state.hpp"

#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace luxel::rasterizer {

template <int N>
struct VertexOutput {
  glm::vec4 position;                ///< clip space (D3D: 0 <= z <= w inside)
  std::array<glm::vec4, N> varyings;
};

template <int N>
struct PixelInput {
  simd::Float x, y;                       ///< pixel centers (x + 0.5, y + 0.5)
  std::array<simd::Float4, N> varyings;   ///< perspective-correct at the pixel centers
  simd::LaneBits live = 0;                ///< lanes with coverage; the others are helpers
  bool front_facing = true;
};

struct PixelOutput {
  simd::Float4 color;         ///< linear; an rgba8 target clamps it to [0, 1] (NaN writes 0), an rgba32f one keeps it
  simd::Float depth;          ///< used only when the functor declares kWritesDepth
  simd::LaneBits discard = 0; ///< lanes to kill (only honoured when kCanDiscard)
};

template <class VS>
concept VertexFunctor = requires(const VS& vs, uint32_t i, VertexOutput<VS::kVaryings>& out) {
  requires VS::kVaryings >= 0 && VS::kVaryings <= kMaxVaryings;
  vs(i, out);
};

/// A vertex functor that says where vertex i's inputs start (see above).
template <class VS>
concept VertexInputAddress = requires(const VS& vs, uint32_t i) {
  { vs.input(i) } -> std::convertible_to<const void*>;
};

template <class PS, int N>
concept PixelFunctor = requires(const PS& ps, const PixelInput<N>& in, PixelOutput& out) {
  { PS::kCanDiscard } -> std::convertible_to<bool>;
  { PS::kWritesDepth } -> std::convertible_to<bool>;
  ps(in, out);
};

/// A pixel functor that declares itself trivial (see above).
template <class PS>
inline constexpr bool kTrivialPixelFunctor = requires { requires PS::kTrivial; };

/// Which vertices make the triangles: every three indices (or, without indices, every three
/// consecutive vertices) are one triangle. Triangles with an index >= vertex_count are dropped.
struct Geometry {
  enum class IndexFormat : uint8_t { None, U16, U32 };
  uint32_t vertex_count = 0;
  IndexFormat index_format = IndexFormat::None;
  const void* indices = nullptr;
  uint32_t index_count = 0;

  static Geometry non_indexed(uint32_t vertex_count) { return {vertex_count, IndexFormat::None, nullptr, 0}; }
  static Geometry indexed(std::span<const uint16_t> idx, uint32_t vertex_count) {
    return {vertex_count, IndexFormat::U16, idx.data(), static_cast<uint32_t>(idx.size())};
  }
  static Geometry indexed(std::span<const uint32_t> idx, uint32_t vertex_count) {
    return {vertex_count, IndexFormat::U32, idx.data(), static_cast<uint32_t>(idx.size())};
  }
  uint32_t triangle_count() const {
    return (index_format == IndexFormat::None ? vertex_count : index_count) / 3;
  }
  uint32_t index(uint32_t i) const {
    switch (index_format) {
      case IndexFormat::U16: return static_cast<const uint16_t*>(indices)[i];
      case IndexFormat::U32: return static_cast<const uint32_t*>(indices)[i];
      default: return i;
    }
  }
};

/// What happened to a draw's triangles (a counter for every path, as llvmpipe keeps them).
struct DrawStats {
  uint64_t triangles = 0;          ///< submitted
  uint64_t bad_index = 0;          ///< dropped: index out of range
  uint64_t non_finite = 0;         ///< dropped: NaN/Inf position
  uint64_t outside = 0;            ///< trivially rejected against the view volume
  uint64_t clipped = 0;            ///< went through the clipper
  uint64_t clip_overflow = 0;      ///< of those, dropped: rounding made more pieces than the clipper holds
  uint64_t culled = 0;             ///< back-face (cull mode) culled
  uint64_t degenerate = 0;         ///< zero area after snapping, or nothing inside the scissor
  uint64_t rasterized = 0;         ///< set up and binned (clipped pieces count one each)
  uint64_t small_walks = 0;        ///< (triangle, tile) pairs walked by the small-triangle path
  uint64_t constant_depth = 0;     ///< (triangle, tile) pairs rasterized with one depth (FastPath::ConstantDepth)
  uint64_t blocks_full = 0;        ///< 16x16 blocks found fully covered (their stamps count as full)
  uint64_t stamps_full = 0;        ///< stamps found fully covered without per-sample tests
  uint64_t stamps_partial = 0;     ///< stamps that needed per-sample edge tests
  uint64_t stamps_wide_edges = 0;  ///< of those, stamps evaluated with 64-bit edges
  uint64_t stamps_shaded = 0;      ///< pixel functor invocations (stamps)
  uint64_t tile_memory_targets = 0;  ///< targets flushes kept in tile memory (FastPath::TileMemory)

  DrawStats& operator+=(const DrawStats& o);
};

/// Draws into `fb` with `state`: runs the vertex functor and bins the triangles now, and records
/// the rest for the context's next flush (see Context). Throws std::invalid_argument when the
/// framebuffer's targets disagree in size or sample count, the viewport is invalid (see
/// Viewport), or the state blends or writes sRGB into an rgba32f color target. The samples that pass count into the context's active occlusion query, if any; the
/// counters go to Context::stats().
/// Defined in draw_definition.hpp, which a file that calls draw() includes.
template <VertexFunctor VS, PixelFunctor<VS::kVaryings> PS>
void draw(Context& ctx, const Framebuffer& fb, const PipelineState& state, const Geometry& geometry,
               const VS& vertex_shader, const PS& pixel_shader);

}  // namespace luxel::rasterizer
