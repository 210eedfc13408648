// UnlitGeneric and non-bumped VertexLitGeneric in the catalog (catalog_entries.hpp): every
// combo of the registry.

#include "catalog_entries.hpp"

namespace luxel::shading::source::detail {

void add_unlit(std::vector<ShaderVariant>& out) {
  static UnlitGenericParams p = [] {
    UnlitGenericParams q;
    q.envmap_contrast = glm::vec4(0.5f);
    return q;
  }();
  for_each_combo<kUnlitSpace>([&]<UnlitCombo C>() {
    auto shade = []<class L>(const auto& get) {
      UnlitTexels<L> t;
      t.base = float4<L>(get(0), get(1), get(2), get(3));
      t.detail = float4<L>(get(4), get(5), get(6), get(7));
      t.mask = float3<L>(get(8), get(9), get(10));
      UnlitInputs<L> in;
      in.vertex_color = float4<L>(get(11), get(12), get(13), get(14));
      in.eye_vector = float3<L>(get(15), get(16), get(17));
      in.normal = float3<L>(get(18), get(19), get(20));
      in.fog = FogInputs<L>{get(21), get(22)};
      return unlit_generic_combine<C>(t, in, p, [](const float3<L>& r) { return r * r; });
    };
    // DIFFUSELIGHTING is VertexLitGeneric without a bump map: listed, and asked for, under it.
    out.push_back(variant(C.family(), C.diffuse_lighting ? "vertexlit" : "unlit", C, C.builds(), 23, shade,
                          registry_cost<C>));
  });
}

}  // namespace luxel::shading::source::detail
