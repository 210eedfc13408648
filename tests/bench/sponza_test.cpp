// W3 `sponza` (bench/workloads/sponza.hpp) against the peer's definition
// (bench/README.md), computed here independently in double precision: a small
// glTF written by this test (four quads under a scaled, translated node; a 2x1 texture; a
// double-sided quad seen from behind; a culled one; one without NORMAL) is rendered, and every
// pixel whose whole footprint lies inside one triangle is compared with a ray cast through its
// center and the workload's shading in glTF's meters and axes.

#include "scenes/temp_dir.hpp"
#include "sponza.hpp"

#include "luxel/rasterizer/context.hpp"
#include "luxel/scenes/image_io.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace luxel::bench {
namespace {

using glm::dvec3;

// --- The scene, in glTF world space ----------------------------------------------------------

struct Quad {
  std::array<dvec3, 4> corners;
  std::array<uint16_t, 6> indices;
  std::optional<std::array<dvec3, 4>> normals;  ///< unit; none: the primitive has no NORMAL
  std::array<glm::dvec2, 4> uvs;
  int material;
};

struct MaterialDef {
  glm::dvec4 factor;
  bool textured, double_sided;
};

const dvec3 kNodeTranslation(0.25, -0.5, 0.0);
constexpr double kNodeScale = 2.0;
const SponzaView kView{{0.0f, 2.0f, 6.0f}, {0.0f, 2.0f, 0.0f}};
/// The texture: two texels, one row; the second's alpha shows the peer's premultiplication.
const std::array<std::array<uint8_t, 4>, 2> kTexels = {{{200, 100, 50, 255}, {40, 160, 240, 128}}};
const std::array<MaterialDef, 3> kMaterials = {{{{1.0, 0.9, 0.8, 1.0}, true, false},
                                                {{0.8, 0.8, 0.8, 1.0}, false, true},
                                                {{0.7, 0.75, 0.8, 1.0}, false, false}}};

dvec3 unit(dvec3 v) { return glm::normalize(v); }

std::vector<Quad> quads() {
  const std::array<glm::dvec2, 4> uv = {{{0, 1}, {1, 1}, {1, 0}, {0, 0}}};
  const std::array<uint16_t, 6> ccw = {0, 1, 2, 0, 2, 3}, cw = {0, 2, 1, 0, 3, 2};
  // Textured, tilted in depth, bent normals, facing the camera.
  Quad textured{{{{-4, 3, 0.5}, {-2, 3, -0.5}, {-2, 5, -0.5}, {-4, 5, 0.5}}},
                ccw,
                std::array<dvec3, 4>{unit({-0.3, 0, 1}), unit({0.3, 0.2, 1}), unit({0.2, 0.4, 0.9}), unit({-0.2, 0.3, 1})},
                uv,
                0};
  // Double-sided, wound clockwise on screen: its back face, normals pointing away and down.
  const dvec3 away = unit({0, -0.6, -0.8});
  Quad back{{{{-1, 3, 0}, {1, 3, 0}, {1, 5, 0}, {-1, 5, 0}}}, cw, std::array<dvec3, 4>{away, away, away, away}, uv, 1};
  // Single-sided, wound clockwise: culled.
  const dvec3 z(0, 0, 1);
  Quad culled{{{{2, 3, 0}, {4, 3, 0}, {4, 5, 0}, {2, 5, 0}}}, cw, std::array<dvec3, 4>{z, z, z, z}, uv, 2};
  // No NORMAL: reads (0, 1, 0) although it faces the camera.
  Quad no_normal{{{{-1, 0, 0}, {1, 0, 0}, {1, 2, 0}, {-1, 2, 0}}}, ccw, std::nullopt, uv, 2};
  return {textured, back, culled, no_normal};
}

// --- Writing it as glTF ----------------------------------------------------------------------

template <class T>
size_t append(std::vector<uint8_t>& bin, const std::vector<T>& values) {
  while (bin.size() % 4) bin.push_back(0);
  const size_t offset = bin.size();
  bin.resize(offset + values.size() * sizeof(T));
  std::memcpy(bin.data() + offset, values.data(), values.size() * sizeof(T));
  return offset;
}

/// Writes dir/scene.gltf, scene.bin and texture.png; returns the .gltf path.
std::string write_scene(const scenes::test::TempDir& dir) {
  scenes::write_image(2, 1, std::span<const uint8_t>(&kTexels[0][0], 8), dir.file("texture.png"));
  std::vector<uint8_t> bin;
  std::string views, accessors, primitives;
  int accessor = 0;
  auto add = [&](size_t offset, size_t bytes, int count, const char* type, int component, const std::string& minmax) {
    views += std::string(views.empty() ? "" : ",") + "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
             ",\"byteLength\":" + std::to_string(bytes) + "}";
    accessors += std::string(accessors.empty() ? "" : ",") + "{\"bufferView\":" + std::to_string(accessor) +
                 ",\"componentType\":" + std::to_string(component) + ",\"count\":" + std::to_string(count) +
                 ",\"type\":\"" + type + "\"" + minmax + "}";
    return accessor++;
  };
  for (const Quad& q : quads()) {
    std::vector<float> pos, nrm, uv;
    glm::dvec3 lo(1e9), hi(-1e9);
    for (int v = 0; v < 4; ++v) {
      const dvec3 local = (q.corners[v] - kNodeTranslation) / kNodeScale;
      lo = glm::min(lo, local);
      hi = glm::max(hi, local);
      pos.insert(pos.end(), {float(local.x), float(local.y), float(local.z)});
      if (q.normals) nrm.insert(nrm.end(), {float((*q.normals)[v].x), float((*q.normals)[v].y), float((*q.normals)[v].z)});
      uv.insert(uv.end(), {float(q.uvs[v].x), float(q.uvs[v].y)});
    }
    auto f = [](double x) { return std::to_string(float(x)); };
    const std::string minmax = ",\"min\":[" + f(lo.x) + "," + f(lo.y) + "," + f(lo.z) + "],\"max\":[" + f(hi.x) + "," +
                               f(hi.y) + "," + f(hi.z) + "]";
    const int p = add(append(bin, pos), pos.size() * 4, 4, "VEC3", 5126, minmax);
    const int t = add(append(bin, uv), uv.size() * 4, 4, "VEC2", 5126, "");
    const std::vector<uint16_t> idx(q.indices.begin(), q.indices.end());
    const int i = add(append(bin, idx), idx.size() * 2, 6, "SCALAR", 5123, "");
    std::string attributes = "\"POSITION\":" + std::to_string(p) + ",\"TEXCOORD_0\":" + std::to_string(t);
    if (q.normals) attributes += ",\"NORMAL\":" + std::to_string(add(append(bin, nrm), nrm.size() * 4, 4, "VEC3", 5126, ""));
    primitives += std::string(primitives.empty() ? "" : ",") + "{\"attributes\":{" + attributes +
                  "},\"indices\":" + std::to_string(i) + ",\"material\":" + std::to_string(q.material) + "}";
  }
  std::ofstream(dir.file("scene.bin"), std::ios::binary).write(reinterpret_cast<const char*>(bin.data()), std::streamsize(bin.size()));
  std::string materials;
  for (const MaterialDef& m : kMaterials) {
    materials += std::string(materials.empty() ? "" : ",") + "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[" +
                 std::to_string(m.factor.r) + "," + std::to_string(m.factor.g) + "," + std::to_string(m.factor.b) + "," +
                 std::to_string(m.factor.a) + "]" + (m.textured ? ",\"baseColorTexture\":{\"index\":0}" : "") +
                 ",\"metallicFactor\":0},\"doubleSided\":" + (m.double_sided ? "true" : "false") + "}";
  }
  const std::string json =
      "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
      "\"nodes\":[{\"mesh\":0,\"translation\":[" + std::to_string(kNodeTranslation.x) + "," + std::to_string(kNodeTranslation.y) +
      "," + std::to_string(kNodeTranslation.z) + "],\"scale\":[2,2,2]}],"
      "\"meshes\":[{\"primitives\":[" + primitives + "]}],"
      "\"materials\":[" + materials + "],"
      // magFilter NEAREST: W3 filters trilinearly whatever the sampler says.
      "\"samplers\":[{\"magFilter\":9728,\"wrapS\":10497,\"wrapT\":10497}],"
      "\"images\":[{\"uri\":\"texture.png\"}],\"textures\":[{\"source\":0,\"sampler\":0}],"
      "\"buffers\":[{\"uri\":\"scene.bin\",\"byteLength\":" + std::to_string(bin.size()) + "}],"
      "\"bufferViews\":[" + views + "],\"accessors\":[" + accessors + "]}";
  std::ofstream(dir.file("scene.gltf")) << json;
  return dir.file("scene.gltf");
}

// --- The workload's definition, in double ----------------------------------------------------

constexpr int kWidth = 128, kHeight = 96;

struct Hit {
  int quad = -1, triangle = -1;  ///< triangle: 0 or 1 within the quad
  double t = 0;
  dvec3 bary;
};

dvec3 ray_direction(double sx, double sy) {  // sx, sy: a point on screen, pixels from the top left
  const dvec3 eye(kView.eye), target(kView.target);
  const dvec3 f = glm::normalize(target - eye);
  const dvec3 r = glm::normalize(glm::cross(f, dvec3(0, 1, 0)));
  const dvec3 u = glm::cross(r, f);
  const double t = std::tan(30.0 * M_PI / 180.0), aspect = double(kWidth) / kHeight;
  return f + r * ((2.0 * sx / kWidth - 1.0) * t * aspect) + u * ((1.0 - 2.0 * sy / kHeight) * t);
}

/// The nearest triangle the ray through (sx, sy) meets, culled ones left out.
Hit trace(const std::vector<Quad>& qs, double sx, double sy) {
  const dvec3 o(kView.eye), d = ray_direction(sx, sy);
  Hit best;
  for (size_t q = 0; q < qs.size(); ++q) {
    for (int tri = 0; tri < 2; ++tri) {
      const dvec3 a = qs[q].corners[qs[q].indices[3 * tri]], b = qs[q].corners[qs[q].indices[3 * tri + 1]],
                  c = qs[q].corners[qs[q].indices[3 * tri + 2]];
      const dvec3 n = glm::cross(b - a, c - a);
      const bool front = glm::dot(n, o - a) > 0;  // counter-clockwise as seen from the eye
      if (!front && !kMaterials[qs[q].material].double_sided) continue;
      const double t = glm::dot(a - o, n) / glm::dot(d, n);
      const dvec3 p = o + t * d;
      const double area = glm::dot(n, n);
      const dvec3 bary(glm::dot(glm::cross(c - b, p - b), n) / area, glm::dot(glm::cross(a - c, p - c), n) / area,
                       glm::dot(glm::cross(b - a, p - a), n) / area);
      if (t > 0 && bary.x >= 0 && bary.y >= 0 && bary.z >= 0 && (best.quad < 0 || t < best.t)) best = {int(q), tri, t, bary};
    }
  }
  return best;
}

/// A texel as the peer reads it: no sRGB decoding, color premultiplied by alpha the way
/// OpenImageIO's PNG reader does it (integer c a / 255).
dvec3 peer_texel(const std::array<uint8_t, 4>& t) {
  return glm::floor(dvec3(t[0], t[1], t[2]) * double(t[3]) / 255.0) / 255.0;
}

/// The peer's fragment shader for a hit, `negate_back_faces` false only to show the test has power.
glm::ivec3 expected_color(const std::vector<Quad>& qs, const Hit& h, bool negate_back_faces = true) {
  const Quad& q = qs[h.quad];
  const int i0 = q.indices[3 * h.triangle], i1 = q.indices[3 * h.triangle + 1], i2 = q.indices[3 * h.triangle + 2];
  const dvec3 p = h.bary.x * q.corners[i0] + h.bary.y * q.corners[i1] + h.bary.z * q.corners[i2];
  dvec3 n(0, 1, 0);
  if (q.normals) n = h.bary.x * (*q.normals)[i0] + h.bary.y * (*q.normals)[i1] + h.bary.z * (*q.normals)[i2];
  n = glm::normalize(n);
  const dvec3 face = glm::cross(q.corners[i1] - q.corners[i0], q.corners[i2] - q.corners[i0]);
  if (negate_back_faces && glm::dot(face, dvec3(kView.eye) - p) < 0) n = -n;
  const MaterialDef& m = kMaterials[q.material];
  dvec3 albedo(1.0);
  if (m.textured) {
    // Bilinear (the quad is magnified: level 0 only), REPEAT, one row.
    const double u = h.bary.x * q.uvs[i0].x + h.bary.y * q.uvs[i1].x + h.bary.z * q.uvs[i2].x;
    const double s = u * 2 - 0.5, fl = std::floor(s), w = s - fl;
    const int a = int(((long long)fl % 2 + 2) % 2), b = (a + 1) % 2;
    albedo = (1 - w) * peer_texel(kTexels[a]) + w * peer_texel(kTexels[b]);
  }
  albedo *= dvec3(m.factor);
  const std::array<dvec3, 6> cube = {dvec3(.30, .28, .25), dvec3(.20, .20, .22), dvec3(.45, .45, .50),
                                     dvec3(.10, .09, .08), dvec3(.25, .25, .25), dvec3(.22, .22, .24)};
  dvec3 light = n.x * n.x * cube[n.x >= 0 ? 0 : 1] + n.y * n.y * cube[n.y >= 0 ? 2 : 3] + n.z * n.z * cube[n.z >= 0 ? 4 : 5];
  const std::array<dvec3, 2> pos = {dvec3(0, 8, 0), dvec3(8, 3, 1)}, col = {dvec3(6, 5.5, 5), dvec3(2, 2.5, 4)};
  for (int i = 0; i < 2; ++i) {
    const dvec3 d = pos[i] - p;
    const double hl = std::pow(0.5 * glm::dot(n, d / glm::length(d)) + 0.5, 2.0);
    light += col[i] * hl / glm::dot(d, d);
  }
  const dvec3 c = glm::clamp(albedo * light, 0.0, 1.0) * 255.0;
  return glm::ivec3(std::lround(c.x), std::lround(c.y), std::lround(c.z));
}

rasterizer::Image render(const std::string& path, int threads, int samples = 4) {
  rasterizer::ContextOptions options;
  options.threads = threads;
  rasterizer::Context ctx(options);
  const scenes::Scene scene = load_sponza_scene(path);
  SponzaFrame frame(scene, kView, kWidth, kHeight, samples);
  frame.render(ctx);
  return frame.image();
}

glm::ivec3 pixel(const rasterizer::Image& image, int x, int y) {
  const uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

/// The hit shared by the pixel's center and its four corners (so by all its samples), if any.
std::optional<Hit> interior_hit(const std::vector<Quad>& qs, int x, int y) {
  const Hit center = trace(qs, x + 0.5, y + 0.5);
  for (auto [dx, dy] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}}) {
    const Hit corner = trace(qs, x + dx, y + dy);
    if (corner.quad != center.quad || corner.triangle != center.triangle) return std::nullopt;
  }
  return center;
}

TEST(Sponza, ShadingMatchesTheDefinitionInDouble) {
  scenes::test::TempDir dir;
  const std::vector<Quad> qs = quads();
  const rasterizer::Image image = render(write_scene(dir), 2);
  ASSERT_EQ(image.width, kWidth);
  std::array<int, 4> compared{};
  int background = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::optional<Hit> h = interior_hit(qs, x, y);
      if (!h) continue;
      // Nothing hit: the clear color (0.45, 0.55, 0.70) written as it is (no sRGB encoding).
      const glm::ivec3 want = h->quad < 0 ? glm::ivec3(115, 140, 178) : expected_color(qs, *h);
      const glm::ivec3 got = pixel(image, x, y);
      const glm::ivec3 diff = glm::abs(got - want);
      ASSERT_LE(std::max({diff.x, diff.y, diff.z}), 1)
          << "pixel (" << x << ", " << y << ") quad " << h->quad << ": got " << got.x << " " << got.y << " " << got.z
          << ", want " << want.x << " " << want.y << " " << want.z;
      (h->quad < 0 ? background : compared[h->quad]) += 1;
    }
  }
  // Every drawn quad was compared over a good part of its pixels; the culled one never drew.
  EXPECT_GT(compared[0], 150);
  EXPECT_GT(compared[1], 150);
  EXPECT_EQ(compared[2], 0);
  EXPECT_GT(compared[3], 150);
  EXPECT_GT(background, 1000);
}

/// A pixel at the center of quad q on screen, and its hit.
std::pair<glm::ivec2, Hit> center_of(const std::vector<Quad>& qs, int q) {
  dvec3 c(0.0);
  for (const dvec3& p : qs[q].corners) c += p / 4.0;
  // Project the center: intersect the image plane along the ray from the eye.
  const dvec3 eye(kView.eye), f = glm::normalize(dvec3(kView.target) - eye);
  const dvec3 r = glm::normalize(glm::cross(f, dvec3(0, 1, 0))), u = glm::cross(r, f);
  const dvec3 d = c - eye;
  const double t = std::tan(30.0 * M_PI / 180.0), aspect = double(kWidth) / kHeight;
  const double ndc_x = glm::dot(d, r) / glm::dot(d, f) / (t * aspect), ndc_y = glm::dot(d, u) / glm::dot(d, f) / t;
  const glm::ivec2 px(int((ndc_x + 1) * 0.5 * kWidth), int((1 - ndc_y) * 0.5 * kHeight));
  return {px, trace(qs, px.x + 0.5, px.y + 0.5)};
}

/// Quad q's center pixel as W3 renders the scene, and the hit the definition has there.
std::pair<glm::ivec3, Hit> rendered_center(const std::vector<Quad>& qs, int q) {
  scenes::test::TempDir dir;
  const rasterizer::Image image = render(write_scene(dir), 1);
  const auto [px, hit] = center_of(qs, q);
  return {pixel(image, px.x, px.y), hit};
}

float steps_apart(glm::ivec3 a, glm::ivec3 b) { return glm::length(glm::vec3(a - b)); }

TEST(Sponza, BackFacesOfDoubleSidedMaterialsNegateTheNormal) {
  const std::vector<Quad> qs = quads();
  const auto [got, hit] = rendered_center(qs, 1);
  ASSERT_EQ(hit.quad, 1);
  EXPECT_LE(steps_apart(got, expected_color(qs, hit)), 1.8f) << got.x << " " << got.y << " " << got.z;
  // The rule matters here: the normal as written would light the pixel very differently.
  EXPECT_GT(steps_apart(got, expected_color(qs, hit, false)), 20.0f);
}

TEST(Sponza, MissingNormalReadsPlusY) {
  const std::vector<Quad> qs = quads();
  const auto [got, hit] = rendered_center(qs, 3);
  ASSERT_EQ(hit.quad, 3);
  EXPECT_LE(steps_apart(got, expected_color(qs, hit)), 1.8f) << got.x << " " << got.y << " " << got.z;
  // Facing the camera (+Z) would be another color: the ambient cube's +Z face and other light.
  std::vector<Quad> facing = qs;
  facing[3].normals = std::array<dvec3, 4>{dvec3(0, 0, 1), dvec3(0, 0, 1), dvec3(0, 0, 1), dvec3(0, 0, 1)};
  EXPECT_GT(steps_apart(got, expected_color(facing, hit)), 10.0f);
}

TEST(Sponza, SameBytesForOneAndTwoThreads) {
  scenes::test::TempDir dir;
  const std::string path = write_scene(dir);
  for (int samples : {1, 4}) {
    const rasterizer::Image one = render(path, 1, samples);
    EXPECT_TRUE(one.rgba == render(path, 2, samples).rgba) << samples << " samples";
    EXPECT_TRUE(one.rgba == render(path, 3, samples).rgba) << samples << " samples";
  }
}

TEST(Sponza, ParsesThePeersVectorSyntax) {
  EXPECT_EQ(parse_vec3("-10.4,1.25,-0.3"), glm::vec3(-10.4f, 1.25f, -0.3f));
  EXPECT_EQ(parse_vec3("1e1,2,3"), glm::vec3(10, 2, 3));
  for (const char* bad : {"", "1,2", "1,2,3,", "1,2,3x", "a,b,c", "1;2;3", "1, 2"})
    EXPECT_FALSE(parse_vec3(bad).has_value()) << bad;
}

}  // namespace
}  // namespace luxel::bench
