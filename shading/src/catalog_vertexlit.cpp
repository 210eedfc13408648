// Per-pixel VertexLitGeneric without an env map in the catalog (catalog_vertexlit.hpp).

#include "catalog_vertexlit.hpp"

#include "luxel/shading/source/normalization_cube.hpp"

namespace luxel::shading::source::detail {

const VertexLitParams& vertexlit_timing_params() {
  static const rasterizer::Texture normalization_cube = normalization_cube_map();
  static const VertexLitParams p = [] {
    VertexLitParams q;
    for (auto& l : q.lights) {
      l.color = glm::vec4(1.0f, 0.8f, 0.6f, 0.0f);
      l.position = glm::vec4(2.0f, 1.0f, 3.0f, 1.0f);
    }
    q.normalization_cube.texture = &normalization_cube;
    return q;
  }();
  return p;
}

void add_vertexlit_plain(std::vector<ShaderVariant>& out) {
  add_vertexlit<subset<kVertexLitSpace, [](const VertexLitCombo& c) { return !c.envmap; }>()>(out);
}

}  // namespace luxel::shading::source::detail
