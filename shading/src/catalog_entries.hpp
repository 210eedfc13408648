#pragma once
// Private: how a catalog variant (catalog.hpp) is made from a family's `shade`: a captureless
// generic lambda that runs the combine stage on lane L from inputs get(0), get(1), ... Its two
// entry points are compiled here, once per lane, and time_lanes / compare_lanes (catalog.cpp) run
// every variant through them. Each family adds its variants in its own file (catalog_*.cpp), so
// that the families compile in parallel.

#include "luxel/shading/source/catalog.hpp"
#include "luxel/shading/source/registry.hpp"

#include <optional>
#include <span>
#include <vector>

// Each family's constants are a static that the shade lambdas (generic, inside a template lambda)
// read; GCC 12 still calls those statics "set but not used".
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"

namespace luxel::shading::source::detail {

/// The entry points of Shade (ShaderVariant::shade_simd, shade_scalar).
template <class Shade>
struct Entries {
  static void simd_stamp(const float* in, float* out) {
    auto get = [&](int i) { return simd::Float::load_unaligned(in + static_cast<size_t>(i) * simd::kLanes); };
    const float4<simd::Float> c = Shade{}.template operator()<simd::Float>(get);
    c.x.store_unaligned(out), c.y.store_unaligned(out + simd::kLanes), c.z.store_unaligned(out + 2 * simd::kLanes),
        c.w.store_unaligned(out + 3 * simd::kLanes);
  }
  static void scalar_pixel(const float* in, float* out) {
    auto get = [&](int i) { return in[i]; };
    const float4<float> c = Shade{}.template operator()<float>(get);
    out[0] = c.x, out[1] = c.y, out[2] = c.z, out[3] = c.w;
  }
};

/// The cards of `candidates` that have a binary of the combo (`builds`) which the combo's rules
/// allow (its valid(model), where the family has one).
template <class Combo>
std::vector<ShaderModel> models_of(const Combo& combo, ShaderBuilds builds, std::span<const ShaderModel> candidates) {
  std::vector<ShaderModel> models;
  for (ShaderModel card : candidates) {
    const std::optional<ShaderModel> binary = builds.binary_for(card);
    if (!binary) continue;
    if constexpr (requires { combo.valid(*binary); }) {
      if (!combo.valid(*binary)) continue;
    }
    models.push_back(card);
  }
  return models;
}

/// The variant of `combo` of a family, its combine stage `shade` over `inputs` values per pixel.
template <class Combo, class Shade, class Measure>
ShaderVariant variant(const char* family, const char* option, const Combo& combo, ShaderBuilds builds, int inputs, Shade,
                      Measure measure, std::span<const ShaderModel> candidates = kPixelModels) {
  return {family, option, combo.name(), models_of(combo, builds, candidates), builds, measure, inputs,
          &Entries<Shade>::simd_stamp, &Entries<Shade>::scalar_pixel};
}

/// A registry combo's counted cost, as a variant's `measure`.
template <auto C>
Cost registry_cost(ShaderModel binary) {
  return counted_cost(C, binary);
}

void add_lightmapped(std::vector<ShaderVariant>& out);
void add_vertexlit_plain(std::vector<ShaderVariant>& out);
void add_vertexlit_envmap(std::vector<ShaderVariant>& out);
void add_unlit(std::vector<ShaderVariant>& out);
void add_water(std::vector<ShaderVariant>& out);
/// The vertex shader, Sky_HDR and the post-processing shaders.
void add_small_families(std::vector<ShaderVariant>& out);

}  // namespace luxel::shading::source::detail
