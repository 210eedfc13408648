// A view's matrices and draws (views.hpp).

#include "views.hpp"

#include "luxel/rasterizer/draw_definition.hpp"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/ext/vector_double3.hpp>
#include <glm/geometric.hpp>

#include <atomic>
#include <utility>

namespace luxel::frame {

ViewMatrices view_matrices(const scenes::Camera& c, int width, int height) {
  const glm::dvec3 eye(c.position), target(c.target);
  glm::dvec3 up(c.up);
  // An up along the line of sight (looking straight down with +Z up) has no screen direction:
  // screen up is then +Y.
  const glm::dvec3 forward = glm::normalize(target - eye);
  if (glm::length(glm::cross(forward, glm::normalize(up))) < 1e-6) up = glm::dvec3(0, 1, 0);
  ViewMatrices m;
  m.view = glm::lookAtRH(eye, target, up);
  const double n = c.near_plane, f = c.far_plane;
  if (c.projection == scenes::Projection::orthographic) {
    const double half_h = 0.5 * c.ortho_height;
    // (h W) / H is exact for integer h, W, H whose quotient is: the workloads' cameras.
    const double half_w = 0.5 * (c.aspect > 0 ? double(c.ortho_height) * c.aspect : double(c.ortho_height) * width / height);
    m.projection = glm::orthoRH_ZO(-half_w, half_w, -half_h, half_h, n, f);
  } else {
    const double aspect = c.aspect > 0 ? double(c.aspect) : double(width) / height;
    m.projection = glm::perspectiveRH_ZO(double(c.vertical_fov), aspect, n, f);
  }
  return m;
}

int draw_count(const PassList& passes) {
  return static_cast<int>(passes.opaque.size() + passes.sky.size() + passes.translucent.size());
}

void run_passes(rasterizer::Context& ctx, const rasterizer::Framebuffer& fb, PassList& passes, PassClock* clock) {
  const std::pair<const char*, std::vector<Pass>*> lists[] = {
      {"opaque", &passes.opaque}, {"sky", &passes.sky}, {"translucent", &passes.translucent}};
  for (const auto& [name, list] : lists) {
    const auto run = [&, list = list] {
      for (Pass& p : *list) {
        if (p.trivial) {
          rasterizer::draw(ctx, fb, p.state, p.geometry, *p.trivial, UnlitPixel{});
        } else {
          p.source->pixels->store(0, std::memory_order_relaxed);
          p.source->run(ctx, fb);
        }
      }
    };
    if (!clock) run();
    else if (!list->empty()) clock->run(name, static_cast<int>(list->size()), run);
  }
}

void add_shader_uses(const PassList& passes, std::vector<ShaderUse>& uses) {
  for (auto* list : {&passes.opaque, &passes.sky, &passes.translucent})
    for (const Pass& p : *list)
      if (p.source)
        shading::source::add_shader_use(
            uses, {p.source->family, p.source->combo, p.source->pixels->load(std::memory_order_relaxed), p.source->binary,
                   p.source->slots});
}

}  // namespace luxel::frame
