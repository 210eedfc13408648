#pragma once
// W3 `sponza`: the llvmpipe peer's textured workload (bench/README.md, "W3"),
// drawn by luxel so that any glTF file compares like for like. It is a benchmark workload, not a
// Source shader: trilinear base texture (RGBA8, no sRGB decode, color premultiplied by alpha as
// the peer's OpenImageIO decode leaves PNGs) x baseColorFactor x (ambient cube
// + two Half-Lambert point lights with 1/d^2 falloff), clamped and written without sRGB encoding;
// MASK materials drawn opaque; double-sided materials unculled with the normal negated on back
// faces; a missing NORMAL reads (0, 1, 0), a missing TEXCOORD_n (0, 0); camera lookAt(eye,
// target, up +Y), vertical FOV 60 degrees, near 0.1, far 100; clear (0.45, 0.55, 0.70).
//
// The peer defines all of this in glTF space (meters, +Y up). luxel's importer (scenes/gltf.hpp)
// moves the scene into Source space (inches, +Z up: source = (x, -z, y) k, k = inches per meter)
// and W3 keeps it there, mapping the workload's constants instead of the geometry:
//   - eye, target and the light positions go through the same map; up +Y becomes +Z; near and far
//     are multiplied by k. The map is a rotation and a uniform scale, so the projection of every
//     vertex is the peer's (to float rounding) and so is every interpolated normal's direction.
//   - distances are k times longer, so 1/d^2 is k^2 times smaller: the light colors are
//     multiplied by k^2, which gives color / d_m^2 exactly (gltf.hpp makes the same argument for
//     KHR_lights_punctual).
//   - the ambient cube's faces are named by glTF axes; Source +X, -X, +Y, -Y, +Z, -Z read glTF's
//     +X, -X, -Z, +Z, +Y, -Y (n_source.y = -n_gltf.z). Where a component is 0 the face's weight
//     is 0, so the >= 0 tie goes either way without changing the sum.
// The alternative, an importer mode that keeps glTF units, would have put a second coordinate
// convention into the product for one benchmark.
//
// Where luxel's import and the peer's loader differ, and W3 follows the importer: a node whose
// matrix mirrors (negative determinant) has its triangles' winding reversed, as glTF asks, where
// the peer leaves it and so culls the faces the author drew as front; normals are normalized per
// vertex after the node's normal matrix, which changes the interpolated direction only under
// non-uniform scaling; KHR_texture_transform's texCoord override is honoured (the transform
// itself is not: W3 reads the raw TEXCOORD_n as the peer does); TEXCOORD_2 and up are refused.

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/scenes/scene.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace luxel::bench {

/// The W3 camera, in glTF space. The defaults are the peer's (chosen for the Khronos Sponza).
struct SponzaView {
  glm::vec3 eye{-10.40f, 1.25f, -0.30f};
  glm::vec3 target{9.45f, 2.50f, -0.30f};
};

/// The W3 camera in the scene's space (Source's: inches, +Z up), with W3's FOV, near and far.
scenes::Camera sponza_camera(const SponzaView& view);

/// W3's lighting in the scene's axes and units (the header comment says why it is the peer's).
struct SponzaLighting {
  std::array<glm::vec3, 6> cube;  ///< Source's faces +X, -X, +Y, -Y, +Z, -Z
  std::array<glm::vec3, 2> position, color;
};
SponzaLighting sponza_lighting();

/// W3's clear color (visible through the open roof).
inline constexpr glm::vec4 kSponzaClear(0.45f, 0.55f, 0.70f, 1.0f);

/// A scene texture as W3 reads it: RGBA8 with color premultiplied by alpha (the peer's decode),
/// no sRGB decode, trilinear with a full mip chain; the wrap modes kept.
scenes::Texture sponza_texture(const scenes::Texture& texture);

/// "X,Y,Z": three numbers separated by commas and nothing after them (the peer's --eye and
/// --target syntax). nullopt when the text is anything else.
std::optional<glm::vec3> parse_vec3(const std::string& text);

/// Reads a .gltf or .glb file as W3 needs it: luxel's importer with a missing NORMAL read as
/// (0, 1, 0) in the primitive's object space, no generated tangents, no added camera or lights.
/// Throws scenes::GltfError (one line naming the file).
scenes::Scene load_sponza_scene(const std::string& path);

/// One W3 frame, prepared once (textures uploaded with their mips, draws built) and rendered any
/// number of times: clear, one draw per mesh in the scene's order, resolve into image().
class SponzaFrame {
 public:
  /// `scene` must outlive the frame (its vertices are read in place). Throws std::invalid_argument
  /// for an invalid scene (scenes::validate) or a size or sample count the rasterizer refuses.
  SponzaFrame(const scenes::Scene& scene, const SponzaView& view, int width, int height, int samples);
  ~SponzaFrame();
  SponzaFrame(SponzaFrame&&) noexcept;
  SponzaFrame& operator=(SponzaFrame&&) noexcept;

  void render(rasterizer::Context& ctx);
  const rasterizer::Image& image() const;
  /// Triangles submitted per frame.
  uint64_t triangles() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace luxel::bench
