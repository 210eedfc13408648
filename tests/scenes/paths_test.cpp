// camera_at: a uniform Catmull-Rom spline through the keys, clamped at the ends; model_offset:
// linear between the keys, clamped at the ends.

#include "luxel/scenes/paths.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace luxel::scenes {
namespace {

std::vector<CameraKey> path() {
  std::vector<CameraKey> keys;
  const glm::vec3 p[4] = {{0, 0, 10}, {100, 0, 20}, {100, 200, 30}, {0, 300, 40}};
  for (int i = 0; i < 4; ++i) {
    CameraKey k;
    k.time = 2.0f * i;
    k.camera.name = "key " + std::to_string(i);
    k.camera.position = p[i];
    k.camera.target = p[i] + glm::vec3(0, 0, -10);
    k.camera.vertical_fov = 0.5f + 0.1f * i;
    keys.push_back(k);
  }
  return keys;
}

TEST(CameraPath, PassesThroughEveryKey) {
  for (const CameraKey& k : path()) {
    const Camera c = camera_at(path(), k.time);
    EXPECT_LT(glm::length(c.position - k.camera.position), 1e-4f) << k.time;
    EXPECT_EQ(c.name, k.camera.name);
  }
}

TEST(CameraPath, MidpointsAreCatmullRoms) {
  // At the middle of a segment, Catmull-Rom gives (-p0 + 9 p1 + 9 p2 - p3) / 16.
  const std::vector<CameraKey> k = path();
  const glm::vec3 mid = (-k[0].camera.position + 9.0f * k[1].camera.position + 9.0f * k[2].camera.position -
                         k[3].camera.position) / 16.0f;
  const Camera c = camera_at(k, 3.0f);
  EXPECT_LT(glm::length(c.position - mid), 1e-3f);
  EXPECT_LT(glm::length(c.target - (mid + glm::vec3(0, 0, -10))), 1e-3f);
  EXPECT_EQ(c.vertical_fov, k[1].camera.vertical_fov) << "the earlier key's other fields";
  // The first segment repeats the first key as its outer neighbour: (8 p0 + 9 p1 - p2) / 16.
  const glm::vec3 first = (8.0f * k[0].camera.position + 9.0f * k[1].camera.position - k[2].camera.position) / 16.0f;
  EXPECT_LT(glm::length(camera_at(k, 1.0f).position - first), 1e-3f);
}

TEST(CameraPath, ClampsOutsideAndRefusesBadPaths) {
  const std::vector<CameraKey> k = path();
  EXPECT_EQ(camera_at(k, -5.0f).position, k.front().camera.position);
  EXPECT_EQ(camera_at(k, 50.0f).position, k.back().camera.position);
  EXPECT_THROW(camera_at({}, 0.0f), std::invalid_argument);
  EXPECT_THROW(camera_at(k, NAN), std::invalid_argument);
  std::vector<CameraKey> backwards = k;
  backwards[2].time = backwards[1].time;
  EXPECT_THROW(camera_at(backwards, 1.0f), std::invalid_argument);
}

TEST(ModelPath, LinearBetweenKeysHeldAtTheEnds) {
  Model m;
  m.name = "walker";
  EXPECT_EQ(model_offset(m, 3.0f), glm::vec3(0.0f)) << "no path: no offset";
  m.path = {{1.0f, {0, 0, 0}}, {3.0f, {40, -20, 8}}, {4.0f, {40, 0, 8}}};
  EXPECT_EQ(model_offset(m, -5.0f), glm::vec3(0, 0, 0));
  EXPECT_EQ(model_offset(m, 1.0f), glm::vec3(0, 0, 0));
  EXPECT_EQ(model_offset(m, 3.0f), glm::vec3(40, -20, 8));
  EXPECT_EQ(model_offset(m, 9.0f), glm::vec3(40, 0, 8));
  const glm::vec3 a = model_offset(m, 1.5f);  // a quarter of the way from key 0 to key 1
  EXPECT_FLOAT_EQ(a.x, 10.0f);
  EXPECT_FLOAT_EQ(a.y, -5.0f);
  EXPECT_FLOAT_EQ(a.z, 2.0f);
  const glm::vec3 b = model_offset(m, 3.75f);  // three quarters from key 1 to key 2
  EXPECT_FLOAT_EQ(b.y, -5.0f);
  EXPECT_THROW(model_offset(m, NAN), std::invalid_argument);
  m.path[2].time = 3.0f;
  EXPECT_THROW(model_offset(m, 2.0f), std::invalid_argument);
}

TEST(ModelPath, ValidateRefusesBadKeys) {
  Scene s;
  s.name = "paths";
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  s.meshes = {mesh};
  Model m;
  m.name = "walker";
  m.meshes = {0};
  m.path = {{0.0f, {0, 0, 0}}, {1.0f, {1, 0, 0}}};
  s.models = {m};
  EXPECT_NO_THROW(validate(s));
  s.models[0].path[1].offset.x = INFINITY;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s.models[0].path[1] = {0.0f, {1, 0, 0}};
  EXPECT_THROW(validate(s), std::invalid_argument);
}

}  // namespace
}  // namespace luxel::scenes
