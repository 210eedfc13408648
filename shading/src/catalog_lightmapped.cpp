// LightmappedGeneric in the catalog (catalog_entries.hpp): every combo of the registry.

#include "catalog_entries.hpp"

namespace luxel::shading::source::detail {

void add_lightmapped(std::vector<ShaderVariant>& out) {
  static LightmappedGenericParams p = [] {
    LightmappedGenericParams q;
    q.fresnel = fresnel_constant(0.2f);
    return q;
  }();
  for_each_combo<kLightmappedSpace>([&]<LightmappedCombo C>() {
    auto shade = []<class L>(const auto& get) {
      LightmappedTexels<L> t;
      t.base = float4<L>(get(0), get(1), get(2), get(3));
      t.bump = float4<L>(get(4), get(5), get(6), get(7));
      t.mask = float3<L>(get(8), get(9), get(10));
      for (int i = 0; i < 4; ++i) t.lightmap[i] = float3<L>(get(11), get(12), get(13)) * float(i + 1);
      LightmappedInputs<L> in;
      in.tangent = float3<L>(get(14), get(15), get(16));
      in.binormal = float3<L>(get(17), get(18), get(19));
      in.normal = float3<L>(get(20), get(21), get(22));
      in.eye_vector = float3<L>(get(23), get(24), get(25));
      in.fog = FogInputs<L>{get(26), get(27)};
      return lightmapped_generic_combine<C>(t, in, p, [](const float3<L>& r) { return r * r; });
    };
    out.push_back(variant("LightmappedGeneric", "lightmapped", C, C.builds(), 28, shade,
                          registry_cost<C>));
  });
}

}  // namespace luxel::shading::source::detail
