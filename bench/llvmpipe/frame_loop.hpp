#pragma once
// The timed frame loop every workload runs through: warm-up frames (llvmpipe compiles shader
// variants at their first draws), then N frames each timed from before the clear to after
// glFinish, as luxel_frame_bench times its own.

#include "render_targets.hpp"
#include "workload.hpp"

#include <vector>

namespace luxel::llvmpipe {

/// One frame: bind A, clear color and depth, the workload's draws, resolve A into B.
void render_frame(const Workload& workload, const RenderTargets& targets);

/// Renders `warmup` untimed frames, glFinish, then `frames` timed ones: their times in ms.
std::vector<double> time_frames(const Workload& workload, const RenderTargets& targets, int warmup, int frames);

/// The median (mean of the two middle values for an even count) and the minimum.
struct FrameStats {
  double median_ms = 0.0, min_ms = 0.0;
};
FrameStats stats_of(std::vector<double> times_ms);

}  // namespace luxel::llvmpipe
