// The frame's combos counted on the Counted lane (combo_slots.hpp), each answer kept.

#include "combo_slots.hpp"

#include "combo_spaces.hpp"

#include "luxel/shading/source/adapter.hpp"

#include <array>
#include <atomic>
#include <stdexcept>
#include <string>

namespace luxel::frame::detail {

namespace {

constexpr size_t kModels = 5;  // shading::ShaderModel's values

/// What count(C, model) gives for the C of kSpace equal to `combo`, counted once per combo and
/// model (stored + 1; 0: not counted yet). Two threads asking at once both count and store the
/// same number.
template <auto kSpace, class Combo, class Count>
int kept(const char* family, const Combo& combo, shading::ShaderModel model, Count count) {
  static std::array<std::atomic<int>, kSpace.size() * kModels> answers{};
  const int i = index_in<kSpace>(combo);
  if (i < 0) throw std::logic_error(std::string(family) + " combo " + combo.name() + " is outside the frame's combo space");
  std::atomic<int>& answer = answers[size_t(i) * kModels + size_t(model)];
  if (const int a = answer.load(std::memory_order_relaxed)) return a - 1;
  int value = 0;
  with_combo<kSpace>(combo, [&]<Combo C>() { value = count.template operator()<C>(model); });
  answer.store(value + 1, std::memory_order_relaxed);
  return value;
}

}  // namespace

int lightmapped_slots(const LightmappedCombo& combo, shading::ShaderModel binary) {
  return kept<kLightmappedSpace>("LightmappedGeneric", combo, binary, []<LightmappedCombo C>(shading::ShaderModel m) {
    return measure_lightmapped_generic<C>(m).total_slots();
  });
}

int vertexlit_slots(const VertexLitCombo& combo, shading::ShaderModel binary) {
  return kept<kVertexLitSpace>("VertexLitGeneric", combo, binary, []<VertexLitCombo C>(shading::ShaderModel m) {
    return measure_vertexlit_generic<C>(m).total_slots();
  });
}

bool vertexlit_fits(const VertexLitCombo& combo, shading::ShaderModel binary) {
  if (index_in<kVertexLitSpace>(combo) < 0) return false;
  return kept<kVertexLitSpace>("VertexLitGeneric", combo, binary, [&]<VertexLitCombo C>(shading::ShaderModel m) {
           return int(vertexlit_compiles<C>(m));
         }) == 1;
}

int unlit_slots(const UnlitCombo& combo, shading::ShaderModel binary) {
  return kept<kUnlitSpace>(combo.family(), combo, binary, []<UnlitCombo C>(shading::ShaderModel m) {
    return measure_unlit_generic<C>(m).total_slots();
  });
}

int water_slots(const WaterCombo& combo, shading::ShaderModel binary) {
  return kept<kWaterSpace>("Water", combo, binary, []<WaterCombo C>(shading::ShaderModel m) {
    return measure_water<C>(m).total_slots();
  });
}

int sky_slots(shading::ShaderModel binary) {
  static constexpr std::array kSkySpace{SkyPixelShader::kCombo};  // the frame's one Sky_HDR combo
  return kept<kSkySpace>("Sky_HDR", SkyPixelShader::kCombo, binary, []<SkyCombo C>(shading::ShaderModel m) {
    return measure_sky<C>(m).total_slots();
  });
}

}  // namespace luxel::frame::detail
