// frame_camera and view_projection: Source's axes (+Z up, right-handed) to Direct3D clip space.

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace luxel::frame {
namespace {

glm::vec3 ndc(const glm::mat4& vp, glm::vec3 p) {
  const glm::vec4 c = vp * glm::vec4(p, 1.0f);
  return glm::vec3(c) / c.w;
}

TEST(View, PerspectiveLooksAlongTheCameraWithZUp) {
  scenes::Camera c;
  c.position = {0, 0, 100};
  c.target = {500, 0, 100};  // along +X
  c.vertical_fov = 1.2f;
  c.near_plane = 4;
  c.far_plane = 4000;
  const glm::mat4 vp = view_projection(c, 200, 100);
  EXPECT_NEAR(ndc(vp, c.target).x, 0.0f, 1e-6f);
  EXPECT_NEAR(ndc(vp, c.target).y, 0.0f, 1e-6f);
  EXPECT_NEAR(ndc(vp, {4, 0, 100}).z, 0.0f, 1e-5f);     // near plane: depth 0
  EXPECT_NEAR(ndc(vp, {4000, 0, 100}).z, 1.0f, 1e-5f);  // far plane: depth 1
  EXPECT_GT(ndc(vp, {500, 0, 150}).y, 0.0f);            // +Z is up on screen
  EXPECT_GT(ndc(vp, {500, -50, 100}).x, 0.0f);          // looking along +X, -Y is to the right
  // The frustum's top edge: tan(fov / 2) at distance d is NDC y = 1; its right edge is aspect wider.
  const float d = 500, up = d * std::tan(0.6f);
  EXPECT_NEAR(ndc(vp, {d, 0, 100 + up}).y, 1.0f, 1e-5f);
  EXPECT_NEAR(ndc(vp, {d, -2 * up, 100}).x, 1.0f, 1e-5f);
}

TEST(View, OrthographicMapsTheViewVolumeToTheImage) {
  scenes::Camera c;
  c.projection = scenes::Projection::orthographic;
  c.position = {640, 360, 2};
  c.target = {640, 360, 0};  // straight down: screen up is then +Y
  c.up = {0, 0, 1};
  c.ortho_height = 720;
  c.aspect = 0;
  c.near_plane = 1;
  c.far_plane = 3;
  const glm::mat4 vp = view_projection(c, 1280, 720);
  // Exact, as renderer.hpp promises for such cameras: the entries are 2/W, 2/H, -1/2 and -1, 1/2.
  EXPECT_EQ(vp[0][0], 2.0f / 1280.0f);
  EXPECT_EQ(vp[1][1], 2.0f / 720.0f);
  EXPECT_EQ(vp[2][2], -0.5f);
  EXPECT_EQ(vp[3][0], -1.0f);
  EXPECT_EQ(vp[3][1], -1.0f);
  EXPECT_EQ(vp[3][2], 0.5f);
  EXPECT_EQ(vp[1][0], 0.0f);
  EXPECT_EQ(vp[2][0], 0.0f);
  EXPECT_EQ(ndc(vp, {0, 0, 1}), glm::vec3(-1, -1, 0));
  EXPECT_EQ(ndc(vp, {1280, 720, -1}), glm::vec3(1, 1, 1));
}

TEST(View, FrameCameraPicksACameraOrThePath) {
  scenes::Scene s;
  s.name = "test";
  scenes::Camera a, b;
  a.position = {1, 2, 3};
  b.position = {4, 5, 6};
  s.cameras = {a, b};
  EXPECT_EQ(frame_camera(s, {}).position, a.position);
  FrameSettings second;
  second.camera = 1;
  EXPECT_EQ(frame_camera(s, second).position, b.position);
  second.camera = 2;
  EXPECT_THROW(frame_camera(s, second), std::invalid_argument);
  s.camera_path = {{0.0f, a}, {1.0f, b}};
  FrameSettings timed;
  timed.camera_path = true;
  timed.time = 1.0f;
  EXPECT_EQ(frame_camera(s, timed).position, b.position);
}

}  // namespace
}  // namespace luxel::frame
