#pragma once
// The frame: renders a scenes::Scene, whatever it holds, into an 8-bit image.
//
// A Renderer prepares a scene once (each scenes::Texture uploaded as a rasterizer::Texture with
// its mips, the camera's view-projection, one draw per mesh) and then renders any number of
// frames, each what the llvmpipe peer calls a frame: clear, draw, resolve.
//
// Until the Source frame (#8) arrives, meshes are drawn with one plain shader:
//   base texture x material color x vertex color x (sky ambient + a fixed sun's Lambert term)
// lit for every family but UnlitGeneric and Sky, which take the product unlit. A mesh whose
// material is unlit with no base texture (vertex colors at most: the peer workloads) is drawn
// with a trivial pixel functor (rasterizer/draw.hpp), the fastest path there is. Everything is
// opaque and depth-tested with LESS; single-sided materials cull their back faces (front faces
// are counter-clockwise, scene.hpp). Colors are sRGB-encoded on write unless the material says
// $linearwrite; the background clears to Scene::background, sRGB-encoded, and a scene with a sky
// cube (Scene::sky_texture) shows it wherever no mesh was drawn, unlit.
//
// Conventions: the view is Source's (+Z up, right-handed), projections are Direct3D's (depth in
// [0, 1]). The view-projection matrix is computed in double and rounded once, so that a camera
// whose exact matrix has float entries (the workloads' orthographic cameras) gets exactly those.

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/scenes/scene.hpp"
#include "luxel/shading/shader_model.hpp"

#include <glm/mat4x4.hpp>

#include <memory>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace luxel::frame {

struct FrameSettings {
  int width = 1280;
  int height = 720;
  int samples = 4;
  int camera = 0;                   ///< index into Scene::cameras
  std::optional<float> path_time = std::nullopt;  ///< set: the camera of Scene::camera_path at this time, seconds
  /// The pixel-shader model the Source shaders are drawn as: ps_2_0, ps_2_b or ps_3_0.
  shading::ShaderModel model = shading::ShaderModel::ps_3_0;
  /// Count the pixels each shader combo shades (Renderer::shader_uses); off, a frame counts nothing.
  bool count_shading = false;
};

/// One shader combo the last frame ran (FrameSettings::count_shading).
struct ShaderUse {
  std::string family;   ///< "LightmappedGeneric", "VertexLitGeneric", ...
  std::string combo;    ///< the combo's name in the shading catalog
  uint64_t pixels = 0;  ///< pixels it shaded (covered pixels, helper lanes not counted)
  int slots = 0;        ///< its counted DX9 instruction slots per pixel (arithmetic + texture) on the frame's model
};

/// The camera a frame with these settings looks through. Throws std::invalid_argument when the
/// scene has no such camera (an index out of range, a path time without a path).
scenes::Camera frame_camera(const scenes::Scene& scene, const FrameSettings& settings);

/// World (inches, +Z up) to Direct3D clip space for `camera` drawn into a width x height image
/// (its aspect, when the camera gives none).
glm::mat4 view_projection(const scenes::Camera& camera, int width, int height);

class Renderer {
 public:
  /// Prepares `scene`, which must outlive the renderer (it reads the meshes in place). Throws
  /// std::invalid_argument naming the problem for an invalid scene (scenes::validate), bad
  /// settings (size outside 1..kMaxTargetSize, samples not 1, 2, 4 or 8, a model that is
  /// not a pixel-shader model) or a missing camera.
  Renderer(const scenes::Scene& scene, const FrameSettings& settings);
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;

  /// Renders one frame and resolves it into image().
  void render(rasterizer::Context& ctx);
  const rasterizer::Image& image() const;
  /// What the draws of the last frame did, summed.
  const rasterizer::DrawStats& stats() const;
  /// What each shader combo did in the last frame, in a fixed order (first draw first); empty
  /// unless FrameSettings::count_shading.
  const std::vector<ShaderUse>& shader_uses() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace luxel::frame
