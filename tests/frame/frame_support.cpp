#include "frame/frame_support.hpp"

#include "luxel/bake/bake.hpp"
#include "luxel/frame/textures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace luxel::frame {

scenes::Scene top_down() {
  scenes::Scene s;
  s.name = "test";
  scenes::Camera c;
  c.projection = scenes::Projection::orthographic;
  c.position = {0, 0, 10};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.ortho_height = 2;
  c.aspect = 1;
  c.near_plane = 1;
  c.far_plane = 20;
  s.cameras.push_back(c);
  return s;
}

scenes::Scene grey_square(double grey) {
  scenes::Scene s = top_down();
  scenes::Material m;
  m.family = scenes::ShaderFamily::unlit_generic;
  m.color = {float(grey), float(grey), float(grey), 1.0f};
  s.materials = {m};
  s.meshes = {square(-1, -1, 1, 1, 0, 0)};
  return s;
}

void attach_lightmaps(scenes::Scene& s, const glm::vec3& flat, const glm::vec3 (&basis)[3]) {
  scenes::Lightmaps maps;
  maps.width = maps.height = 4;
  auto add = [&](const glm::vec3& c) {
    scenes::Texture t;
    t.name = "lightmap";
    t.color_space = scenes::ColorSpace::linear;
    scenes::PixelImage image;
    image.width = image.height = 4;
    for (int i = 0; i < 16; ++i) image.rgba32f.insert(image.rgba32f.end(), {c.r, c.g, c.b, 1.0f});
    t.faces = {image};
    t.mipmaps = false;
    s.textures.push_back(t);
    return static_cast<int>(s.textures.size()) - 1;
  };
  maps.flat = add(flat);
  for (int k = 0; k < 3; ++k) maps.textures[static_cast<size_t>(k)] = add(basis[k]);
  s.lightmaps = maps;
}

scenes::Scene color_ramp() {
  scenes::Scene s = top_down();
  scenes::Material m;
  m.family = scenes::ShaderFamily::unlit_generic;
  s.materials = {m};
  s.meshes = {square(-1, -1, 1, 1, 0, 0)};
  s.meshes[0].colors = {{0.1f, 0.2f, 0.3f, 1}, {0.9f, 0.5f, 0.2f, 1}, {0.6f, 0.8f, 0.4f, 1}, {0.3f, 0.3f, 0.9f, 1}};
  s.exposure.min_scale = s.exposure.max_scale = 1.0f;
  return s;
}

scenes::Mesh square(float x0, float y0, float x1, float y1, float z, int material, bool flip) {
  scenes::Mesh m;
  m.material = material;
  m.positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
  m.normals.assign(4, {0, 0, 1});
  m.uv0 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  m.indices = flip ? std::vector<uint16_t>{0, 2, 1, 0, 3, 2} : std::vector<uint16_t>{0, 1, 2, 0, 2, 3};
  return m;
}

namespace {

/// A bake cheap enough for every test binary, sanitizers included: the frame's tests need baked
/// data to exist and to be the same every time, not to be converged.
bake::BakeSettings test_bake_settings() {
  bake::BakeSettings s = bake::BakeSettings::quick();
  s.samples = 16;
  s.cube_samples = 16;
  s.supersample = 1;
  s.max_bounces = 2;
  return s;
}

}  // namespace

double srgb_encode(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

double srgb_decode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

int srgb8(double linear) { return static_cast<int>(std::floor(srgb_encode(linear) * 255 + 0.5)); }

double through_srgb8(double linear) { return srgb_decode(srgb8(linear) / 255.0); }

int channels_off(const rasterizer::Image& image, int x0, int x1, const std::array<double, 3>& want) {
  int off = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) off += std::abs(image.pixel(x, y)[c] - want[size_t(c)]) > 1.0;
  return off;
}

void attach_test_bake(scenes::Scene& scene) {
  static std::mutex mutex;
  static std::map<std::string, bake::BakeResult> bakes;  // per scene name: built-ins bake once per binary
  std::lock_guard lock(mutex);
  auto it = bakes.find(scene.name);
  if (it == bakes.end()) it = bakes.emplace(scene.name, bake::bake(scene, test_bake_settings())).first;
  bake::attach(scene, it->second);
}

scenes::Scene baked_courtyard() {
  scenes::Scene scene = scenes::make_builtin_scene("courtyard", {64, 64});
  attach_test_bake(scene);
  return scene;
}

rasterizer::Image render_frame(const scenes::Scene& scene, const FrameSettings& settings, int threads) {
  Renderer r(scene, settings);
  rasterizer::Context ctx(threads);
  r.render(ctx);
  return r.image();
}

namespace {

/// The last built-in scene built, and its textures once a render asked for them.
struct BuiltScene {
  std::string key;
  std::shared_ptr<const scenes::Scene> scene;
  std::shared_ptr<const SceneTextures> textures;
};

std::mutex built_mutex;
BuiltScene built;

/// builtin_scene's work, with built_mutex held.
BuiltScene& build_scene(std::string_view name, int width, int height) {
  // Tests render one scene many times over (per thread count, shader model, fast path), and
  // building tris's million triangles costs more than drawing them small; keeping only the last
  // scene bounds the memory.
  const std::string key = std::string(name) + " " + std::to_string(width) + "x" + std::to_string(height);
  if (key != built.key || !built.scene) {
    built = {};
    auto fresh = std::make_shared<scenes::Scene>(scenes::make_builtin_scene(name, {width, height}));
    if (name == "demo" || name == "courtyard") attach_test_bake(*fresh);
    if (name == "tris" && kReduced) {
      scenes::Mesh& m = fresh->meshes.at(0);  // non-indexed: each three vertices a triangle
      m.positions.resize(std::min(m.positions.size(), 3 * kReducedTrisTriangles));
      m.colors.resize(m.positions.size());
    }
    built = {key, std::move(fresh), nullptr};
  }
  return built;
}

}  // namespace

std::shared_ptr<const scenes::Scene> builtin_scene(std::string_view name, int width, int height) {
  std::lock_guard lock(built_mutex);
  return build_scene(name, width, height).scene;
}

RenderedFrame render_builtin(std::string_view name, const FrameSettings& settings,
                             const rasterizer::ContextOptions& options, int frames) {
  std::shared_ptr<const scenes::Scene> scene;
  std::shared_ptr<const SceneTextures> textures;
  {
    // The scene's textures are shared by its renders as the scene is: preparing them is most of
    // what constructing a Renderer costs (textures.hpp), and most of a small frame's test.
    std::lock_guard lock(built_mutex);
    BuiltScene& b = build_scene(name, settings.width, settings.height);
    if (!b.textures) b.textures = std::make_shared<const SceneTextures>(*b.scene);
    scene = b.scene;
    textures = b.textures;
  }
  Renderer renderer(*scene, settings, textures);
  rasterizer::Context ctx(options);
  RenderedFrame f;
  for (int i = 0; i < frames; ++i) {
    renderer.render(ctx);
    if (i > 0) {
      EXPECT_TRUE(renderer.image().rgba == f.image.rgba) << name << ": frame " << i << " differs from frame 0";
    }
    f.image = renderer.image();
    f.stats = renderer.stats();
  }
  return f;
}

}  // namespace luxel::frame
