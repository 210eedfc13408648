// Range fog in the frame against the SDK's formulas computed here in double
// (docs/fidelity.md#fog): a floor receding from the eye under range fog whose density is capped,
// per pixel with f² on ps_2_b and ps_3_0 (CalcRangeFog, BlendPixelFog), and on ps_2_0 through the
// vertex shader's visibility max(1 - maxDensity, (end - projZ) / range) at the floor's corners,
// interpolated across its triangles and blended linearly by the fixed-function fog unit. The cap
// binds at the far corners, so the interpolated visibility is not the per-pixel one: a frame
// that fogged ps_2_0 per pixel, or squared its blend, or left the square off ps_2_b, fails.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace luxel::frame {
namespace {

constexpr int kFogSide = 96;
constexpr double kEyeNear = 0.5, kEyeFar = 100.0, kTanHalfFov = 0.57735026918962573;  // 60 degrees
constexpr double kStart = 5.0, kEnd = 30.0, kMaxDensity = 0.7;
const glm::dvec3 kColor(0.8, 0.6, 0.1), kFogColor(0.1, 0.3, 0.9);
constexpr double kX0 = -5.0, kX1 = 5.0, kY0 = 1.0, kY1 = 40.0;  // the floor, at z = 0

/// An eye 1 above the floor looking along +Y, the floor unlit in kColor, range fog.
scenes::Scene fogged_floor() {
  scenes::Scene s;
  s.name = "fogged floor";
  scenes::Camera c;
  c.position = {0, 0, 1};
  c.target = {0, 1, 1};
  c.up = {0, 0, 1};
  c.vertical_fov = float(2.0 * std::atan(kTanHalfFov));
  c.aspect = 1;
  c.near_plane = float(kEyeNear);
  c.far_plane = float(kEyeFar);
  s.cameras.push_back(c);
  scenes::Material m;
  m.family = scenes::ShaderFamily::unlit_generic;
  m.color = glm::vec4(glm::vec3(kColor), 1.0f);
  s.materials = {m};
  s.meshes = {square(float(kX0), float(kY0), float(kX1), float(kY1), 0, 0)};
  s.fog.mode = scenes::FogMode::range;
  s.fog.color = glm::vec3(kFogColor);
  s.fog.start = float(kStart), s.fog.end = float(kEnd), s.fog.max_density = float(kMaxDensity);
  return s;
}

/// D3D's projected z (perspectiveRH_ZO) of a point at view depth d.
double proj_z(double d) { return kEyeFar * (d - kEyeNear) / (kEyeFar - kEyeNear); }

/// ps_2_0's visibility at the vertex shader: RangeFog with c16 = (end/range, 1, 1 - maxDensity, 1/range).
double vertex_visibility(double d) { return std::max(1.0 - kMaxDensity, (kEnd - proj_z(d)) / (kEnd - kStart)); }

struct Hit {
  bool floor = false;
  double x = 0, y = 0;  ///< the floor point the pixel's centre sees; its view depth is y
};

Hit floor_hit(int i, int j) {
  const double ndc_x = 2.0 * (i + 0.5) / kFogSide - 1.0, ndc_y = 1.0 - 2.0 * (j + 0.5) / kFogSide;
  if (ndc_y >= 0.0) return {};
  const double s = -1.0 / (ndc_y * kTanHalfFov);  // along (ndc_x t, 1, ndc_y t) from z = 1 to z = 0
  const Hit h{true, s * ndc_x * kTanHalfFov, s};
  // Away from the floor's edges, where a pixel's footprint leaves it.
  const bool inside = h.x > kX0 + 0.5 && h.x < kX1 - 0.5 && h.y > kY0 + 0.5 && h.y < kY1 - 3.0;
  return inside ? h : Hit{};
}

/// The floor's corners' visibilities interpolated at (x, y) over its two triangles, (0, 1, 2) and
/// (0, 2, 3) of square(): the point lies in its triangle, so perspective-correct weights are its
/// world barycentric coordinates.
double interpolated_visibility(double x, double y) {
  const double cx[4] = {kX0, kX1, kX1, kX0}, cy[4] = {kY0, kY0, kY1, kY1};
  for (const std::array<int, 3>& t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
    const double x0 = cx[t[0]], y0 = cy[t[0]], x1 = cx[t[1]], y1 = cy[t[1]], x2 = cx[t[2]], y2 = cy[t[2]];
    const double area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    const double w1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / area;
    const double w2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / area;
    const double w0 = 1.0 - w1 - w2;
    if (w0 >= -1e-12 && w1 >= -1e-12 && w2 >= -1e-12)
      return w0 * vertex_visibility(cy[t[0]]) + w1 * vertex_visibility(cy[t[1]]) + w2 * vertex_visibility(cy[t[2]]);
  }
  ADD_FAILURE() << "(" << x << ", " << y << ") is on no triangle of the floor";
  return 0.0;
}

/// The expected 8-bit pixel at floor point h on card `card` (exposure 1: the fog color and the
/// color reach the blend unscaled).
glm::dvec3 expected(const Hit& h, shading::ShaderModel card) {
  glm::dvec3 linear;
  if (card == shading::ShaderModel::ps_2_0) {
    const double v = std::clamp(interpolated_visibility(h.x, h.y), 0.0, 1.0);
    linear = kFogColor + (kColor - kFogColor) * v;
  } else {
    const double f = std::clamp(std::min(kMaxDensity, proj_z(h.y) / (kEnd - kStart) - kStart / (kEnd - kStart)), 0.0, 1.0);
    linear = kColor + (kFogColor - kColor) * (f * f);
  }
  return 255.0 * glm::dvec3(srgb_encode(linear.r), srgb_encode(linear.g), srgb_encode(linear.b));
}

TEST(FogFrame, RangeFogPerPixelFromPs2bAndPerVertexOnPs20) {
  FrameSettings f{kFogSide, kFogSide, 1};
  f.exposure = 1.0f;
  f.color_correction = false;
  const scenes::Scene scene = fogged_floor();
  int checked = 0;
  double largest_gap = 0.0;  // between the two models' expectations: the test tells them apart
  for (shading::ShaderModel card : {shading::ShaderModel::ps_2_0, shading::ShaderModel::ps_2_b, shading::ShaderModel::ps_3_0}) {
    SCOPED_TRACE(std::string(shading::caps(card).name));
    f.model = card;
    const rasterizer::Image image = render_frame(scene, f);
    int off = 0;
    for (int j = 0; j < kFogSide; ++j)
      for (int i = 0; i < kFogSide; ++i) {
        const Hit h = floor_hit(i, j);
        if (!h.floor) continue;
        const glm::dvec3 want = expected(h, card);
        for (int c = 0; c < 3; ++c) {
          const bool far = std::abs(image.pixel(i, j)[c] - want[c]) > 1.0;
          if (far && off < 5)
            ADD_FAILURE() << "pixel (" << i << ", " << j << ") at depth " << h.y << ", channel " << c << ": "
                          << int(image.pixel(i, j)[c]) << ", expected " << want[c];
          off += far;
        }
        ++checked;
        const glm::dvec3 other = expected(h, card == shading::ShaderModel::ps_2_0 ? shading::ShaderModel::ps_2_b
                                                                                  : shading::ShaderModel::ps_2_0);
        for (int c = 0; c < 3; ++c) largest_gap = std::max(largest_gap, std::abs(other[c] - want[c]));
      }
    EXPECT_EQ(off, 0);
  }
  std::printf("range fog: %d floor pixels checked on three models; per pixel and per vertex differ by up to %.1f steps\n",
              checked, largest_gap);
  EXPECT_GT(checked, 3 * 1000) << "the floor covers too few pixels to tell";
  EXPECT_GT(largest_gap, 10.0) << "per pixel and per vertex must disagree somewhere by more than the tolerance";
}

}  // namespace
}  // namespace luxel::frame
