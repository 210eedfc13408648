// VertexLitGeneric draws with an env map (vertexlit_draw_in.hpp).

#include "vertexlit_draw_in.hpp"

namespace luxel::frame::detail {

SourceDraw vertexlit_envmap_draw(const shading::source::VertexLitCombo& combo, shading::ShaderModel model,
                                 const DrawTarget& target, const shading::source::VertexLitParams& params) {
  return vertexlit_draw_in<kVertexLitEnvmapDrawn>(combo, model, target, params);
}

}  // namespace luxel::frame::detail
