// Every copied-in asset (tests/data/gltf, SOURCES.md) loads, or for the modes luxel refuses is
// refused with its line, and values from each are checked against the file's own data (decoded
// independently for these tests) and the mapping gltf.hpp documents.

#include "gltf_support.hpp"

#include "luxel/scenes/tangents.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>

namespace luxel::scenes::test {
namespace {


/// glTF meters -> Source inches, each component rounded once from double.


std::vector<uint8_t> vertex_bytes(const Mesh& m) {
  std::vector<uint8_t> b(m.positions.size() * sizeof(glm::vec3));
  std::memcpy(b.data(), m.positions.data(), b.size());
  return b;
}

// The same box in three containers: .gltf + .bin + .png, .glb, and base64 data URIs. Its root
// node's matrix turns the box's Z-up into glTF's Y-up, which luxel's Y-up -> Z-up undoes: the
// Source positions are the file's values times kInches, the cube [-0.5, 0.5]^3 m.
TEST(GltfAssets, BoxTexturedInThreeContainers) {
  const Scene a = load_gltf(asset("box-textured/glTF/BoxTextured.gltf"), no_defaults());
  const Scene b = load_gltf(asset("box-textured/glTF-Binary/BoxTextured.glb"), no_defaults());
  const Scene c = load_gltf(asset("box-textured/glTF-Embedded/BoxTextured.gltf"), no_defaults());
  for (const Scene* s : {&a, &b, &c}) {
    ASSERT_EQ(s->meshes.size(), 1u) << s->name;
    const Mesh& m = s->meshes[0];
    EXPECT_EQ(m.vertex_count(), 24u);
    EXPECT_EQ(m.index_count(), 36u);
    EXPECT_EQ(m.uv0.size(), 24u);
    EXPECT_EQ(m.tangents.size(), 24u) << "generated: the file has none";
    const Bounds bounds = bounds_of(*s);
    const float h = float(0.5 * kInches);
    EXPECT_EQ(bounds.min, glm::vec3(-h)) << s->name;
    EXPECT_EQ(bounds.max, glm::vec3(h)) << s->name;
    ASSERT_EQ(s->materials.size(), 1u);
    EXPECT_EQ(s->materials[0].name, "Texture");
    ASSERT_TRUE(s->materials[0].base.bound());
    const Texture& t = s->textures[size_t(s->materials[0].base.texture)];
    EXPECT_EQ(t.color_space, ColorSpace::srgb);
    ASSERT_EQ(t.faces.size(), 1u);
    EXPECT_FALSE(t.faces[0].is_hdr());
    // The PNG's own header (IHDR width and height, big-endian, at bytes 16 and 20).
    const std::vector<uint8_t> png = read_bytes(asset("box-textured/glTF/CesiumLogoFlat.png"));
    auto be32 = [&](size_t at) { return int(png[at]) << 24 | int(png[at + 1]) << 16 | int(png[at + 2]) << 8 | int(png[at + 3]); };
    EXPECT_EQ(t.faces[0].width, be32(16));
    EXPECT_EQ(t.faces[0].height, be32(20));
    EXPECT_EQ(t.wrap_u, Wrap::repeat);
    EXPECT_TRUE(t.mipmaps);  // minFilter NEAREST_MIPMAP_LINEAR
    EXPECT_EQ(t.min, Filter::nearest);
    ASSERT_EQ(s->models.size(), 1u);
    // Normals are unit and point out of the box: along the position's largest component.
    for (size_t v = 0; v < m.vertex_count(); ++v) {
      EXPECT_NEAR(glm::length(m.normals[v]), 1.0f, 1e-6f);
      EXPECT_NEAR(glm::dot(m.normals[v], m.positions[v]), h, 1e-3f);
    }
  }
  EXPECT_EQ(vertex_bytes(a.meshes[0]), vertex_bytes(b.meshes[0]));
  EXPECT_EQ(vertex_bytes(a.meshes[0]), vertex_bytes(c.meshes[0]));
  EXPECT_EQ(a.textures[0].faces[0].rgba8, b.textures[0].faces[0].rgba8);
  EXPECT_EQ(a.textures[0].faces[0].rgba8, c.textures[0].faces[0].rgba8);
}

// COLOR_0 is VEC3 float and equal to each vertex's glTF position (the RGB cube): alpha 1.
TEST(GltfAssets, BoxVertexColors) {
  const Scene s = load_gltf(asset("box-vertex-colors/glTF-Embedded/BoxVertexColors.gltf"), no_defaults());
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  ASSERT_EQ(m.colors.size(), 24u);
  for (size_t v = 0; v < 24; ++v) {
    const glm::vec4 c = m.colors[v];
    EXPECT_EQ(c.a, 1.0f);
    EXPECT_EQ(m.positions[v], source_inches(c.r, c.g, c.b)) << "vertex " << v;
  }
}

// Positions 0..13 are a 7 x 2 grid (x = 0..6, y = 0 or 1); the sparse part moves vertices 8, 10
// and 12 to (1, 2, 0), (3, 3, 0) and (5, 4, 0).
TEST(GltfAssets, SimpleSparseAccessor) {
  const Scene s = load_gltf(asset("simple-sparse-accessor/glTF-Embedded/SimpleSparseAccessor.gltf"), no_defaults());
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  ASSERT_EQ(m.vertex_count(), 36u) << "no normals: one vertex per triangle corner";
  // Collect the distinct positions the triangles use.
  std::vector<glm::vec3> used;
  for (size_t i = 0; i < m.index_count(); ++i) {
    const glm::vec3 p = m.positions[m.vertex_of_corner(i)];
    if (std::find(used.begin(), used.end(), p) == used.end()) used.push_back(p);
  }
  auto has = [&](glm::vec3 p) { return std::find(used.begin(), used.end(), p) != used.end(); };
  EXPECT_TRUE(has(source_inches(1, 2, 0)));
  EXPECT_TRUE(has(source_inches(3, 3, 0)));
  EXPECT_TRUE(has(source_inches(5, 4, 0)));
  EXPECT_FALSE(has(source_inches(1, 1, 0))) << "vertex 8 before substitution";
  EXPECT_TRUE(has(source_inches(2, 1, 0))) << "vertex 9 is not substituted";
  EXPECT_TRUE(has(source_inches(6, 0, 0)));
  EXPECT_EQ(used.size(), 14u);
}

// KHR_texture_transform as the file states it per material; clamp sampler; 32-bit indices.
TEST(GltfAssets, TextureTransformTest) {
  const Scene s = load_gltf(asset("texture-transform-test/glTF/TextureTransformTest.gltf"), no_defaults());
  auto material = [&](const std::string& name) -> const Material& {
    for (const Material& m : s.materials)
      if (m.name == name) return m;
    ADD_FAILURE() << "no material " << name;
    return s.materials.at(0);
  };
  EXPECT_EQ(material("Offset U").base.offset, glm::vec2(0.5f, 0.0f));
  EXPECT_EQ(material("Offset V").base.offset, glm::vec2(0.0f, 0.5f));
  EXPECT_EQ(material("Offset UV").base.offset, glm::vec2(0.5f, 0.5f));
  EXPECT_FLOAT_EQ(material("Rotation").base.rotation, 0.39269908169872414f);
  EXPECT_EQ(material("Rotation").base.scale, glm::vec2(1.0f));
  EXPECT_EQ(material("Scale").base.scale, glm::vec2(1.5f, 1.5f));
  const TextureRef& all = material("All").base;
  EXPECT_EQ(all.offset, glm::vec2(-0.2f, -0.1f));
  EXPECT_FLOAT_EQ(all.rotation, 0.3f);
  EXPECT_EQ(all.scale, glm::vec2(1.5f, 1.5f));
  EXPECT_EQ(material("Correct").base.offset, glm::vec2(0.0f));
  const Texture& uv = s.textures[size_t(material("Offset U").base.texture)];
  EXPECT_EQ(uv.wrap_u, Wrap::clamp);
  EXPECT_EQ(uv.wrap_v, Wrap::clamp);
  EXPECT_FALSE(uv.mipmaps);  // minFilter LINEAR
  ASSERT_FALSE(s.meshes.empty());
  EXPECT_TRUE(std::holds_alternative<std::vector<uint32_t>>(s.meshes[0].indices));
  EXPECT_EQ(s.models.size(), s.meshes.size()) << "each node with a mesh is a model";
}

// The file's tangents (MikkTSpace, from its authoring tool) have both handednesses, for its
// mirrored UV halves. luxel's generated tangents, computed from the same normals and UVs, agree
// with them: the same handedness and nearly the same direction.
TEST(GltfAssets, NormalTangentMirrorTest) {
  const Scene s = load_gltf(asset("normal-tangent-mirror-test/NormalTangentMirrorTest.glb"), no_defaults());
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& file = s.meshes[0];
  ASSERT_EQ(file.tangents.size(), file.vertex_count());
  size_t positive = 0, negative = 0;
  for (const glm::vec4& t : file.tangents) (t.w > 0 ? positive : negative)++;
  EXPECT_GT(positive, 0u);
  EXPECT_GT(negative, 0u);
  std::printf("NormalTangentMirrorTest: %zu vertices, %zu right-handed, %zu mirrored\n", file.vertex_count(), positive, negative);
  EXPECT_TRUE(s.materials[0].bump.bound());
  EXPECT_EQ(s.textures[size_t(s.materials[0].bump.texture)].color_space, ColorSpace::linear);
  EXPECT_TRUE(s.materials[0].double_sided);

  Mesh generated = file;
  generated.tangents.clear();
  generate_tangents(generated);
  ASSERT_GE(generated.vertex_count(), file.vertex_count());
  size_t same_hand = 0, close = 0;
  for (size_t v = 0; v < file.vertex_count(); ++v) {
    same_hand += generated.tangents[v].w == file.tangents[v].w;
    close += glm::dot(glm::vec3(generated.tangents[v]), glm::vec3(file.tangents[v])) > 0.98f;
  }
  const double n = double(file.vertex_count());
  std::printf("generated tangents: %zu of %.0f with the file's handedness, %zu within 11.5 degrees\n", same_hand, n, close);
  EXPECT_EQ(double(same_hand), n);
  EXPECT_GT(close / n, 0.95) << close << " of " << n;
}

// Modes 00-03 and 07-10 are points and lines: refused. The others draw the same unit quad
// (x, y in [-0.5, 0.5] m, facing glTF +Z): two front-facing triangles covering 1 m^2.
TEST(GltfAssets, MeshPrimitiveModes) {
  const char* refused[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
  for (int i = 0; i < 16; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "asset-generator-mesh-primitive-mode/Mesh_PrimitiveMode_%02d.gltf", i);
    const std::string path = asset(name);
    const int mode = i < 7 ? i : i - 7;
    if (mode <= 3) {
      expect_gltf_error(path, std::string("mesh 0 primitive 0 is ") + refused[mode] + "; luxel draws triangles only",
                        [&] { load_gltf(path); });
      continue;
    }
    const Scene s = load_gltf(path, no_defaults());
    ASSERT_EQ(s.meshes.size(), 1u) << name;
    const Mesh& m = s.meshes[0];
    ASSERT_EQ(m.triangle_count(), 2u) << name;
    if (i == 4) {
      EXPECT_FALSE(m.indexed()) << name << ": TRIANGLES without indices stays a non-indexed list";
    }
    double area = 0.0;
    for (size_t t = 0; t < 6; t += 3) {
      const glm::dvec3 a(m.positions[m.vertex_of_corner(t)]), b(m.positions[m.vertex_of_corner(t + 1)]), c(m.positions[m.vertex_of_corner(t + 2)]);
      const glm::dvec3 n = glm::cross(b - a, c - a);
      EXPECT_LT(n.y, 0.0) << name << ": triangle " << t / 3 << " faces away (glTF +Z is Source -Y)";
      area += 0.5 * glm::length(n);
    }
    EXPECT_NEAR(area, kInches * kInches, 1e-2) << name;
    EXPECT_EQ(bounds_of(s).min, source_inches(-0.5, -0.5, 0)) << name;
    // 11-13 have 32-bit indices (kept), 14 8-bit (widened to 16), the rest 16-bit or none.
    EXPECT_EQ(std::holds_alternative<std::vector<uint32_t>>(m.indices), i >= 11 && i <= 13) << name;
  }
}

}  // namespace
}  // namespace luxel::scenes::test
