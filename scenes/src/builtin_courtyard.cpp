// `courtyard`: the scene that shows every technique of the Source pipeline at once.
//
// A 1024 x 1024 inch stone-paved courtyard inside brick walls 256 inches high (world geometry:
// LightmappedGeneric, bump-mapped, env-map specular masked by the base alpha on the floor and by
// a mask texture on the walls, lightmap charts in uv1). On a pedestal in the middle stands the
// hero model, a bronze sphere in a ring (VertexLitGeneric: Phong with an exponent texture and a
// base-alpha mask, rim light, hero boost); around it crates (bumped), barrels and balls (not), one
// ball rolling around the yard along a path.
// A fountain basin holds a water plane. Lights: the sun and four local lights (two torches on the
// walls, their flames unlit, and two spots), with Source's quadratic falloff. Environment: five cube-map sample points,
// an irradiance volume over the yard (bounds and spacing; baked later), an HDR sky cube, range
// fog, a warm and a cool color-correction node, two cameras and a camera path around the yard.
//
// Everything is built in code and deterministic; textures are procedural: base textures as sRGB
// bytes, normal maps (tangent space, +Y up) and masks linear.

#include "builtin_geometry.hpp"
#include "builtin_scenes.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace luxel::scenes::builtin {

namespace {

constexpr int kTextureSize = 256;

uint8_t byte(float x) { return static_cast<uint8_t>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); }

/// A tangent-space normal map (+Y up the image) from a tiling height field height(u, v) in
/// inches-ish units; `strength` scales the slopes. Alpha carries `alpha(u, v)` (a mask).
template <class Height, class Alpha>
Texture normal_map(std::string name, Height height, float strength, Alpha alpha) {
  const int n = kTextureSize;
  std::vector<float> h(static_cast<size_t>(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) h[static_cast<size_t>(y) * n + x] = height((x + 0.5f) / n, (y + 0.5f) / n);
  auto at = [&](int x, int y) { return h[static_cast<size_t>((y + n) % n) * n + (x + n) % n]; };
  return make_flat_texture(std::move(name), n, ColorSpace::linear, [&](int x, int y) {
    // Up the image is -y: the slope along the bitangent is -(dh/dy).
    const float dx = (at(x + 1, y) - at(x - 1, y)) * 0.5f * strength;
    const float dy = (at(x, y + 1) - at(x, y - 1)) * 0.5f * strength;
    const glm::vec3 nrm = glm::normalize(glm::vec3(-dx, dy, 1.0f));
    return glm::u8vec4(byte(0.5f + 0.5f * nrm.x), byte(0.5f + 0.5f * nrm.y), byte(0.5f + 0.5f * nrm.z),
                       byte(alpha((x + 0.5f) / n, (y + 0.5f) / n)));
  });
}

// --- Patterns (u, v in [0, 1), tiling) ---

/// Paving stones: 4 x 4 per texture, 1/64 grout; returns (stone id, distance to the grout).
struct Paving {
  float edge;  // 0 at the grout line, 1 at the stone's center
  int id;
};
Paving paving(float u, float v) {
  const float x = u * 4, y = v * 4;
  const int i = int(x), j = int(y);
  const float fx = x - i, fy = y - j;
  return {std::min({fx, 1 - fx, fy, 1 - fy}) * 2, i + 4 * j};
}

/// Bricks: 8 rows of 4 per texture, every other row offset by half.
struct Brick {
  float edge;
  int id;
};
Brick brick(float u, float v) {
  const float y = v * 8;
  const int row = int(y);
  const float x = u * 4 + (row % 2) * 0.5f;
  const int col = int(x);
  const float fx = x - col, fy = y - row;
  return {std::min({fx * 2, (1 - fx) * 2, fy, 1 - fy}) * 2.5f, (col % 4) + 4 * row};
}

float puddles(float u, float v) { return std::clamp((tiled_fbm(u, v, 3, 3, 41) - 0.5f) * 5.0f, 0.0f, 1.0f); }

/// The sky, linear HDR, in the direction `d` (world: +Z up): a horizon-to-zenith gradient and the
/// sun, which is where the directional light comes from.
glm::vec3 sky_radiance(glm::vec3 d, glm::vec3 to_sun) {
  d = glm::normalize(d);
  const float up = std::max(d.z, 0.0f);
  const glm::vec3 horizon(0.85f, 0.9f, 1.0f), zenith(0.25f, 0.45f, 0.9f), ground(0.3f, 0.28f, 0.25f);
  glm::vec3 c = d.z >= 0 ? horizon + (zenith - horizon) * std::sqrt(up) : ground;
  const float cos_sun = glm::dot(d, to_sun);
  c += glm::vec3(1.0f, 0.9f, 0.7f) * (std::pow(std::max(cos_sun, 0.0f), 64.0f) * 2.0f);  // glow
  if (cos_sun > 0.9995f) c += glm::vec3(60.0f, 55.0f, 45.0f);                              // the disc
  return c;
}

/// A cube of six faces in D3D order, each face (u, v) mapped to its direction as D3D defines
/// (rasterizer/texture.hpp "Cube maps": +X (1, -t, -s), -X (-1, -t, s), +Y (s, 1, t),
/// -Y (s, -1, -t), +Z (s, -t, 1), -Z (-s, -t, -1) with s = 2u - 1, t = 2v - 1).
Texture sky_cube(int size, glm::vec3 to_sun) {
  Texture t;
  t.name = "builtin:courtyard/sky";
  t.shape = TextureShape::cube;
  t.color_space = ColorSpace::linear;
  t.wrap_u = t.wrap_v = Wrap::clamp;
  for (int f = 0; f < 6; ++f) {
    PixelImage image;
    image.width = image.height = size;
    image.rgba32f.reserve(static_cast<size_t>(size) * size * 4);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const float s = 2 * (x + 0.5f) / size - 1, tt = 2 * (y + 0.5f) / size - 1;
        const glm::vec3 dirs[6] = {{1, -tt, -s}, {-1, -tt, s}, {s, 1, tt}, {s, -1, -tt}, {s, -tt, 1}, {-s, -tt, -1}};
        const glm::vec3 c = sky_radiance(dirs[f], to_sun);
        image.rgba32f.insert(image.rgba32f.end(), {c.r, c.g, c.b, 1.0f});
      }
    t.faces.push_back(std::move(image));
  }
  return t;
}

struct Builder {
  Scene s;

  int texture(Texture t) {
    s.textures.push_back(std::move(t));
    return static_cast<int>(s.textures.size()) - 1;
  }
  int material(Material m) {
    s.materials.push_back(std::move(m));
    return static_cast<int>(s.materials.size()) - 1;
  }
  int mesh(std::string name, int material, bool indices16) {
    Mesh m;
    m.name = std::move(name);
    m.material = material;
    if (!indices16) m.indices = std::vector<uint32_t>{};
    s.meshes.push_back(std::move(m));
    return static_cast<int>(s.meshes.size()) - 1;
  }
  /// A model of the given meshes, its centroid the mean of their vertices.
  void model(std::string name, std::vector<int> meshes) {
    Model m;
    m.name = std::move(name);
    glm::dvec3 sum(0.0);
    size_t count = 0;
    for (int i : meshes) {
      compute_tangents(s.meshes[i]);
      for (const glm::vec3& p : s.meshes[i].positions) sum += glm::dvec3(p);
      count += s.meshes[i].positions.size();
    }
    m.centroid = glm::vec3(sum / double(std::max<size_t>(count, 1)));
    m.meshes = std::move(meshes);
    s.models.push_back(std::move(m));
  }
};

Light point_light(std::string name, glm::vec3 position, glm::vec3 color) {
  Light l;
  l.name = std::move(name);
  l.type = LightType::point;
  l.position = position;
  l.color = color;
  l.constant = 0, l.linear = 0, l.quadratic = 1;  // Source's default: inverse square, in inches
  l.range = 1024;
  return l;
}

Light spot_light(std::string name, glm::vec3 position, glm::vec3 target, glm::vec3 color, float inner, float outer) {
  Light l = point_light(std::move(name), position, color);
  l.type = LightType::spot;
  l.direction = glm::normalize(target - position);
  l.inner_cone = inner, l.outer_cone = outer;
  l.spot_exponent = 2;
  l.constant = 0, l.linear = 0.5f, l.quadratic = 1;
  return l;
}

Camera camera(std::string name, glm::vec3 position, glm::vec3 target, float fov_degrees) {
  Camera c;
  c.name = std::move(name);
  c.position = position;
  c.target = target;
  c.vertical_fov = fov_degrees * kPi / 180.0f;
  c.near_plane = 4;
  c.far_plane = 16384;
  return c;
}

}  // namespace

Scene make_courtyard() {
  Builder b;
  Scene& s = b.s;
  s.name = "builtin:courtyard";
  const glm::vec3 to_sun = glm::normalize(glm::vec3(-0.45f, -0.4f, 0.8f));

  // --- Textures ---
  const int paving_base = b.texture(make_flat_texture("builtin:courtyard/paving", kTextureSize, ColorSpace::srgb,
                                                      [](int x, int y) {
    const float u = (x + 0.5f) / kTextureSize, v = (y + 0.5f) / kTextureSize;
    const Paving p = paving(u, v);
    const float tone = 0.8f + 0.3f * hash01(p.id, 0, 7) + 0.25f * (tiled_fbm(u, v, 16, 3, 3) - 0.5f);
    const bool grout = p.edge < 0.06f;
    const glm::vec3 c = grout ? glm::vec3(0.38f, 0.36f, 0.33f) : glm::vec3(0.72f, 0.68f, 0.6f) * tone;
    return glm::u8vec4(byte(c.r), byte(c.g), byte(c.b), 255);
  }));
  // Alpha: the env-map mask (envmap_mask = normal_alpha): 1 in the grout, 0.85 (1 - puddles) on the
  // stones. A bumped LightmappedGeneric surface cannot take it from the base alpha: $bumpmap with
  // $basealphaenvmapmask is a combo the SDK never compiles.
  const int paving_bump = b.texture(normal_map("builtin:courtyard/paving_normal", [](float u, float v) {
    const Paving p = paving(u, v);
    return std::min(p.edge * 6.0f, 1.0f) * 2.0f + 0.6f * tiled_fbm(u, v, 16, 4, 5);
  }, 24.0f, [](float u, float v) { return paving(u, v).edge < 0.06f ? 1.0f : 0.85f * (1.0f - puddles(u, v)); }));
  const int brick_base = b.texture(make_flat_texture("builtin:courtyard/bricks", kTextureSize, ColorSpace::srgb,
                                                     [](int x, int y) {
    const float u = (x + 0.5f) / kTextureSize, v = (y + 0.5f) / kTextureSize;
    const Brick k = brick(u, v);
    const float tone = 0.75f + 0.35f * hash01(k.id, 1, 11) + 0.2f * (tiled_fbm(u, v, 32, 3, 13) - 0.5f);
    const glm::vec3 c = k.edge < 0.12f ? glm::vec3(0.78f, 0.76f, 0.7f) : glm::vec3(0.66f, 0.33f, 0.24f) * tone;
    return glm::u8vec4(byte(c.r), byte(c.g), byte(c.b), 255);
  }));
  const int brick_bump = b.texture(normal_map("builtin:courtyard/bricks_normal", [](float u, float v) {
    return std::min(brick(u, v).edge * 5.0f, 1.0f) * 1.5f + 0.5f * tiled_fbm(u, v, 32, 3, 17);
  }, 20.0f, [](float, float) { return 1.0f; }));
  // Glazed bricks shine, the mortar does not.
  const int brick_mask = b.texture(make_flat_texture("builtin:courtyard/bricks_envmask", kTextureSize, ColorSpace::linear,
                                                     [](int x, int y) {
    const float u = (x + 0.5f) / kTextureSize, v = (y + 0.5f) / kTextureSize;
    const Brick k = brick(u, v);
    const float m = k.edge < 0.12f ? 0.0f : 0.3f + 0.7f * hash01(k.id, 2, 19);
    return glm::u8vec4(byte(m), byte(m), byte(m), 255);
  }));
  const int trim_base = b.texture(make_flat_texture("builtin:courtyard/trim", kTextureSize, ColorSpace::srgb,
                                                    [](int x, int y) {
    const float g = 0.78f + 0.15f * tiled_fbm((x + 0.5f) / kTextureSize, (y + 0.5f) / kTextureSize, 8, 4, 23);
    return glm::u8vec4(byte(g), byte(g * 0.97f), byte(g * 0.92f), 255);
  }));
  // The hero: patinated bronze, bright where polished (alpha: the Phong mask).
  const int hero_base = b.texture(make_flat_texture("builtin:courtyard/bronze", kTextureSize, ColorSpace::srgb,
                                                    [](int x, int y) {
    const float u = (x + 0.5f) / kTextureSize, v = (y + 0.5f) / kTextureSize;
    const float patina = std::clamp((tiled_fbm(u, v, 4, 4, 29) - 0.45f) * 4.0f, 0.0f, 1.0f);
    const glm::vec3 bronze(0.8f, 0.55f, 0.3f), green(0.35f, 0.6f, 0.5f);
    const glm::vec3 c = bronze + (green - bronze) * patina;
    return glm::u8vec4(byte(c.r), byte(c.g), byte(c.b), byte(1.0f - patina));
  }));
  // Red: the Phong exponent (0..1 for 1..150), green: tint by the albedo, alpha: the rim mask.
  const int hero_exponent = b.texture(make_flat_texture("builtin:courtyard/bronze_exponent", kTextureSize,
                                                        ColorSpace::linear, [](int x, int y) {
    const float u = (x + 0.5f) / kTextureSize, v = (y + 0.5f) / kTextureSize;
    const float patina = std::clamp((tiled_fbm(u, v, 4, 4, 29) - 0.45f) * 4.0f, 0.0f, 1.0f);
    return glm::u8vec4(byte(0.1f + 0.6f * (1.0f - patina)), byte(0.8f), 0, byte(0.4f + 0.6f * (1.0f - patina)));
  }));
  const int hero_bump = b.texture(normal_map("builtin:courtyard/bronze_normal", [](float u, float v) {
    return tiled_fbm(u, v, 8, 4, 31);  // hammered
  }, 6.0f, [](float u, float v) { return 1.0f - std::clamp((tiled_fbm(u, v, 4, 4, 29) - 0.45f) * 4.0f, 0.0f, 1.0f); }));
  const int crate_base = b.texture(make_flat_texture("builtin:courtyard/crate", kTextureSize, ColorSpace::srgb,
                                                     [](int x, int y) {
    const float u = (x + 0.5f) / kTextureSize, v = (y + 0.5f) / kTextureSize;
    const int plank = int(v * 5);
    const bool frame = u < 0.08f || u > 0.92f || v < 0.08f || v > 0.92f;
    const float grain = tiled_fbm(u * 0.25f, v, 32, 3, 37 + plank);
    const glm::vec3 c = (frame ? glm::vec3(0.45f, 0.3f, 0.17f) : glm::vec3(0.68f, 0.5f, 0.3f)) * (0.8f + 0.35f * grain);
    return glm::u8vec4(byte(c.r), byte(c.g), byte(c.b), 255);
  }));
  const int crate_bump = b.texture(normal_map("builtin:courtyard/crate_normal", [](float u, float v) {
    const bool frame = u < 0.08f || u > 0.92f || v < 0.08f || v > 0.92f;
    const float seam = std::abs(v * 5 - std::round(v * 5)) < 0.04f ? -0.6f : 0.0f;
    return (frame ? 1.0f : 0.0f) + seam + 0.3f * tiled_fbm(u * 0.25f, v, 32, 3, 41);
  }, 16.0f, [](float, float) { return 1.0f; }));
  const int barrel_base = b.texture(make_flat_texture("builtin:courtyard/barrel", kTextureSize, ColorSpace::srgb,
                                                      [](int x, int y) {
    const float u = (x + 0.5f) / kTextureSize, v = (y + 0.5f) / kTextureSize;
    const bool hoop = std::abs(v - 0.15f) < 0.04f || std::abs(v - 0.85f) < 0.04f;
    const float stave = 0.85f + 0.25f * hash01(int(u * 24), 3, 43);
    const glm::vec3 c = hoop ? glm::vec3(0.3f, 0.3f, 0.32f) : glm::vec3(0.55f, 0.36f, 0.2f) * stave;
    return glm::u8vec4(byte(c.r), byte(c.g), byte(c.b), 255);
  }));
  const int water_bump = b.texture(normal_map("builtin:courtyard/water_normal", [](float u, float v) {
    return 0.5f * std::sin(2 * kPi * (3 * u + v)) + 0.3f * std::sin(2 * kPi * (5 * v - 2 * u)) +
           0.4f * tiled_fbm(u, v, 8, 3, 47);
  }, 4.0f, [](float, float) { return 1.0f; }));
  s.sky_texture = b.texture(sky_cube(32, to_sun));

  // --- Materials ---
  Material floor;
  floor.name = "courtyard/paving";
  floor.family = ShaderFamily::lightmapped_generic;
  floor.base.texture = paving_base;
  floor.bump.texture = paving_bump;
  floor.envmap = EnvmapSource::nearest_sample;
  floor.envmap_mask = EnvmapMask::normal_alpha;
  floor.envmap_tint = glm::vec3(0.6f);
  floor.fresnel_reflection = 0.3f;
  const int floor_m = b.material(floor);
  Material wall;
  wall.name = "courtyard/bricks";
  wall.family = ShaderFamily::lightmapped_generic;
  wall.base.texture = brick_base;
  wall.bump.texture = brick_bump;
  wall.envmap = EnvmapSource::nearest_sample;
  wall.envmap_mask = EnvmapMask::texture;
  wall.envmap_mask_texture.texture = brick_mask;
  wall.envmap_tint = glm::vec3(0.25f);
  wall.envmap_contrast = 0.5f;
  wall.fresnel_reflection = 0.5f;
  const int wall_m = b.material(wall);
  Material trim;
  trim.name = "courtyard/trim";
  trim.family = ShaderFamily::lightmapped_generic;
  trim.base.texture = trim_base;
  const int trim_m = b.material(trim);
  Material hero;
  hero.name = "courtyard/bronze";
  hero.family = ShaderFamily::vertexlit_generic;
  hero.base.texture = hero_base;
  hero.bump.texture = hero_bump;
  hero.phong = true;
  hero.phong_boost = 4;
  hero.phong_fresnel_ranges = {0.4f, 0.7f, 1.0f};
  hero.phong_exponent_texture.texture = hero_exponent;
  hero.rim = true;
  hero.rim_exponent = 3;
  hero.rim_boost = 2;
  hero.rim_mask = true;
  hero.hero_boost = 1.6f;
  hero.envmap = EnvmapSource::nearest_sample;
  hero.envmap_mask = EnvmapMask::normal_alpha;
  hero.envmap_tint = glm::vec3(0.3f);
  hero.envmap_fresnel = 1.0f;
  const int hero_m = b.material(hero);
  Material crate;
  crate.name = "courtyard/crate";
  crate.family = ShaderFamily::vertexlit_generic;
  crate.base.texture = crate_base;
  crate.bump.texture = crate_bump;
  crate.half_lambert = true;
  const int crate_m = b.material(crate);
  Material barrel;
  barrel.name = "courtyard/barrel";
  barrel.family = ShaderFamily::vertexlit_generic;
  barrel.base.texture = barrel_base;
  barrel.phong = true;
  barrel.phong_exponent = 12;
  barrel.phong_boost = 0.5f;
  const int barrel_m = b.material(barrel);
  Material ball;
  ball.name = "courtyard/painted";
  ball.family = ShaderFamily::vertexlit_generic;
  ball.color = {0.7f, 0.12f, 0.1f, 1.0f};
  ball.phong = true;
  ball.phong_exponent = 30;
  ball.phong_boost = 2;
  const int ball_m = b.material(ball);
  Material water;
  water.name = "courtyard/water";
  water.family = ShaderFamily::water;
  water.color = {0.12f, 0.3f, 0.38f, 1.0f};  // what the plain frame shows until #8
  water.water_normal.texture = water_bump;
  water.water_normal.scale = {0.25f, 0.25f};
  water.water_scroll = {0.02f, 0.01f};
  water.envmap = EnvmapSource::nearest_sample;
  water.reflect_amount = 0.6f, water.refract_amount = 0.2f;
  water.reflect_tint = {0.9f, 0.95f, 1.0f};
  water.refract_tint = {0.6f, 0.8f, 0.8f};
  water.water_fog_color = {0.08f, 0.2f, 0.22f};
  water.water_fog_start = 0, water.water_fog_end = 64;
  const int water_m = b.material(water);
  Material flame;
  flame.name = "courtyard/flame";
  flame.family = ShaderFamily::unlit_generic;
  flame.color = {1.0f, 0.6f, 0.25f, 1.0f};
  flame.emissive = {8.0f, 4.8f, 2.0f};
  const int flame_m = b.material(flame);

  // --- World geometry (lightmapped: one chart per rectangle, 8 inches a luxel) ---
  s.lightmap_luxel_size = 8.0f;
  ChartPacker charts(s.lightmap_luxel_size);
  const int floor_mesh = b.mesh("floor", floor_m, false);
  add_rectangle(s.meshes[floor_mesh], {-512, -512, 0}, {1024, 0, 0}, {0, 1024, 0}, 8, 8, 128, &charts, floor_mesh);
  const int walls = b.mesh("walls", wall_m, false);
  add_box(s.meshes[walls], {-544, 512, 0}, {544, 544, 256}, 128, &charts, walls);    // north
  add_box(s.meshes[walls], {-544, -544, 0}, {544, -512, 256}, 128, &charts, walls);  // south
  add_box(s.meshes[walls], {512, -512, 0}, {544, 512, 256}, 128, &charts, walls);    // east
  add_box(s.meshes[walls], {-544, -512, 0}, {-512, 512, 256}, 128, &charts, walls);  // west
  const int trims = b.mesh("pedestal and basin", trim_m, false);
  add_box(s.meshes[trims], {-40, -40, 0}, {40, 40, 48}, 64, &charts, trims);  // the hero's pedestal
  // The fountain basin: four rims around the water, centered on (256, -256).
  add_box(s.meshes[trims], {152, -360, 0}, {360, -344, 24}, 64, &charts, trims);
  add_box(s.meshes[trims], {152, -168, 0}, {360, -152, 24}, 64, &charts, trims);
  add_box(s.meshes[trims], {152, -344, 0}, {168, -168, 24}, 64, &charts, trims);
  add_box(s.meshes[trims], {344, -344, 0}, {360, -168, 24}, 64, &charts, trims);
  charts.pack(s.meshes);
  for (int m : {floor_mesh, walls, trims}) compute_tangents(s.meshes[m]);
  const int water_mesh = b.mesh("water", water_m, false);
  add_rectangle(s.meshes[water_mesh], {168, -344, 18}, {176, 0, 0}, {0, 176, 0}, 2, 2, 176);
  compute_tangents(s.meshes[water_mesh]);
  // The torches' flames, where the torch lights are (unlit, unbumped: no tangents).
  const int flames = b.mesh("torch flames", flame_m, true);
  for (float x : {-490.0f, 490.0f}) add_box(s.meshes[flames], {x - 5, -5, 170}, {x + 5, 5, 192}, 16, nullptr, -1, true);

  // --- Models ---
  const int hero_sphere = b.mesh("hero sphere", hero_m, true);
  add_sphere(s.meshes[hero_sphere], {0, 0, 78}, 30, 32, 16);
  const int hero_ring = b.mesh("hero ring", hero_m, true);
  add_torus(s.meshes[hero_ring], {0, 0, 78}, 44, 6, 48, 12);
  b.model("hero", {hero_sphere, hero_ring});
  const glm::vec3 crates[3][2] = {{{-440, 360, 0}, {-376, 424, 64}}, {{-360, 380, 0}, {-312, 428, 48}},
                                  {{-432, 368, 64}, {-384, 416, 112}}};
  for (int i = 0; i < 3; ++i) {
    const int m = b.mesh("crate " + std::to_string(i), crate_m, true);
    add_box(s.meshes[m], crates[i][0], crates[i][1], crates[i][1].x - crates[i][0].x, nullptr, -1, true);
    b.model(s.meshes[m].name, {m});
  }
  for (int i = 0; i < 2; ++i) {
    const int m = b.mesh("barrel " + std::to_string(i), barrel_m, true);
    add_cylinder(s.meshes[m], {-470.0f, 120.0f + 70.0f * i, 0}, 26, 60, 24);
    b.model(s.meshes[m].name, {m});
  }
  for (int i = 0; i < 3; ++i) {
    const int m = b.mesh("ball " + std::to_string(i), ball_m, true);
    const float r = 10.0f + 4.0f * i;
    add_sphere(s.meshes[m], {60.0f + 50.0f * i, 300.0f + 30.0f * (i % 2), r}, r, 24, 12);
    b.model(s.meshes[m].name, {m});
  }
  // Ball 0 rolls around the yard in the camera path's 24 seconds: past the west torch, along the
  // south wall, back up the east side of the pedestal, across irradiance-volume cells and
  // through changes of its two most significant lights.
  s.models[s.models.size() - 3].path = {{0.0f, {0, 0, 0}},       {6.0f, {-380, -300, 0}}, {12.0f, {-380, -620, 0}},
                                        {18.0f, {0, -620, 0}}, {24.0f, {0, 0, 0}}};

  // --- Lights ---
  Light sun;
  sun.name = "sun";
  sun.type = LightType::directional;
  sun.direction = -to_sun;
  sun.color = {3.2f, 3.0f, 2.6f};
  s.lights.push_back(sun);
  s.lights.push_back(point_light("torch west", {-490, 0, 180}, glm::vec3(2.0f, 1.3f, 0.6f) * 12000.0f));
  s.lights.push_back(point_light("torch east", {490, 0, 180}, glm::vec3(2.0f, 1.3f, 0.6f) * 12000.0f));
  s.lights.push_back(spot_light("hero spot", {-200, -260, 300}, {0, 0, 78}, glm::vec3(1.0f, 0.95f, 0.9f) * 60000.0f,
                                0.15f, 0.3f));
  s.lights.push_back(spot_light("fountain spot", {420, -420, 260}, {256, -256, 18}, glm::vec3(0.6f, 0.8f, 1.0f) * 40000.0f,
                                0.3f, 0.5f));

  // --- Environment ---
  for (glm::vec3 p : {glm::vec3(0, 0, 96), glm::vec3(256, -256, 48), glm::vec3(-320, -320, 64), glm::vec3(-320, 320, 64),
                      glm::vec3(320, 320, 64)}) {
    CubemapSample c;
    c.position = p;
    c.size = 64;
    s.cubemap_samples.push_back(c);
  }
  IrradianceVolume volume;
  volume.min = {-512, -512, 0};
  volume.max = {512, 512, 256};
  volume.spacing = glm::vec3(64);
  volume.counts = {17, 17, 5};
  s.irradiance_volume = volume;
  ColorCorrection warm;
  warm.lut = "builtin:warm";
  warm.position = {-300, -300, 64};
  warm.min_falloff = 128, warm.max_falloff = 512;
  warm.max_weight = 0.8f;
  ColorCorrection cool = warm;
  cool.lut = "builtin:cool";
  cool.position = {256, -256, 48};
  s.color_corrections = {warm, cool};
  s.fog.mode = FogMode::range;
  s.fog.color = {0.55f, 0.62f, 0.72f};
  s.fog.start = 600;
  s.fog.end = 6000;
  s.fog.max_density = 0.5f;
  s.exposure.min_scale = 0.5f, s.exposure.max_scale = 2.0f;
  // A bright, sunlit yard: at the default bloom scale 1 the bloom whites out the floor; Valve's
  // maps lowered it in their env_tonemap_controller the same way (SetBloomScale).
  s.exposure.bloom_scale = 0.25f;
  s.background = {0.45f, 0.6f, 0.85f};  // the sky near the horizon, for frames that draw no sky

  // --- Cameras ---
  s.cameras.push_back(camera("overview", {-470, -470, 210}, {40, 40, 40}, 70));
  s.cameras.push_back(camera("hero", {-150, -190, 100}, {0, 0, 70}, 50));
  s.cameras.push_back(camera("fountain", {40, -60, 100}, {256, -256, 18}, 60));
  // Around the yard in 24 seconds, looking at the hero, rising and falling.
  for (int k = 0; k <= 8; ++k) {
    const float a = 2 * kPi * k / 8 + 1.25f * kPi;
    CameraKey key;
    key.time = 3.0f * k;
    key.camera = camera("path " + std::to_string(k), {400 * std::cos(a), 400 * std::sin(a), 120 + 50 * std::sin(2 * a)},
                        {0, 0, 80}, 65);
    s.camera_path.push_back(key);
  }
  return s;
}

}  // namespace luxel::scenes::builtin
