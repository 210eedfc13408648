// The registry's counted costs (registry.hpp): each combo run once per binary model on the
// Counted lane, the answer kept.

#include "luxel/shading/source/registry.hpp"

#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

namespace luxel::shading::source {

namespace {

constexpr size_t kModels = 5;  // ShaderModel's values

/// What count.template operator()<C>(model) gives for the C of kSpace equal to `combo`, counted
/// once per combo and model.
template <auto kSpace, class Combo, class Count>
Cost kept(const char* family, const Combo& combo, ShaderModel model, Count count) {
  static std::mutex mutex;
  static std::array<std::optional<Cost>, kSpace.size() * kModels> answers{};
  const int i = index_in<kSpace>(combo);
  if (i < 0) throw std::logic_error(std::string(family) + " combo " + combo.name() + " is outside the registry's space");
  const std::lock_guard lock(mutex);
  std::optional<Cost>& answer = answers[size_t(i) * kModels + size_t(model)];
  if (!answer) with_combo<kSpace>(combo, [&]<Combo C>() { answer = count.template operator()<C>(model); });
  return *answer;
}

}  // namespace

Cost counted_cost(const LightmappedCombo& combo, ShaderModel binary) {
  return kept<kLightmappedSpace>("LightmappedGeneric", combo, binary,
                                 []<LightmappedCombo C>(ShaderModel m) { return measure_lightmapped_generic<C>(m); });
}

Cost counted_cost(const VertexLitCombo& combo, ShaderModel binary) {
  return kept<kVertexLitSpace>("VertexLitGeneric", combo, binary,
                               []<VertexLitCombo C>(ShaderModel m) { return measure_vertexlit_generic<C>(m); });
}

Cost counted_cost(const VertexLitVsCombo& combo, ShaderModel binary) {
  return kept<kVertexLitVsSpace>("VertexLitGeneric_vs", combo, binary,
                                 []<VertexLitVsCombo C>(ShaderModel m) { return measure_vertexlit_vertex_shader<C>(m); });
}

Cost counted_cost(const UnlitCombo& combo, ShaderModel binary) {
  return kept<kUnlitSpace>(combo.family(), combo, binary,
                           []<UnlitCombo C>(ShaderModel m) { return measure_unlit_generic<C>(m); });
}

Cost counted_cost(const WaterCombo& combo, ShaderModel binary) {
  return kept<kWaterSpace>("Water", combo, binary, []<WaterCombo C>(ShaderModel m) { return measure_water<C>(m); });
}

Cost counted_cost(const SkyCombo& combo, ShaderModel binary) {
  return kept<kSkySpace>("Sky_HDR", combo, binary, []<SkyCombo C>(ShaderModel m) { return measure_sky<C>(m); });
}

Cost counted_cost(const LuminanceRangeCombo& combo, ShaderModel binary) {
  return kept<kLuminanceRangeSpace>("LuminanceRange", combo, binary,
                                    []<LuminanceRangeCombo C>(ShaderModel m) { return measure_luminance_range<C>(m); });
}

Cost counted_cost(const ColorCorrectionCombo& combo, ShaderModel binary) {
  return kept<kColorCorrectionSpace>("ColorCorrection", combo, binary,
                                     []<ColorCorrectionCombo C>(ShaderModel m) { return measure_color_correction<C>(m); });
}

Cost counted_cost(const EnginePostCombo& combo, ShaderModel binary) {
  return kept<kEnginePostSpace>("Engine_Post", combo, binary,
                                []<EnginePostCombo C>(ShaderModel m) { return measure_engine_post<C>(m); });
}

bool vertexlit_fits(const VertexLitCombo& combo, ShaderModel binary) {
  if (index_in<kVertexLitSpace>(combo) < 0 || !combo.valid(binary)) return false;
  return static_cast<bool>(fits(counted_cost(combo, binary), caps(binary)));
}

}  // namespace luxel::shading::source
