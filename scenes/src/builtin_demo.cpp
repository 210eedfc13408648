// `demo`: a small depth-tested, textured, perspective scene: a checkered ground plane running to
// the horizon (mip-mapped, trilinear: no shimmer in the distance) and a ring of brick cubes, under
// a sky-blue background.
//
// It was first written in a y-up world of meters; it is laid out there still (the numbers below)
// and mapped to Source's axes and inches by to_source(), so that it looks as it always did.

#include "builtin_scenes.hpp"

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <numbers>

namespace luxel::scenes::builtin {

namespace {

/// y-up meters -> +Z-up inches (the glTF mapping of scene.hpp).
glm::vec3 to_source(glm::vec3 p) { return glm::vec3(p.x, -p.z, p.y) * kInchesPerMeter; }
glm::vec3 to_source_direction(glm::vec3 d) { return glm::vec3(d.x, -d.z, d.y); }

/// A quad from four corners listed counter-clockwise seen from the side the normal points to.
void add_quad(Mesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n, float uv_scale) {
  const uint32_t base = static_cast<uint32_t>(m.positions.size());
  for (glm::vec3 p : {a, b, c, d}) m.positions.push_back(to_source(p));
  for (int i = 0; i < 4; ++i) m.normals.push_back(to_source_direction(n));
  m.uv0.insert(m.uv0.end(), {{0, uv_scale}, {uv_scale, uv_scale}, {uv_scale, 0}, {0, 0}});
  auto& idx = std::get<std::vector<uint32_t>>(m.indices);
  idx.insert(idx.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

void add_cube(Mesh& m, const glm::mat4& model) {
  static const glm::vec3 kNormals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& n : kNormals) {
    // Two axes spanning the face, so that (u, v, n) is right-handed.
    const glm::vec3 u = std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::normalize(glm::cross(glm::vec3(0, 1, 0), n));
    const glm::vec3 v = glm::cross(n, u);
    auto world = [&](glm::vec3 p) { return glm::vec3(model * glm::vec4(p, 1)); };
    const glm::vec3 wn = glm::normalize(glm::vec3(model * glm::vec4(n, 0)));
    add_quad(m, world(n - u - v), world(n + u - v), world(n + u + v), world(n - u + v), wn, 1.0f);
  }
}

}  // namespace

Scene make_demo() {
  Scene s;
  s.name = "builtin:demo";
  // Texel colors are sRGB bytes (the encodings of the linear colors the demo was designed with).
  s.textures.push_back(make_flat_texture("builtin:demo/checker", 256, ColorSpace::srgb, [](int x, int y) {
    const bool dark = ((x / 128) + (y / 128)) % 2;
    return dark ? glm::u8vec4(80, 85, 93, 255) : glm::u8vec4(225, 221, 212, 255);
  }));
  s.textures.push_back(make_flat_texture("builtin:demo/bricks", 128, ColorSpace::srgb, [](int x, int y) {
    const int row = y / 16, offset = (row % 2) * 16;
    const bool mortar = y % 16 < 2 || (x + offset) % 32 < 2;
    const float shade = 0.9f + 0.1f * float((x * 7 + y * 13) % 17) / 16.0f;  // 0.8..1 linear, in sRGB
    auto b = [shade](int c) { return static_cast<uint8_t>(std::lround(c * shade)); };
    return mortar ? glm::u8vec4(196, 196, 188, 255) : glm::u8vec4(b(179), b(97), b(75), 255);
  }));

  Material ground;
  ground.name = "ground";
  ground.family = ShaderFamily::lightmapped_generic;
  ground.base.texture = 0;
  Material bricks;
  bricks.name = "bricks";
  bricks.family = ShaderFamily::vertexlit_generic;
  bricks.base.texture = 1;
  s.materials = {ground, bricks};

  // Ground: 200 x 200 m, the checker repeating every 2 m.
  Mesh plane;
  plane.name = "ground";
  plane.material = 0;
  plane.indices = std::vector<uint32_t>{};
  add_quad(plane, {-100, 0, 100}, {100, 0, 100}, {100, 0, -100}, {-100, 0, -100}, {0, 1, 0}, 100.0f);
  plane.uv1 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};  // the whole lightmap: one chart
  s.meshes.push_back(std::move(plane));

  for (int i = 0; i < 7; ++i) {
    const float a = 2.0f * std::numbers::pi_v<float> * i / 7;
    glm::mat4 m = glm::translate(glm::mat4(1), {5.0f * std::cos(a), 0.9f + 0.25f * (i % 3), 5.0f * std::sin(a) - 2.0f});
    m = glm::rotate(m, 0.7f * i + 0.3f, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f * i)));
    Mesh cube;
    cube.name = "cube " + std::to_string(i);
    cube.material = 1;
    cube.indices = std::vector<uint32_t>{};
    add_cube(cube, glm::scale(m, glm::vec3(0.8f)));
    Model model;
    model.name = cube.name;
    model.meshes = {static_cast<int>(s.meshes.size())};
    model.centroid = to_source(glm::vec3(m[3]));
    s.meshes.push_back(std::move(cube));
    s.models.push_back(std::move(model));
  }

  Camera camera;
  camera.name = "demo";
  camera.position = to_source({0, 3.2f, 9});
  camera.target = to_source({0, 0.6f, -2});
  camera.vertical_fov = 55.0f * std::numbers::pi_v<float> / 180.0f;
  camera.near_plane = 0.1f * kInchesPerMeter;
  camera.far_plane = 300.0f * kInchesPerMeter;
  s.cameras.push_back(camera);

  // The sun the plain frame lights with (frame/renderer.hpp), as a light for the Source frame.
  Light sun;
  sun.name = "sun";
  sun.type = LightType::directional;
  sun.direction = -glm::normalize(to_source_direction({-0.45f, 0.8f, 0.4f}));
  sun.color = {1.1f, 1.0f, 0.85f};
  s.lights.push_back(sun);
  s.background = {0.147027266f, 0.262250658f, 0.520995573f};  // sRGB bytes (107, 140, 191)
  return s;
}

}  // namespace luxel::scenes::builtin
