#pragma once
// `luxel compare --explain`: every pixel where two shader models' frames differ, attributed to the
// SDK rule behind it by drawing the pair again with rules made equal (docs/compare.md).
//
// The rules by which the frame of a card differs from another's (docs/fidelity.md):
//   fog_per_vertex  ps_2_0 fogs per vertex where the later cards fog per pixel;
//   skin_shader     the helper's choice of shader for a model material: no skin shader on ps_2_0
//                   (no Phong, no rim, the bumped path's env map);
//   light_count     bumped and skin models take two local lights on ps_2_0 (with --lights above 2);
//   water_blur      water blurs its refraction from ps_2_b up;
//   card_binary     what the ps20 binary computes itself: on models, the normalization cube map.
// With `lo` the lower card and `hi` the higher, a differing pixel is the fog's when the pair drawn
// without fog agrees there. Else, without fog: card_binary when `lo`'s frame differs there from
// `hi`'s card drawn with every dispatch rule of `lo` (FrameSettings::dispatch_cards); a dispatch
// rule when taking `hi`'s choice for it alone changes that drawing there, or taking `lo`'s for it
// alone changes `hi`'s frame there (what a rule does only together with another). A pixel with
// one cause is counted under it, with more under `several`, with none under `unexplained`, which
// should stay empty. Dispatch rules that cannot change the scene (no $phong model material, two
// local lights, no blurring water) are not drawn.

#include "luxel/frame/renderer.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/scenes/scene.hpp"
#include "luxel/shading/shader_model.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

namespace luxel::cli {

enum class Cause : uint8_t { fog_per_vertex, skin_shader, light_count, water_blur, card_binary, several, unexplained };
inline constexpr int kCauses = 7;

/// The cause's name in JSON and on the sheet.
std::string_view cause_name(Cause c);
/// The cause's colour on the sheet.
std::array<uint8_t, 3> cause_colour(Cause c);

struct Explanation {
  uint64_t differing = 0;                    ///< pixels whose rgb bytes differ
  std::array<uint64_t, kCauses> pixels{};    ///< per cause, each differing pixel under one
  std::array<uint64_t, kCauses> involved{};  ///< per rule, the differing pixels it has a part in
  rasterizer::Image map;                     ///< each differing pixel in its cause's colour, black elsewhere
};

/// Draws the first frame of `scene` with `settings` (the caller's renderer), or nullopt after
/// saying why.
using FrameDrawer = std::function<std::optional<rasterizer::Image>(const scenes::Scene&, const frame::FrameSettings&)>;

/// Explains the differences between `image_lo` and `image_hi`, the frames of `scene` drawn with
/// `settings` as cards `lo` < `hi`; draws what it needs through `draw`. nullopt when a drawing failed.
std::optional<Explanation> explain_pair(const rasterizer::Image& image_lo, const rasterizer::Image& image_hi,
                                        shading::ShaderModel lo, shading::ShaderModel hi, const scenes::Scene& scene,
                                        const frame::FrameSettings& settings, const FrameDrawer& draw);

}  // namespace luxel::cli
