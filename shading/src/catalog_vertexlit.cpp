// Per-pixel VertexLitGeneric without an env map in the catalog (catalog_vertexlit.hpp).

#include "catalog_vertexlit.hpp"

namespace luxel::shading::source::detail {

void add_vertexlit_plain(std::vector<ShaderVariant>& out) {
  add_vertexlit<subset<kVertexLitSpace, [](const VertexLitCombo& c) { return !c.envmap; }>()>(out);
}

}  // namespace luxel::shading::source::detail
