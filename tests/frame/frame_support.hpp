#pragma once
// Renders a built-in scene through frame::Renderer: the helper every frame test uses.

#include "luxel/frame/renderer.hpp"
#include "luxel/scenes/builtin.hpp"

#include <array>
#include <cstddef>
#include <memory>
#include <string_view>

namespace luxel::frame {

/// Sanitizer (ASan and TSan: LUXEL_SANITIZE_BUILD) and unoptimized builds render fewer and smaller
/// frames.
#if defined(LUXEL_SANITIZE_BUILD) || !defined(__OPTIMIZE__)
inline constexpr bool kReduced = true;
#else
inline constexpr bool kReduced = false;
#endif

/// Where kReduced, builtin_scene keeps only this many of builtin:tris's million triangles (the
/// first ones its generator makes, as small): two front-end chunks, at a twenty-fifth of the cost.
inline constexpr size_t kReducedTrisTriangles = 40000;

struct RenderedFrame {
  rasterizer::Image image;
  rasterizer::DrawStats stats;
};

/// The sRGB encode (IEC 61966-2-1), written out here so that tests check the frame's against it.
double srgb_encode(double linear);
/// The sRGB decode of an encoded value in [0, 1].
double srgb_decode(double encoded);
/// What an 8-bit sRGB target stores for a linear value, as a byte.
int srgb8(double linear);
/// A linear value through an 8-bit sRGB target and back.
double through_srgb8(double linear);
/// Channel values in columns [x0, x1) of `image` more than one 8-bit step from `want` (rgb).
int channels_off(const rasterizer::Image& image, int x0, int x1, const std::array<double, 3>& want);

/// A scene with one camera looking straight down at [-1, 1]^2 (orthographic; screen right +X, up
/// +Y), nothing else.
scenes::Scene top_down();

/// top_down() filled by an unlit square of linear grey `grey`: the frame's luminance is `grey` x
/// the exposure scale.
scenes::Scene grey_square(double grey);

/// Four constant lightmaps (flat, then the three basis maps) attached to `s`.
void attach_lightmaps(scenes::Scene& s, const glm::vec3& flat, const glm::vec3 (&basis)[3]);

/// top_down() filled by an unlit square whose corners are four saturated colors (something for a
/// grade to change), at a fixed exposure of 1.
scenes::Scene color_ramp();

/// The square [x0, x1] x [y0, y1] at height z, facing +Z (counter-clockwise seen from above)
/// unless `flip`.
scenes::Mesh square(float x0, float y0, float x1, float y1, float z, int material, bool flip = false);

/// One frame of `scene` with `settings`, rendered on `threads` worker threads.
rasterizer::Image render_frame(const scenes::Scene& scene, const FrameSettings& settings, int threads = 2);

/// Attaches a cheap, deterministic bake (lightmaps, ambient cubes) to `scene`, baked once per
/// scene name and test binary.
void attach_test_bake(scenes::Scene& scene);

/// builtin:courtyard at 64x64 with attach_test_bake: a scene with cube-map sample points.
scenes::Scene baked_courtyard();

/// builtin:`name` built for a width x height image, with attach_test_bake where it needs a bake
/// (and only kReducedTrisTriangles of tris where kReduced); the last one built is kept and shared.
std::shared_ptr<const scenes::Scene> builtin_scene(std::string_view name, int width, int height);

/// Renders builtin_scene(`name`) at the settings' size `frames` times with `options`, and
/// returns the last (checking that every frame gave the same bytes). The scene's textures are
/// prepared once and kept with it, for every render of it.
RenderedFrame render_builtin(std::string_view name, const FrameSettings& settings,
                             const rasterizer::ContextOptions& options, int frames = 1);

}  // namespace luxel::frame
