// Water in the catalog (catalog_entries.hpp): every combo of the registry.

#include "catalog_entries.hpp"

namespace luxel::shading::source::detail {

void add_water(std::vector<ShaderVariant>& out) {
  static const WaterParams p = water_constants(WaterMaterial{}, HdrType::integer, ToneMapConstants{});
  for_each_combo<kWaterSpace>([&]<WaterCombo C>() {
    auto shade = []<class L>(const auto& get) {
      WaterNormalTexels<L> t;
      t.n0 = float4<L>(get(0), get(1), get(2), get(3));
      t.n1 = float4<L>(get(4), get(5), get(6), get(7));
      t.n2 = float4<L>(get(8), get(9), get(10), get(11));
      WaterInputs<L> in;
      in.tangent_eye = float3<L>(get(12), get(13), get(14));
      in.reflect_refract = float4<L>(get(15), get(16), get(17), get(18));
      in.w = get(19);
      in.proj_z = get(20);
      in.world_z = get(21);
      auto target = [](const float2<L>& uv) { return float4<L>(uv.x, uv.y, uv.x * uv.y, uv.y); };
      return water_combine<C>(t, in, p, target, target);
    };
    out.push_back(variant("Water", "water", C, C.builds(), 22, shade, registry_cost<C>));
  });
}

}  // namespace luxel::shading::source::detail
