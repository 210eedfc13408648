// The llvmpipe benchmark's frame and its timing.

#include "frame_loop.hpp"

#include <GL/glcorearb.h>

#include <algorithm>
#include <chrono>

namespace luxel::llvmpipe {

void render_frame(const Workload& workload, const RenderTargets& targets) {
  targets.bind_for_drawing();
  const glm::vec4 clear = workload.clear_color();
  glClearColor(clear.r, clear.g, clear.b, clear.a);
  glClearDepth(1.0);
  glDepthMask(GL_TRUE);  // glClear honours the depth mask: a workload may have left it off
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  workload.draw();
  targets.resolve();
}

std::vector<double> time_frames(const Workload& workload, const RenderTargets& targets, int warmup, int frames) {
  for (int i = 0; i < warmup; ++i) render_frame(workload, targets);
  glFinish();
  std::vector<double> times;
  times.reserve(size_t(frames));
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    render_frame(workload, targets);
    glFinish();  // llvmpipe queues the work: the frame has ended when the driver has drawn it
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return times;
}

FrameStats stats_of(std::vector<double> times_ms) {
  if (times_ms.empty()) return {};
  std::sort(times_ms.begin(), times_ms.end());
  const size_t n = times_ms.size();
  return {n % 2 ? times_ms[n / 2] : 0.5 * (times_ms[n / 2 - 1] + times_ms[n / 2]), times_ms.front()};
}

}  // namespace luxel::llvmpipe
