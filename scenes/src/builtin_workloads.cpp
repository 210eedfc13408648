// W1 `fill` and W2 `tris`: the benchmark workloads shared with the llvmpipe peer
// (bench/README.md), rebuilt exactly as that harness defines them, as scenes.
//
// The peer states them in OpenGL terms (NDC depth in [-1, 1], window y up). Here each is a sheet
// of unlit, vertex-colored, double-sided triangles in the XY plane seen from above by an
// orthographic camera (screen right = +X, screen up = +Y), with sizes chosen so that the camera's
// view-projection matrix is exactly the peer's mapping: the frame (frame/renderer.hpp) then gives
// every vertex the clip position the peer's vertex shader computes, bit for bit. Their materials
// write colors as they are ($linearwrite), as the peer does.

#include "builtin_scenes.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace luxel::scenes::builtin {

namespace {

Material workload_material(std::string name, glm::vec3 color) {
  Material m;
  m.name = std::move(name);
  m.family = ShaderFamily::unlit_generic;
  m.color = glm::vec4(color, 1.0f);
  m.double_sided = true;  // the peer draws with culling off
  m.linear_write = true;
  return m;
}

/// The peer's frame is clear, draw, resolve: no tone mapping, so no auto exposure (whose
/// histogram pass would otherwise run after every frame, as the default Exposure's range asks).
void fix_exposure(Scene& s) { s.exposure.min_scale = s.exposure.max_scale = 1.0f; }

}  // namespace

// W1: a 64 x 36 grid of quads covering the viewport, drawn as 8 layers, each nearer than the
// last, colored uColor_k * (0.9 + 0.1 u). The grid spans x, y in [-512, 512] inches (NDC x 512,
// exact), seen by a square orthographic view (aspect 1: the grid covers any image exactly, as
// the peer's NDC grid does). Layer k lies at z = 128 k, the camera 1024 above the floor with
// near 64 and far 1088, so that depth = (960 - 128 k) / 1024 = 0.5 (0.875 - 0.25 k) + 0.5: the
// peer's NDC depth mapped to Direct3D's [0, 1], exactly.
Scene make_fill() {
  constexpr int kQuadsX = 64, kQuadsY = 36, kLayers = 8;
  static constexpr glm::vec3 kLayerColor[kLayers] = {{.90f, .20f, .20f}, {.20f, .90f, .20f}, {.20f, .20f, .90f},
                                                     {.90f, .90f, .20f}, {.90f, .20f, .90f}, {.20f, .90f, .90f},
                                                     {.60f, .60f, .60f}, {.95f, .55f, .15f}};
  Scene s;
  s.name = "builtin:fill";
  std::vector<uint16_t> indices;
  const int row = kQuadsX + 1;
  for (int j = 0; j < kQuadsY; ++j) {
    for (int i = 0; i < kQuadsX; ++i) {
      const uint16_t v00 = uint16_t(j * row + i), v10 = uint16_t(v00 + 1);
      const uint16_t v01 = uint16_t(v00 + row), v11 = uint16_t(v01 + 1);
      indices.insert(indices.end(), {v00, v10, v11, v00, v11, v01});
    }
  }
  for (int k = 0; k < kLayers; ++k) {
    s.materials.push_back(workload_material("layer " + std::to_string(k), kLayerColor[k]));
    Mesh m;
    m.name = "layer " + std::to_string(k);
    m.material = k;
    for (int j = 0; j <= kQuadsY; ++j) {
      for (int i = 0; i <= kQuadsX; ++i) {
        const float ndc_x = -1.0f + 2.0f * i / kQuadsX, ndc_y = -1.0f + 2.0f * j / kQuadsY;
        m.positions.push_back({512.0f * ndc_x, 512.0f * ndc_y, 128.0f * k});
        const float ramp = 0.9f + 0.1f * (float(i) / kQuadsX);  // the peer's 0.9 + 0.1 uv.x
        m.colors.push_back({ramp, ramp, ramp, 1.0f});
      }
    }
    m.indices = indices;
    s.meshes.push_back(std::move(m));
  }
  Camera c;
  c.name = "fill";
  c.projection = Projection::orthographic;
  c.position = {0, 0, 1024};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.ortho_height = 1024;
  c.aspect = 1.0f;
  c.near_plane = 64;
  c.far_plane = 1088;
  s.cameras.push_back(c);
  s.background = {0, 0, 0};
  fix_exposure(s);
  return s;
}

// W2: one million small equilateral triangles (2 to 4 pixel^2) with random position, depth,
// orientation and flat color, from std::mt19937(1), non-indexed. One inch is one pixel of the
// width x height image the scene is built for: x, y are the peer's window coordinates (origin
// bottom-left) and z = -(NDC depth) in [-1, 1]; the camera, 2 above z = 0 with near 1 and far 3,
// maps z to depth (1 - z) / 2, the peer's NDC depth mapped to [0, 1]. Its aspect is the image's,
// so drawn at the size it was built for, the clip positions are the peer's bit for bit.
Scene make_tris(int width, int height) {
  constexpr int kTriangles = 1'000'000;
  Scene s;
  s.name = "builtin:tris";
  Material material = workload_material("tris", glm::vec3(1.0f));
  s.materials.push_back(material);
  Mesh m;
  m.name = "tris";
  m.material = 0;
  m.positions.reserve(size_t(kTriangles) * 3);
  m.colors.reserve(size_t(kTriangles) * 3);
  std::mt19937 rng(1);
  auto u = [&rng] { return double(rng() >> 8) / double(1u << 24); };
  const double pi = std::numbers::pi;
  for (int t = 0; t < kTriangles; ++t) {
    const double cx = width * u(), cy = height * u(), z = 2 * u() - 1;
    const double area = 2 + 2 * u(), theta = 2 * pi * u();
    const uint32_t r = 64 + rng() % 192, g = 64 + rng() % 192, b = 64 + rng() % 192;
    // The peer's RGBA8 color, normalized: the frame writes it back to the same bytes.
    const glm::vec4 color = glm::vec4(float(r), float(g), float(b), 255.0f) / 255.0f;
    const double R = std::sqrt(4 * area / (3 * std::sqrt(3.0)));
    for (int k = 0; k < 3; ++k) {
      const double a = theta + k * (2 * pi / 3);  // the peer's exact expression
      m.positions.push_back({float(cx + R * std::cos(a)), float(cy + R * std::sin(a)), -float(z)});
      m.colors.push_back(color);
    }
  }
  s.meshes.push_back(std::move(m));
  Camera c;
  c.name = "tris";
  c.projection = Projection::orthographic;
  c.position = {0.5f * width, 0.5f * height, 2};
  c.target = {0.5f * width, 0.5f * height, 0};
  c.up = {0, 1, 0};
  c.ortho_height = float(height);
  c.aspect = 0;
  c.near_plane = 1;
  c.far_plane = 3;
  s.cameras.push_back(c);
  s.background = {0.010329823f, 0.010329823f, 0.010329823f};  // sRGB byte 26: the peer's clear to 0.1
  fix_exposure(s);
  return s;
}

}  // namespace luxel::scenes::builtin
