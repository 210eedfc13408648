#pragma once
// The definition of draw(). Include it where draws are instantiated: in a file that calls draw().
// draw.hpp is the contract (the functor concepts, Geometry, DrawStats, the declaration of draw())
// and includes no detail header, so a file that only names those does not parse the rasterizer's
// templates. draw() and the stages it instantiates are headers because they are templated on the
// shader functors: the vertex stage (detail/vertex_front_end.hpp), the recorded command
// (detail/draw_command.hpp) and the tile rasterizer (detail/tile_rasterizer.hpp).

#include "luxel/rasterizer/detail/command_queue.hpp"
#include "luxel/rasterizer/detail/draw_command.hpp"
#include "luxel/rasterizer/detail/tile_rasterizer.hpp"
#include "luxel/rasterizer/detail/vertex_front_end.hpp"
#include "luxel/rasterizer/draw.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace luxel::rasterizer {

template <VertexFunctor VS, PixelFunctor<VS::kVaryings> PS>
void draw(Context& ctx, const Framebuffer& fb, const PipelineState& state, const Geometry& geometry,
          const VS& vertex_shader, const PS& pixel_shader) {
  using namespace detail;
  constexpr int N = VS::kVaryings;
  const DrawPlan plan = plan_draw(fb, state, N, ctx.options().fast_paths);
  const uint32_t triangles = geometry.triangle_count();
  CommandQueue& queue = ctx.queue();
  if (!queue.accepts(plan.layout)) ctx.flush_within_frame();
  queue.set_layout(plan.layout);
  // Before the front end: a draw into a discarded target fails whatever its triangles.
  if (plan.color) ctx.refer(*plan.color);  // see Context, "The deferred frame"
  if (plan.depth_stencil) ctx.refer(*plan.depth_stencil);
  queue.front_end_stats().triangles += triangles;
  if (triangles == 0 || plan.constants.clip_x0 >= plan.constants.clip_x1 ||
      plan.constants.clip_y0 >= plan.constants.clip_y1)
    return;

  const auto recorded_shader = recorded_pixel_shader<N>(pixel_shader);
  // A large draw is recorded in parts, and the queue flushes between them once its records take
  // more than the context's budget (ContextOptions::max_pending_record_bytes).
  for (uint32_t part_first = 0; part_first < triangles;) {
    if (queue.pending_record_bytes() >= ctx.options().max_pending_record_bytes) ctx.flush_within_frame();
    const uint32_t part = std::min<uint32_t>(triangles - part_first, kTrianglesPerPart);
    // Front end now, in parallel over chunks of triangles; each chunk bins into its own lists.
    const uint32_t threads = static_cast<uint32_t>(ctx.thread_count());
    const uint32_t per_chunk = std::clamp<uint32_t>((part + threads - 1) / threads,
                                                    kMinTrianglesPerChunk, kTrianglesPerChunk);
    const int chunk_count = static_cast<int>((part + per_chunk - 1) / per_chunk);
    std::vector<ChunkBins*> chunks = queue.allocate_chunks(chunk_count);
    std::vector<DrawStats> chunk_stats(chunk_count);
    ctx.parallel_for(chunk_count, [&](int c, int) {
      const uint32_t first = part_first + static_cast<uint32_t>(c) * per_chunk;
      const uint32_t last = std::min<uint32_t>(part_first + part, first + per_chunk);
      front_end_chunk(plan.constants, geometry, vertex_shader, first, last, *chunks[c], chunk_stats[c]);
    });
    for (const DrawStats& s : chunk_stats) queue.front_end_stats() += s;
    for (const ChunkBins* c : chunks) queue.add_pending_record_bytes(c->bytes());
    const int slot = queue.query_slot(ctx.active_query());
    if (plan.color) ctx.refer(*plan.color);  // again: a flush above forgot them
    if (plan.depth_stencil) ctx.refer(*plan.depth_stencil);
    queue.push(make_draw_command<N>(plan, state, recorded_shader, std::move(chunks), slot));
    part_first += part;
  }
}

}  // namespace luxel::rasterizer
