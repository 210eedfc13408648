#pragma once
// HDR cube maps at the scene's cube-map samples, rendered by the frame itself, the
// way Source's buildcubemaps makes them: from each sample point, six 90-degree square faces of
// the world and the sky (what a capture draws: renderer.hpp), each taken at a bracket of
// exposures into 8-bit targets through the Source shaders' tone-map epilogue, then merged into
// linear HDR (exposure_merge.hpp) and stored as the shaders read an HDR env map: a linear cube of
// float texels (uploaded RGBA16F: the merge is rounded to half floats, so a cube kept on disk as
// half-float EXR reloads to the same bytes), mipmapped, in Scene::textures, the sample's
// CubemapSample::texture pointing at it.
//
// Faces: D3D order (+X, -X, +Y, -Y, +Z, -Z) and layout (rasterizer/texture.hpp "Cube maps"):
// texel (x, y) of face f sees the world direction cube_direction(f, (x + 0.5) / n, (y + 0.5) / n),
// the direction the shaders' cube sampling reads it for. The world is right-handed and D3D's
// cube layout left-handed, so a face is rendered through a right-handed camera (forward: the
// face's axis, up: its top row's direction) and mirrored left to right.
//
// Exposures: the scene's range decides the bracket. The darkest exposure is the power of two
// that keeps the brightest value the scene holds (its sky texels, its flat lightmap, its
// materials' emission) under 0.9 (code 243: not clipped); the brightest puts the dimmest surface
// worth reflecting (a dark albedo, kDarkAlbedo, under the 1st-percentile flat lightmap value) at
// 0.25 (code 137: half a step is 0.8 % of it); in between, exposures `stops_apart` stops apart.
// Some exposure puts every value of the range within `stops_apart` stops under 0.9: two stops
// apart, at code 131 or above; four, at 67 or above.
//
// Capture without MSAA: a face texel is one pixel sample, as the float reference must be.

#include "luxel/frame/textures.hpp"
#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/rasterizer/texture.hpp"
#include "luxel/scenes/scene.hpp"
#include "luxel/shading/shader_model.hpp"

#include <glm/vec4.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace luxel::frame {

/// How cube maps are baked.
struct CubemapSettings {
  int face_size = 0;          ///< texels on a face's side; 0: each sample's CubemapSample::size
  float stops_apart = 2.0f;   ///< between consecutive exposures of the bracket
  shading::ShaderModel model = shading::ShaderModel::ps_3_0;  ///< the shaders a capture runs

  /// `--bake quick`: 16-texel faces, exposures four stops apart.
  static CubemapSettings quick() {
    CubemapSettings s;
    s.face_size = 16;
    s.stops_apart = 4.0f;
    return s;
  }
};

/// The albedo the bracket's brightest exposure is set for (above).
inline constexpr float kDarkAlbedo = 0.05f;

/// The camera that renders face `face` of a cube at `position` (before the mirroring above).
scenes::Camera cube_face_camera(glm::vec3 position, rasterizer::CubeFace face);

/// The bracket for `scene` (above): tone-map scales, powers of two, darkest first. Throws
/// std::invalid_argument when `stops_apart` is not a positive finite number.
std::vector<float> exposure_bracket(const scenes::Scene& scene, float stops_apart);

/// Face `face` of the cube at `position`, `size` texels square, through the 8-bit target at
/// tone-map scale `exposure`, in the cube's layout. `textures`: the scene's, prepared once for
/// many captures (null: prepared here). Throws std::invalid_argument as Renderer does.
rasterizer::Image capture_face(const scenes::Scene& scene, glm::vec3 position, rasterizer::CubeFace face, int size,
                               float exposure, shading::ShaderModel model, rasterizer::Context& ctx,
                               std::shared_ptr<const SceneTextures> textures = nullptr);

/// The same face rendered to floats at tone-map scale 1 (Renderer::render_float: HDR_TYPE_FLOAT,
/// no clamp): the reference a merge is measured against.
std::vector<glm::vec4> capture_face_float(const scenes::Scene& scene, glm::vec3 position, rasterizer::CubeFace face,
                                          int size, shading::ShaderModel model, rasterizer::Context& ctx,
                                          std::shared_ptr<const SceneTextures> textures = nullptr);

/// The merged HDR cube at `position` (the texture the bake stores, named `name`).
scenes::Texture bake_cubemap(const scenes::Scene& scene, glm::vec3 position, int size, std::span<const float> exposures,
                             shading::ShaderModel model, rasterizer::Context& ctx, std::string name,
                             std::shared_ptr<const SceneTextures> textures = nullptr);

/// Called after each sample's cube: samples done, of total.
using CubemapProgressFn = std::function<void(int done, int total)>;

/// The cubes of every cube-map sample of `scene` (in order; the scene's own cubes ignored:
/// renderer.hpp). Throws std::invalid_argument naming the problem (a sample size outside
/// 1..kMaxTextureSize, settings out of range, what Renderer refuses).
std::vector<scenes::Texture> bake_cubemaps(const scenes::Scene& scene, const CubemapSettings& settings,
                                           rasterizer::Context& ctx, const CubemapProgressFn& progress = {});

/// Adds `cubes` (one per cube-map sample, in order) to Scene::textures and points each sample's
/// CubemapSample::texture at its cube. Throws std::invalid_argument when the count differs.
void attach_cubemaps(scenes::Scene& scene, std::vector<scenes::Texture> cubes);

/// The sampler state of a baked cube: clamped (seamless anyway), bilinear, mipmapped.
scenes::Texture cubemap_texture(std::string name, std::vector<scenes::PixelImage> faces);

/// The hash (64-bit FNV-1a) of everything bake_cubemaps reads: the meshes (positions, normals,
/// tangents, uvs, colors, indices, material, model membership), every material parameter a world
/// shader reads, every texture but the samples' own cubes (lightmaps and sky included), the
/// background, the samples' positions and sizes, the settings and the bake's format version.
uint64_t cubemap_input_hash(const scenes::Scene& scene, const CubemapSettings& settings);

}  // namespace luxel::frame
