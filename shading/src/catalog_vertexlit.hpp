#pragma once
// Private: per-pixel VertexLitGeneric in the catalog (catalog_entries.hpp), for a part of the
// registry's space: the combos without an env map compile in catalog_vertexlit.cpp, those with one
// in catalog_vertexlit_envmap.cpp, so that the two build in parallel.

#include "catalog_entries.hpp"

namespace luxel::shading::source::detail {

/// The constants both halves time with: two lights and the normalization cube (the ps_2_0
/// combos), made once (catalog_vertexlit.cpp).
const VertexLitParams& vertexlit_timing_params();

template <auto kCombos>
void add_vertexlit(std::vector<ShaderVariant>& out) {
  static const VertexLitParams& p = vertexlit_timing_params();
  for_each_combo<kCombos>([&]<VertexLitCombo C>() {
    auto shade = []<class L>(const auto& get) {
      VertexLitTexels<L> t;
      t.base = float4<L>(get(0), get(1), get(2), get(3));
      t.bump = float4<L>(get(4), get(5), get(6), get(7));
      t.exponent = float4<L>(get(8), get(9), get(10), get(11));
      VertexLitInputs<L> in;
      in.world_pos = float3<L>(get(12), get(13), get(14));
      in.normal = float3<L>(get(15), get(16), get(17));
      in.tangent = float3<L>(get(18), get(19), get(20));
      in.binormal = float3<L>(get(21), get(22), get(23));
      in.attenuation = float4<L>(get(24), get(25), get(26), get(27));
      in.proj_z = get(28);
      return vertexlit_combine<C>(t, in, p, [](const float3<L>& r) { return r * r; });
    };
    out.push_back(variant("VertexLitGeneric", "vertexlit", C, C.builds(), 29, shade,
                          registry_cost<C>));
  });
}

}  // namespace luxel::shading::source::detail
