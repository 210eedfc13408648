// The water's reflection and refraction views and its draws (water_passes.hpp).

#include "water_passes.hpp"

#include "luxel/rasterizer/draw_definition.hpp"
#include "luxel/rasterizer/limits.hpp"
#include "luxel/rasterizer/srgb.hpp"
#include "luxel/rasterizer/texture.hpp"
#include "luxel/shading/source/hdr_type.hpp"
#include "luxel/shading/source/material_color.hpp"
#include "luxel/shading/source/water.hpp"

#include <glm/common.hpp>
#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_double4.hpp>
#include <glm/ext/vector_int2.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace luxel::frame {

using namespace shading::source;

namespace {

/// CBaseWorldView::PushView's spread: how far past the water plane each view keeps geometry.
constexpr float kSpread = 2.0f;

/// Two heights closer than this are one plane.
constexpr float kSameHeight = 1e-3f;

/// Lengyel's oblique near plane ("Oblique View Frustum Depth Projection and Clipping", 2005), for
/// Direct3D's depth range: `projection` with its near plane (z = 0) replaced by `plane` (view
/// space, kept where plane · p >= 0, the eye on the other side) and its far plane tilted through
/// the frustum corner farthest from it, so that the view's frustum stays inside.
glm::dmat4 oblique_near_plane(glm::dmat4 projection, const glm::dvec4& plane) {
  const glm::dvec4 corner = glm::inverse(projection) * glm::dvec4(glm::sign(plane.x), glm::sign(plane.y), 1.0, 1.0);
  const glm::dvec4 w_row(projection[0][3], projection[1][3], projection[2][3], projection[3][3]);
  // z = w at the corner: the corner lies on the new far plane (scale-free in the corner's w).
  const glm::dvec4 z_row = plane * (glm::dot(w_row, corner) / glm::dot(plane, corner));
  for (int c = 0; c < 4; ++c) projection[c][2] = z_row[c];
  return projection;
}

/// Row 2 (clip z) of a matrix.
glm::vec4 z_row(const glm::dmat4& m) { return glm::vec4(glm::dvec4(m[0][2], m[1][2], m[2][2], m[3][2])); }

/// The view of `camera` that keeps world plane `keep` (n, d), through `view` (the camera's view,
/// or it after a mirror).
ViewSpec clipped_view(const ViewMatrices& camera, const glm::dmat4& view, const glm::dvec4& keep, const ViewSpec& base) {
  const glm::dvec4 plane_in_view = glm::transpose(glm::inverse(view)) * keep;
  ViewSpec v = base;
  v.view_projection = glm::mat4(oblique_near_plane(camera.projection, plane_in_view) * view);
  v.proj_z_row = z_row(camera.projection * view);
  v.keep = glm::vec4(keep);
  return v;
}

std::string scene_name(const scenes::Scene& s) { return s.name.empty() ? std::string("scene") : s.name; }

/// The height of a water mesh; throws unless it is a horizontal plane.
float water_height(const scenes::Scene& scene, const scenes::Mesh& mesh) {
  if (mesh.positions.empty()) return 0.0f;
  float lo = mesh.positions[0].z, hi = lo;
  for (const glm::vec3& p : mesh.positions) lo = std::min(lo, p.z), hi = std::max(hi, p.z);
  if (hi - lo > kSameHeight)
    throw std::invalid_argument(scene_name(scene) + ": water mesh '" + mesh.name + "' is not horizontal (z from " +
                                std::to_string(lo) + " to " + std::to_string(hi) + "); water must be a plane of one height");
  return lo;
}

/// Whether any part of the mesh's bounding box may be inside the view volume of `vp`.
bool may_be_visible(const scenes::Mesh& mesh, const glm::mat4& vp) {
  if (mesh.positions.empty()) return false;
  glm::vec3 lo = mesh.positions[0], hi = lo;
  for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  // Outside when all eight corners lie beyond one of the six clip planes.
  int outside[6] = {0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = vp * glm::vec4(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z, 1.0f);
    outside[0] += c.x < -c.w;
    outside[1] += c.x > c.w;
    outside[2] += c.y < -c.w;
    outside[3] += c.y > c.w;
    outside[4] += c.z < 0.0f;
    outside[5] += c.z > c.w;
  }
  return std::none_of(std::begin(outside), std::end(outside), [](int n) { return n == 8; });
}

bool reflects(const scenes::Material& m) { return m.reflect_tint != glm::vec3(0.0f); }

/// How far a normal map can bend a lookup (water.hpp: offset = n.xy x n.a x amount x depth):
/// its largest |2 texel - 1| in red (the offset's x) and in green (its y), and its largest alpha.
/// Filtering and MULTITEXTURE's 0.33 x (three reads) stay within the texels' range, but for
/// 0.33 x 3 = 0.99 moving 2x - 1 by up to 0.02, which the offsets add.
struct NormalExtent {
  glm::dvec2 xy{0.0};
  double alpha = 0.0;
};

NormalExtent normal_extent(const scenes::Texture& normal_map) {
  NormalExtent r;
  for (const scenes::PixelImage& image : normal_map.faces) {
    const size_t texels = static_cast<size_t>(image.width) * image.height;
    for (size_t i = 0; i < texels; ++i) {
      auto channel = [&](int c) {
        return image.is_hdr() ? double(image.rgba32f[4 * i + c]) : image.rgba8[4 * i + c] / 255.0;
      };
      r.xy = glm::max(r.xy, glm::abs(2.0 * glm::dvec2(channel(0), channel(1)) - 1.0));
      r.alpha = std::max(r.alpha, channel(3));
    }
  }
  return r;
}

/// The largest offset, in screen units per axis, that a lookup with `amount` ($reflectamount for
/// the reflection, $refractamount for the refraction) can get from a normal map (the depth is at
/// most 1), plus `taps`: how far around its lookup a filter reads.
glm::dvec2 largest_offset(const NormalExtent& normal, float amount, double taps) {
  return (normal.xy + 0.02) * normal.alpha * std::abs(double(amount)) + taps;
}

/// The blurred refraction reads 5 x 5 taps 0.005 apart around its lookup (water.hpp).
double refraction_taps(const scenes::Material& m) { return m.water_blur_refract ? 2 * 0.005 : 0.0; }

/// An offset in screen units as whole pixels of the frame, and one more: a pixel is shaded at its
/// center when any of its samples is inside the water's triangles.
glm::ivec2 margin_pixels(const glm::dvec2& offset, const FrameSettings& settings) {
  return glm::ivec2(glm::ceil(offset * glm::dvec2(settings.width, settings.height))) + 1;
}

/// The pixels of a width x height target that `mesh` covers through `vp`, widened by `margin`
/// pixels: its bounding box's corners projected, the whole target when one lies behind the eye.
rasterizer::Scissor screen_rectangle(const scenes::Mesh& mesh, const glm::mat4& vp, int width, int height,
                                     const glm::ivec2& margin) {
  rasterizer::Scissor r{true, 0, 0, width, height};
  glm::vec3 lo = mesh.positions[0], hi = lo;
  for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  glm::dvec2 min_px(1e300), max_px(-1e300);
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = vp * glm::vec4(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z, 1.0f);
    if (!(c.w > 0.0f)) return r;
    const glm::dvec2 px((double(c.x) / c.w + 1) * 0.5 * width, (1 - double(c.y) / c.w) * 0.5 * height);
    min_px = glm::min(min_px, px);
    max_px = glm::max(max_px, px);
  }
  auto clamp_to = [](double v, int hi) { return static_cast<int>(std::clamp(v, 0.0, double(hi))); };
  r.x0 = clamp_to(std::floor(min_px.x) - margin.x, width);
  r.y0 = clamp_to(std::floor(min_px.y) - margin.y, height);
  r.x1 = clamp_to(std::ceil(max_px.x) + margin.x, width);
  r.y1 = clamp_to(std::ceil(max_px.y) + margin.y, height);
  return r;
}

/// The texels of a view (a square of water_texture_side) that bilinear lookups
/// at screen places inside `frame_pixels` (a rectangle of the frame's pixels) can read: the
/// screen is stretched onto the square, and a lookup at u reads texels floor(u side - 0.5) and
/// the next.
rasterizer::Scissor in_view_pixels(const rasterizer::Scissor& frame_pixels, const FrameSettings& settings) {
  const int side = water_texture_side(settings);
  auto to_view = [side](int pixel, int frame_size, bool upper) {
    const double texel = double(pixel) * side / frame_size;
    return std::clamp(static_cast<int>(upper ? std::ceil(texel) + 1 : std::floor(texel) - 1), 0, side);
  };
  return {true, to_view(frame_pixels.x0, settings.width, false), to_view(frame_pixels.y0, settings.height, false),
          to_view(frame_pixels.x1, settings.width, true), to_view(frame_pixels.y1, settings.height, true)};
}

/// The factor from the frame's pixels to a view's texels, per axis: the screen is stretched
/// onto the square.
glm::dvec2 texels_per_pixel(const FrameSettings& settings) {
  const double side = water_texture_side(settings);
  return {side / settings.width, side / settings.height};
}

/// The convex hull of `points`, counter-clockwise on screen (Andrew's monotone chain), without
/// collinear points.
std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> points) {
  std::sort(points.begin(), points.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  if (points.size() < 3) return points;
  auto turns_left = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x) > 0;
  };
  std::vector<glm::dvec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {  // the lower chain
    while (k >= 2 && !turns_left(hull[k - 2], hull[k - 1], points[i])) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // the upper chain
    while (k >= lower && !turns_left(hull[k - 2], hull[k - 1], points[i])) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point is the first
  return hull;
}

/// The texels of a view that the water of `mesh` can read, as a convex polygon in view texels:
/// the convex hull of its vertices on screen, widened by `margin` pixels of the frame as the
/// rectangle is (screen_rectangle), then by what rounding the rectangle to whole pixels and
/// in_view_pixels can add at most (a pixel, then two texels). Nothing when a vertex lies behind
/// the eye, or so far off screen that the rasterizer would clip the polygon instead of only
/// snapping it (the guard band).
std::optional<std::vector<glm::dvec2>> footprint_polygon(const scenes::Mesh& mesh, const glm::mat4& vp,
                                                         const FrameSettings& settings, const glm::ivec2& margin) {
  const glm::dvec2 scale = texels_per_pixel(settings);
  const glm::dvec2 reach = (glm::dvec2(margin) + 1.0) * scale + 2.0;
  const double limit = 0.5 * rasterizer::kGuardBand;
  std::vector<glm::dvec2> corners;
  corners.reserve(4 * mesh.positions.size());
  for (const glm::vec3& p : mesh.positions) {
    const glm::vec4 c = vp * glm::vec4(p, 1.0f);
    if (!(c.w > 0.0f)) return std::nullopt;
    const glm::dvec2 texel = glm::dvec2((double(c.x) / c.w + 1) * 0.5 * settings.width,
                                        (1 - double(c.y) / c.w) * 0.5 * settings.height) * scale;
    if (!(glm::all(glm::lessThan(glm::abs(texel), glm::dvec2(limit - reach))))) return std::nullopt;
    // The hull widened by a rectangle (their Minkowski sum) is the hull of its vertices moved
    // to the rectangle's corners.
    for (const glm::dvec2 corner : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
      corners.push_back(texel + corner * reach);
  }
  return convex_hull(std::move(corners));
}

/// The corners of a rectangle of texels, as a polygon.
std::vector<glm::dvec2> corners_of(const rasterizer::Scissor& r) {
  return {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}};
}

/// Appends a convex polygon of view texels to `triangles` as a fan, in the view's clip space.
void add_fan(std::vector<glm::vec4>& triangles, const std::vector<glm::dvec2>& polygon, int side) {
  auto clip = [side](const glm::dvec2& texel) {
    return glm::vec4(float(2 * texel.x / side - 1), float(1 - 2 * texel.y / side), 0.0f, 1.0f);
  };
  for (size_t i = 2; i < polygon.size(); ++i)
    for (const glm::dvec2& corner : {polygon[0], polygon[i - 1], polygon[i]}) triangles.push_back(clip(corner));
}

/// A footprint's vertices, already in the view's clip space.
struct ClipPositions {
  static constexpr int kVaryings = 0;
  const glm::vec4* positions;
  void operator()(uint32_t i, rasterizer::VertexOutput<0>& out) const { out.position = positions[i]; }
};

/// Writes nothing: a footprint's draw marks the stencil alone.
struct NoColor {
  static constexpr bool kCanDiscard = false, kWritesDepth = false, kTrivial = true;
  void operator()(const rasterizer::PixelInput<0>&, rasterizer::PixelOutput&) const {}
};

/// Writes kDrawnStencil into `depth`'s stencil over `footprint` (triangles in clip space), inside
/// `scissor`: where a masked view draws (views.hpp, ViewSpec::masked).
void mark_footprint(rasterizer::Context& ctx, rasterizer::DepthStencilTarget& depth, const rasterizer::Scissor& scissor,
                    const std::vector<glm::vec4>& footprint) {
  rasterizer::PipelineState state;
  state.scissor = scissor;
  state.rasterizer.cull = rasterizer::CullMode::None;
  state.depth_stencil.depth_enable = false;
  state.depth_stencil.stencil_enable = true;
  state.depth_stencil.stencil_ref = kDrawnStencil;
  state.depth_stencil.front.pass = rasterizer::StencilOp::Replace;
  rasterizer::draw(ctx, rasterizer::Framebuffer{nullptr, &depth}, state,
                   rasterizer::Geometry::non_indexed(static_cast<uint32_t>(footprint.size())),
                   ClipPositions{footprint.data()}, NoColor{});
}

/// The smallest rectangle holding both.
rasterizer::Scissor united(const rasterizer::Scissor& a, const rasterizer::Scissor& b) {
  if (!a.enable) return b;
  return {true, std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

WaterMaterial water_material(const scenes::Material& m) {
  WaterMaterial w;
  w.reflect_tint = m.reflect_tint;
  w.refract_tint = m.refract_tint;
  w.fog_color = m.water_fog_color;
  w.reflect_amount = m.reflect_amount;
  w.refract_amount = m.refract_amount;
  w.fog_start = m.water_fog_start;
  w.fog_end = m.water_fog_end;
  w.exposure = WaterReflectionExposure::sdk_fixed;  // docs/fidelity.md#water
  return w;
}

/// A view's target as a texture: 8-bit sRGB, one level, read bilinear and clamped (the distorted
/// lookups near the screen's edges).
GpuTexture view_texture(int side) {
  GpuTexture t{rasterizer::Texture::create_2d(side, side, rasterizer::TextureFormat::RGBA8_sRGB, 1), {}};
  t.sampler.mip = rasterizer::MipFilter::None;
  t.sampler.u = t.sampler.v = rasterizer::Address::Clamp;
  return t;
}

glm::vec4 encoded_clear(const glm::vec3& linear, float alpha) {
  auto encode = [](float x) { return float(rasterizer::linear_to_srgb(std::clamp(x, 0.0f, 1.0f))); };
  return glm::vec4(encode(linear.r), encode(linear.g), encode(linear.b), alpha);
}

}  // namespace

/// What the water of a plane can read of one of its views.
struct WaterPasses::ViewReach {
  rasterizer::Scissor rectangle;  ///< around all of it, in view texels: the view's scissor
  /// Triangles in the view's clip space over all of it: where the view draws (ViewSpec::masked).
  std::vector<glm::vec4> footprint;

  /// Adds what the water of `mesh`, seen through `vp`, can read with lookups bent by up to
  /// `margin` pixels of the frame.
  void add(const scenes::Mesh& mesh, const glm::mat4& vp, const FrameSettings& settings, const glm::ivec2& margin) {
    const rasterizer::Scissor r = in_view_pixels(screen_rectangle(mesh, vp, settings.width, settings.height, margin), settings);
    rectangle = united(rectangle, r);
    add_fan(footprint, footprint_polygon(mesh, vp, settings, margin).value_or(corners_of(r)), water_texture_side(settings));
  }
};

struct WaterPasses::Plane {
  float height = 0.0f;
  bool reflect = false;
  ViewReach reflection_reach, refraction_reach;  ///< what its water can read of its views
  PassList reflection, refraction;
  std::optional<GpuTexture> reflection_texture, refraction_texture;  // set when the view is drawn
  glm::vec4 reflection_clear{0.0f}, refraction_clear{0.0f};
};

WaterPasses::WaterPasses(const scenes::Scene& scene, const FrameSettings& settings, const ViewMatrices& camera,
                         const ViewSpec& camera_view, const BuildView& build)
    : settings_(settings), plane_of_mesh_(scene.meshes.size(), -1) {
  const glm::vec3 eye = camera_view.eye;
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const scenes::Mesh& mesh = scene.meshes[i];
    if (mesh.material < 0) continue;
    const scenes::Material& m = scene.materials[static_cast<size_t>(mesh.material)];
    if (m.family != scenes::ShaderFamily::water) continue;
    if (!m.water_normal.bound())
      throw std::invalid_argument(scene_name(scene) + ": water material '" + m.name + "' has no normal map ($normalmap)");
    if (!reflects(m) && m.refract_amount == 0.0f)
      throw std::invalid_argument(scene_name(scene) + ": water material '" + m.name +
                                  "' neither reflects (its reflect tint is black) nor refracts (its refract amount is 0)");
    const float h = water_height(scene, mesh);
    if (!(eye.z > h) || !may_be_visible(mesh, camera_view.view_projection)) continue;
    auto same = std::find_if(planes_.begin(), planes_.end(), [&](const auto& p) { return std::abs(p->height - h) <= kSameHeight; });
    if (same == planes_.end()) {
      planes_.push_back(std::make_unique<Plane>());
      planes_.back()->height = h;
      same = planes_.end() - 1;
    }
    (*same)->reflect = (*same)->reflect || reflects(m);
    plane_of_mesh_[i] = static_cast<int>(same - planes_.begin());
    // Each view is read with its own amount: the reflection bent by $reflectamount, the
    // refraction by $refractamount (and blurred where asked).
    const NormalExtent normal = normal_extent(scene.textures[static_cast<size_t>(m.water_normal.texture)]);
    const glm::mat4& vp = camera_view.view_projection;
    (*same)->reflection_reach.add(mesh, vp, settings, margin_pixels(largest_offset(normal, m.reflect_amount, 0.0), settings));
    (*same)->refraction_reach.add(mesh, vp, settings,
                                  margin_pixels(largest_offset(normal, m.refract_amount, refraction_taps(m)), settings));
  }

  const float scale = camera_view.exposure;
  for (auto& plane : planes_) {
    const double h = plane->height;
    const double spread = std::min(double(kSpread), 0.5 * (double(eye.z) - h));
    ViewSpec base = camera_view;
    base.water = false;
    auto limited_to = [&](const ViewReach& reach) {
      ViewSpec v = base;
      if (settings.limit_water_views) {
        v.scissor = reach.rectangle;
        v.masked = true;
      }
      return v;
    };
    if (plane->reflect) {
      glm::dmat4 mirror(1.0);  // z -> 2h - z
      mirror[2][2] = -1.0;
      mirror[3][2] = 2.0 * h;
      ViewSpec v = clipped_view(camera, camera.view * mirror, glm::dvec4(0, 0, 1, -(h - spread)),
                                limited_to(plane->reflection_reach));
      v.eye = glm::vec3(eye.x, eye.y, float(2.0 * h - eye.z));
      v.mirrored = true;
      WaterMaterial fixed;
      fixed.exposure = WaterReflectionExposure::sdk_fixed;
      v.exposure = water_reflection_scale(scale, HdrType::integer, fixed);  // 0.25 x the frame's
      build(v, plane->reflection);
      plane->reflection_texture = view_texture(water_texture_side(settings));
      plane->reflection_clear = encoded_clear(scene.background, 1.0f);
    }
    // The water's fog: of the first of its materials that is drawn (the SDK's fog volume has one).
    const scenes::Material* fog_material = nullptr;
    for (size_t i = 0; i < scene.meshes.size() && !fog_material; ++i)
      if (plane_of_mesh_[i] >= 0 && planes_[static_cast<size_t>(plane_of_mesh_[i])] == plane)
        fog_material = &scene.materials[static_cast<size_t>(scene.meshes[i].material)];
    FogSettings fog;
    fog.start = fog_material->water_fog_start;
    fog.end = fog_material->water_fog_end;
    fog.max_density = 1.0f;
    fog.color = material_gamma_to_linear(fog_material->water_fog_color);
    fog.water_z = float(h + spread);
    ViewSpec v = clipped_view(camera, camera.view, glm::dvec4(0, 0, -1, h + spread), limited_to(plane->refraction_reach));
    v.water_fog = fog;
    v.sky = false;
    build(v, plane->refraction);
    plane->refraction_texture = view_texture(water_texture_side(settings));
    plane->refraction_clear = encoded_clear(fog.color * scale, 1.0f);
  }
}

WaterPasses::~WaterPasses() = default;
WaterPasses::WaterPasses(WaterPasses&&) noexcept = default;
WaterPasses& WaterPasses::operator=(WaterPasses&&) noexcept = default;

void WaterPasses::render(rasterizer::Context& ctx, rasterizer::ColorTarget& color, rasterizer::DepthStencilTarget& depth,
                         PassClock& clock) {
  const rasterizer::Framebuffer fb{&color, &depth};
  auto draw_view = [&](const char* name, const ViewReach& reach, PassList& passes, const glm::vec4& clear,
                       std::optional<GpuTexture>& into) {
    // Limited views: only the scissor's tiles are cleared and resolved, straight into the
    // view's texture, and drawn only inside the footprint. The texels outside it are never read
    // (it holds every texel the water reads, with a nonzero weight), so whatever they hold
    // changes no pixel.
    const rasterizer::Scissor region = settings_.limit_water_views ? reach.rectangle : rasterizer::Scissor{};
    clock.run(name, draw_count(passes), [&] {
      rasterizer::clear_color(ctx, color, clear, region);
      rasterizer::clear_depth_stencil(ctx, depth, 1.0f, 0, region);
      if (settings_.limit_water_views) mark_footprint(ctx, depth, reach.rectangle, reach.footprint);
      run_passes(ctx, fb, passes);
      // Flushes: the views' draws are done.
      rasterizer::resolve_into(ctx, color, into->texture, rasterizer::ResolveAlpha::samples, region);
    });
  };
  for (auto& plane : planes_) {
    if (plane->reflect)
      draw_view("water reflection", plane->reflection_reach, plane->reflection, plane->reflection_clear, plane->reflection_texture);
    draw_view("water refraction", plane->refraction_reach, plane->refraction, plane->refraction_clear, plane->refraction_texture);
  }
}

std::optional<SourceDraw> WaterPasses::surface_draw(size_t index, const scenes::Material& m, const GpuTexture& normal_map,
                                                    const DrawTarget& target, const WaterSurfaceContext& frame) const {
  if (plane_of_mesh_[index] < 0) return std::nullopt;
  const Plane& plane = *planes_[static_cast<size_t>(plane_of_mesh_[index])];
  WaterCombo combo;
  combo.reflect = reflects(m);
  combo.refract = m.refract_amount != 0.0f;
  combo.above_water = true;
  combo.multitexture = m.water_scroll != glm::vec2(0.0f);
  // Valve's helper asks for BLURRY only where it exists (ps_2_b and up) and the water refracts.
  combo.blurry_refract = m.water_blur_refract && combo.refract &&
                        settings_.dispatch_cards.water_blur.value_or(settings_.model) != shading::ShaderModel::ps_2_0;
  combo.fog = frame.fog;
  WaterParams p = water_constants(water_material(m), HdrType::integer, frame.tonemap);
  auto drawn = [&](const rasterizer::Sampler& s) { return as_drawn(s, settings_.texture_lod_bias, settings_.sampling); };
  p.refraction = Sampler2D{0, &plane.refraction_texture->texture, drawn(plane.refraction_texture->sampler)};
  // A refract-only combo never reads the reflection; the binding only has to be valid.
  const GpuTexture& reflection = plane.reflect ? *plane.reflection_texture : *plane.refraction_texture;
  p.reflection = Sampler2D{2, &reflection.texture, drawn(reflection.sampler)};
  p.normal = Sampler2D{4, &normal_map.texture, drawn(normal_map.sampler)};
  p.pixel_fog = frame.fog_constants;
  WaterVertexConstants c;
  const scenes::UvTransform t = scenes::UvTransform::of(m.water_normal);
  c.bump_u = glm::vec3(t.cos_r * t.scale.x, t.sin_r * t.scale.y, t.offset.x);
  c.bump_v = glm::vec3(-t.sin_r * t.scale.x, t.cos_r * t.scale.y, t.offset.y);
  // water.cpp: TexOffsets = time x ($scroll1, $scroll2); scenes have no $scroll2.
  const float time = settings_.time;
  c.scroll_offsets = glm::vec4(time * m.water_scroll, 0.0f, 0.0f);
  c.inverse_size = glm::vec2(1.0f / float(settings_.width), 1.0f / float(settings_.height));
  return water_draw(combo, settings_.model, target, p, c, frame.eye);
}

void WaterPasses::add_shader_uses(std::vector<ShaderUse>& uses) const {
  for (const auto& plane : planes_) {
    frame::add_shader_uses(plane->reflection, uses);
    frame::add_shader_uses(plane->refraction, uses);
  }
}

}  // namespace luxel::frame
