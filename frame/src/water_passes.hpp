#pragma once
// Private: the water's views, as viewrender.cpp's CAboveWaterView draws them. For
// each height at which the scene has water that the camera sees from above, two views of the
// scene are drawn before the frame into square one-sample targets (renderer.hpp's
// water_texture_side: 1024, the SDK's render targets), each over the whole target with the
// camera's aspect as viewrender.cpp's AdjustView draws them, and copied into 8-bit sRGB textures,
// which the water shader reads at the pixel's place on screen (water.hpp, adapter.hpp's
// WaterPixelShader):
//  - reflection (only when a water material of that height reflects): the scene mirrored about
//    the water plane, seen from the camera, so that the reflection of what lies along a pixel's
//    reflected ray lands on that pixel (the SDK flips its camera instead and its vertex shader
//    flips the lookup; the texels read are the same). At the reflection exposure of
//    docs/fidelity.md#water (INTEGER HDR): 0.25 x the frame's tone-map scale, the water's reflect tint
//    x 4 (water.hpp's sdk_fixed). The scene's fog, the sky. Geometry below the plane is clipped.
//  - refraction (always: the water shader reads its alpha as the water's depth, even in a
//    reflect-only combo): what lies below the plane, from the camera, at the frame's exposure,
//    cleared to the water's fog color; the world draws with the water's height fog (fog.hpp:
//    Fog::height, from the water's $fogcolor, $fogstart, $fogend) and opaque materials write its
//    factor to alpha (WRITEWATERFOGTODESTALPHA, adapter.hpp). That factor, the part of the
//    eye-to-point segment under the water times its projected depth over the fog range, is the
//    "depth" water.hpp reads: 0 at the waterline, 1 where the water's fog is full; a pixel where
//    nothing is drawn keeps the clear's alpha, 1. No sky.
// Neither view draws water, nor any pixel the water cannot read: what each mesh of the plane can
// read is its footprint on screen (the convex hull of its vertices) widened by the largest offset
// its normal map can add to a lookup of that view (|2 texel - 1| x alpha x the view's amount:
// $reflectamount for the reflection, $refractamount for the refraction, the depth being at most 1),
// plus the reach of $blurrefract's 5 x 5 taps (2 x 0.005 of the view) in the refraction where the
// material asks for it, plus a texel for the bilinear read. Each view is scissored to the rectangle
// around that (the meshes' bounding boxes on screen, widened alike), which keeps the rasterizer
// from binning anything outside it, and stencil-masked to the widened hulls inside it: before the
// view's draws, a draw of the hulls writes the stencil, and every draw of the view tests it (before
// its pixel shader, but for alpha-tested materials), so that the floor around a basin below the
// plane and the walls above it are not shaded. A mesh with a vertex behind the eye, or far beyond
// the screen, reads its whole rectangle. The clip plane sits 2 inches past the water plane into the
// kept side (CBaseWorldView::PushView's "spread", which hides seams at the waterline; less when the
// eye is closer than that), and is the projection's near plane (Lengyel's oblique near plane): the
// rasterizer clips at z = 0, so nothing of the rasterizer changes. Fog reads the view's ordinary
// projected depth (views.hpp, ViewSpec::proj_z_row). Meshes wholly on the clipped side are not
// drawn.
//
// Water meshes must be horizontal planes with a normal map ($normalmap); each distinct height is
// one plane with its own two views. A plane whose meshes are all outside the camera's frustum,
// or whose height is at or above the eye (the frame draws no water seen from below), costs
// nothing and its meshes are not drawn.

#include "views.hpp"

#include "luxel/frame/textures.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/shading/source/fog.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace luxel::frame {

/// What the frame's own view gives a water draw.
struct WaterSurfaceContext {
  shading::source::ToneMapConstants tonemap;  ///< the frame's
  shading::source::Fog fog = shading::source::Fog::none;
  shading::source::FogConstants fog_constants;
  glm::vec3 eye{0.0f};
};

class WaterPasses {
 public:
  /// Plans the planes of `scene` seen through `camera` (its matrices and view) and builds their
  /// views with `build`. Throws std::invalid_argument naming the problem for a water material
  /// without a normal map, one that neither reflects nor refracts, or a water mesh that is not
  /// a horizontal plane.
  WaterPasses(const scenes::Scene& scene, const FrameSettings& settings, const ViewMatrices& camera,
              const ViewSpec& camera_view, const BuildView& build);
  ~WaterPasses();
  WaterPasses(WaterPasses&&) noexcept;
  WaterPasses& operator=(WaterPasses&&) noexcept;

  /// Whether any plane is drawn (render has views to draw).
  bool has_views() const { return !planes_.empty(); }

  /// Draws every plane's views into `color` and `depth`, one-sample targets of
  /// water_texture_side on a side, and resolves each into its texture; each view
  /// one pass of `clock` ("water reflection", "water refraction").
  void render(rasterizer::Context& ctx, rasterizer::ColorTarget& color, rasterizer::DepthStencilTarget& depth, PassClock& clock);

  /// The water draw of mesh `index` with material `m`, its plane's textures bound; nothing when
  /// its plane is not drawn.
  std::optional<SourceDraw> surface_draw(size_t index, const scenes::Material& m, const GpuTexture& normal_map,
                                         const DrawTarget& target, const WaterSurfaceContext& frame) const;

  /// What the views' draws shaded (views.hpp), planes in order, reflection first.
  void add_shader_uses(std::vector<ShaderUse>& uses) const;

 private:
  struct ViewReach;
  struct Plane;
  FrameSettings settings_;
  std::vector<std::unique_ptr<Plane>> planes_;
  std::vector<int> plane_of_mesh_;  ///< per mesh: index into planes_, or -1
};

}  // namespace luxel::frame
