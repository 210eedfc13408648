#pragma once
// Private: what lights a model (docs/fidelity.md#irradiance-volume-and-lights): the ambient cube of the
// irradiance-volume sample nearest its centroid (or the trilinear blend of the eight around it), its
// most significant local lights (two, or FrameSettings::local_lights up to four where its shader
// takes them: the bumped and skin shaders on ps_2_b and ps_3_0), every other light folded into
// that cube on the CPU
// (shading/source/light_folding.hpp: significance = delivered luminance at the centroid, ties by
// scene order), then the hero boost where the material asks; across the frames of a sequence,
// the volume's cube and the lights' shares of being local lights time-averaged (renderer.hpp).
//
// Hero boost: a material's hero_boost h > 1 turns on light_folding.hpp's ambient boost with the
// floor h x its default fraction (the cube is raised until its mean luminance is at least
// 0.25 h times the local lights' at the centroid); h <= 1 leaves the cube as it is.
// Light ranges (scenes::Light::range) are not applied: Source's models see every light.
// No irradiance volume (a scene not baked, or one without a volume): a black cube, except in a
// scene with no light at all (no lights, no sky: a glTF model on its own), which is drawn
// fullbright, a white cube, as Source draws a map that was never lit.

#include "luxel/frame/renderer.hpp"
#include "luxel/scenes/scene.hpp"
#include "luxel/shading/source/light_folding.hpp"
#include "luxel/shading/source/vertexlit_dispatch.hpp"

#include <array>
#include <span>
#include <vector>

namespace luxel::frame {

/// The most local lights a shader takes (the SDK's bumped and skin shaders on ps_2_b and ps_3_0).
inline constexpr int kMaxLocalLights = 4;

/// What a model's lighting averages across frames (renderer.hpp): the volume's cube at its
/// centroid, and per scene light its share of being one of its local lights.
struct AveragedLighting {
  shading::source::AmbientCube volume;
  std::vector<float> shares;
};

struct ModelLighting {
  shading::source::AmbientCube cube;
  std::array<shading::source::LocalLight, 4> lights{};  ///< the local lights first; the rest black
  int kept = 0;                                          ///< 0 to kMaxLocalLights
  std::array<int, kMaxLocalLights> local{-1, -1, -1, -1};  ///< the scene lights in the slots, or -1
};

/// The scene's lights as the shaders' light descriptions, in scene order.
std::vector<shading::source::LightDesc> light_descriptions(const scenes::Scene& scene);

/// The volume's cube at `point` (clamped to the grid): the nearest sample's, or the trilinear
/// blend of the eight around it; black / white (above) without a volume.
shading::source::AmbientCube ambient_cube(const scenes::Scene& scene, const glm::vec3& point, AmbientSampling sampling);

/// What the averaging moves towards at `centroid`: the volume's cube there, share 1 for the
/// `local_lights` lights the significance rule keeps and 0 for the others.
AveragedLighting lighting_at(const scenes::Scene& scene, std::span<const shading::source::LightDesc> lights,
                             const glm::vec3& centroid, AmbientSampling sampling, int local_lights);

/// Moves `averaged` towards `target` over `dt` seconds with time constant `tau` (renderer.hpp).
/// tau <= 0, or a negative dt (the clock went back): `target` itself.
void step_towards(AveragedLighting& averaged, const AveragedLighting& target, float dt, float tau);

/// The local-light slots for `shares`: the `count` largest shares above 0 (count <=
/// kMaxLocalLights), ties to the earlier light in `significance` (light_folding.hpp's
/// significance_order at the model's centroid); the other slots -1.
std::array<int, kMaxLocalLights> local_light_slots(std::span<const size_t> significance, std::span<const float> shares,
                                                   int count);

/// The parameters of a VertexLitGeneric material that choose its shader (vertexlit_dispatch.hpp),
/// but those the frame resolves (the env map, the base texture's alpha, the mesh's colors).
shading::source::VertexLitMaterial vertexlit_material(const scenes::Material& material);

/// The shader's lighting of a model drawn with `material`, from its averaged lighting: the lights
/// folded into the cube with squared Half-Lambert or Lambert, as the shader the material gets
/// lights (vertexlit_half_lambert); at most `local_lights` local lights (the shader's count), the
/// other lights with a share folded wholly.
ModelLighting light_model(std::span<const shading::source::LightDesc> lights, const glm::vec3& centroid,
                          const scenes::Material& material, bool half_lambert, const AveragedLighting& averaged,
                          int local_lights);

}  // namespace luxel::frame
