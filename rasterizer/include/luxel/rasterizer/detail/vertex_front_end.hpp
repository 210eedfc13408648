#pragma once
// The vertex stage of a draw's front end: the vertex functor run over a chunk of triangles (for
// indexed geometry through a small post-transform cache), its outputs handed on in batches to
// process_triangles, which clips, sets up and bins them (detail/triangle_setup.hpp, compiled once
// in rasterizer/src). A header because it is templated on the vertex functor, which it inlines.

#include "luxel/rasterizer/detail/triangle_setup.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/rasterizer/simd.hpp"

#include <glm/vec4.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace luxel::rasterizer::detail {

/// Runs the vertex functor for a chunk of triangles and sets them up into `bins`.
template <class VS>
void front_end_chunk(const DrawConstants& dc, const Geometry& geometry, const VS& vs, uint32_t first, uint32_t last,
                     ChunkBins& bins, DrawStats& stats) {
  constexpr int N = VS::kVaryings;
  using Vertex = VertexOutput<N>;
  // Setup reads the position and then N float4 varyings from one pointer.
  static_assert(N == 0 || sizeof(Vertex) == sizeof(glm::vec4) * (1 + N), "position and varyings must be contiguous");
  if (geometry.index_format == Geometry::IndexFormat::None) {
    Vertex v[kFrontEndBatch][3];
    const glm::vec4* positions[3 * kFrontEndBatch];
    for (int i = 0; i < kFrontEndBatch; ++i)
      for (int k = 0; k < 3; ++k) positions[3 * i + k] = &v[i][k].position;
    for (uint32_t base = first; base < last; base += kFrontEndBatch) {
      const int n = static_cast<int>(std::min<uint32_t>(kFrontEndBatch, last - base));
      if constexpr (VertexInputAddress<VS>) {
        const uint32_t ahead = base + kFrontEndBatch, ahead_end = std::min<uint32_t>(last, ahead + kFrontEndBatch);
        for (uint32_t i = 3 * ahead; i < 3 * ahead_end; ++i) simd::prefetch(vs.input(i));
      }
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) vs(3 * (base + i) + k, v[i][k]);
      process_triangles(dc, positions, n, bins, stats);
    }
    return;
  }
  // A small direct-mapped post-transform cache: shared vertices are shaded once most of the time.
  // A vertex whose slot holds another one that the pending batch still reads is shaded into
  // the batch's own spill space instead: evicting would mean running the batch early, and a
  // mesh whose rows are about a cache size long (a grid) would then run batches of one or two
  // triangles. Without FastPath::VertexCache every vertex of every triangle is spilled.
  constexpr uint32_t kCacheSize = 128;
  const bool use_cache = dc.fast_paths.on(FastPath::VertexCache);
  struct Entry {
    uint32_t index = ~0u;
    uint32_t batch = ~0u;  ///< the last batch that reads this entry
    Vertex out;
  };
  std::vector<Entry> cache(kCacheSize);
  Vertex spill[kFrontEndBatch][3];
  const glm::vec4* pending[3 * kFrontEndBatch];  // vertex k of pending triangle t at 3 t + k
  int pending_count = 0;
  uint32_t batch = 0;
  auto run_batch = [&] {
    if (pending_count == 0) return;
    process_triangles(dc, pending, pending_count, bins, stats);
    pending_count = 0;
    ++batch;
  };
  for (uint32_t tri = first; tri < last; ++tri) {
    if constexpr (VertexInputAddress<VS>) {
      if (tri + kFrontEndBatch < last)
        for (int k = 0; k < 3; ++k) {
          const uint32_t ahead = geometry.index(3 * (tri + kFrontEndBatch) + k);
          if (ahead < geometry.vertex_count) simd::prefetch(vs.input(ahead));
        }
    }
    uint32_t idx[3];
    bool bad = false;
    for (int k = 0; k < 3; ++k) {
      idx[k] = geometry.index(3 * tri + k);
      bad |= idx[k] >= geometry.vertex_count;
    }
    if (bad) {
      ++stats.bad_index;
      continue;
    }
    const glm::vec4** p = pending + 3 * pending_count;
    for (int k = 0; k < 3; ++k) {
      const uint32_t slot = idx[k] % kCacheSize;
      if (!use_cache || (cache[slot].index != idx[k] && cache[slot].batch == batch)) {
        vs(idx[k], spill[pending_count][k]);
        p[k] = &spill[pending_count][k].position;
        continue;
      }
      Entry& e = cache[slot];
      if (e.index != idx[k]) {
        vs(idx[k], e.out);
        e.index = idx[k];
      }
      e.batch = batch;
      p[k] = &e.out.position;
    }
    if (++pending_count == kFrontEndBatch) run_batch();
  }
  run_batch();
}

}  // namespace luxel::rasterizer::detail
