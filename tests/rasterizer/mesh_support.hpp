#pragma once
// Meshes that tile a region exactly (for watertightness), built in screen space or in clip
// space, and how to draw them so that each triangle adds 1 to every sample it covers.

#include "raster_support.hpp"

#include <random>
#include <string>
#include <vector>

namespace luxel::rasterizer::test {

struct Mesh {
  std::string name;
  std::vector<glm::vec4> clip;     ///< per vertex
  std::vector<uint32_t> indices;   ///< 3 per triangle
  enum class Format { None, U16, U32 } format = Format::U32;
  /// For Format::None the vertices are expanded per triangle before drawing.
  uint32_t triangle_count() const { return uint32_t(indices.size() / 3); }
};

/// An axis-aligned rectangle in screen space whose corners lie exactly on the 1/256 grid after
/// the viewport transform (power-of-two viewport): the union every screen-space mesh tiles.
struct ScreenRect {
  double x0, y0, x1, y1;  ///< pixels, multiples of 2^-10
  /// Top-left rule on the snapped rectangle: left and top edges in, right and bottom out.
  bool contains_sample(int64_t sx, int64_t sy) const;
};

/// Vertices on the boundary are exact (ViewportMap::clip_from_screen); interior ones are
/// arbitrary floats. Triangles get a random winding.
Mesh jittered_grid(const ViewportMap& map, const ScreenRect& r, int nx, int ny, std::mt19937& rng);
Mesh random_fan(const ViewportMap& map, const ScreenRect& r, int boundary_points, std::mt19937& rng);
Mesh random_strip(const ViewportMap& map, const ScreenRect& r, int top_points, int bottom_points, std::mt19937& rng);
/// `triangles` thin triangles around one interior vertex, fanning to points on the whole boundary.
Mesh thin_fan(const ViewportMap& map, const ScreenRect& r, int triangles, std::mt19937& rng);

/// A jittered grid on the plane y = -1 of a perspective view, x in [-half_x, half_x], depth
/// (clip w) in [w0, w1], crossing the near plane (clip z = w - near) and, for large half_x, the
/// guard band. `corners` receives the four corners of the plane's rectangle in clip space.
Mesh perspective_floor(float half_x, float w0, float w1, float near, int nx, int nz, std::mt19937& rng,
                       glm::vec4 corners[4]);

/// Draws the mesh with additive blending: each covered sample's red channel grows by 1.
void draw_counting(Context& ctx, ColorTarget& target, const Mesh& mesh, PipelineState state = {});

}  // namespace luxel::rasterizer::test
