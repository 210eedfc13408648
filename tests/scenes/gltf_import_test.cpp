// load_gltf on small files built here: units and axes, the node hierarchy (matrix and TRS,
// normals by the inverse transpose, mirroring), index types, strips and fans, normalized
// attributes, materials (the PBR table and extras), lights, cameras and the defaults. Expected
// values are worked out by hand in the comments, not by the code under test.

#include "gltf_support.hpp"

#include "luxel/scenes/gltf.hpp"
#include "luxel/scenes/image_io.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace luxel::scenes::test {
namespace {



void expect_near(glm::vec3 a, glm::vec3 b, float tolerance, const char* what) {
  EXPECT_NEAR(a.x, b.x, tolerance) << what;
  EXPECT_NEAR(a.y, b.y, tolerance) << what;
  EXPECT_NEAR(a.z, b.z, tolerance) << what;
}


TEST(GltfImport, MetersAndYUpBecomeInchesAndZUp) {
  TempDir dir;
  GltfBuilder b;
  const int pos = b.add_positions({1, 2, 3, -1, 0.5f, 0, 0, 0, -2});
  b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}})}});
  const Scene s = load_gltf(b.write(dir), no_defaults());
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  ASSERT_EQ(m.positions.size(), 3u);
  // (1, 2, 3) m: 1 m right, 2 m up, 3 m towards the viewer = (x, -z, y) in Source.
  EXPECT_EQ(m.positions[0], source_inches(1, 2, 3));
  EXPECT_EQ(m.positions[1], source_inches(-1, 0.5, 0));
  EXPECT_EQ(m.positions[2], source_inches(0, 0, -2));
  EXPECT_EQ(m.positions[2], glm::vec3(0.0f, float(2 * kInches), 0.0f));
  EXPECT_EQ(s.name, dir.file("scene.gltf"));
}

// Parent: matrix translating by (1, 0, 0). Child: TRS with rotation 90 degrees about +Y
// (quaternion (0, sin 45, 0, cos 45)) and scale (2, 1, 1).
//  vertex (1, 0, 0): scale -> (2, 0, 0); R_y(90): (x, y, z) -> (z, y, -x) gives (0, 0, -2);
//  translate -> (1, 0, -2) m -> Source (1, 2, 0) * kInches.
//  vertex (0, 1, 0): -> (0, 1, 0) -> (0, 1, 0) -> (1, 1, 0) -> Source (1, 0, 1) * kInches.
//  normal (1, 1, 0) / sqrt 2: the inverse transpose of scale (2, 1, 1) is (1/2, 1, 1):
//  (0.5, 1, 0) / |.| = (1, 2, 0) / sqrt 5; R_y(90) -> (0, 2, -1) / sqrt 5 -> Source (0, 1, 2) / sqrt 5.
TEST(GltfImport, NodeHierarchyFlattensWithInverseTransposeNormals) {
  TempDir dir;
  GltfBuilder b;
  const int pos = b.add_positions({1, 0, 0, 0, 1, 0, 0, 0, 1});
  const float r = float(1 / std::sqrt(2.0));
  const int nrm = b.add_floats({r, r, 0, r, r, 0, r, r, 0}, "VEC3", 3);
  const int mesh = b.add_mesh({{"POSITION", pos}, {"NORMAL", nrm}});
  b.doc["nodes"].push_back({{"mesh", mesh}, {"rotation", {0, std::sin(M_PI / 4), 0, std::cos(M_PI / 4)}}, {"scale", {2, 1, 1}}});
  b.add_node({{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1}}, {"children", {0}}});
  const Scene s = load_gltf(b.write(dir), no_defaults());
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  const float tol = 1e-4f;
  expect_near(m.positions[0], glm::vec3(float(kInches), float(2 * kInches), 0), tol, "vertex 0");
  expect_near(m.positions[1], glm::vec3(float(kInches), 0, float(kInches)), tol, "vertex 1");
  const float s5 = float(std::sqrt(5.0));
  expect_near(m.normals[0], glm::vec3(0, 1 / s5, 2 / s5), 1e-6f, "normal");
  // A node with a mesh is a model; its centroid is the mean of its world positions.
  ASSERT_EQ(s.models.size(), 1u);
  const glm::vec3 mean = (m.positions[0] + m.positions[1] + m.positions[2]) / 3.0f;
  expect_near(s.models[0].centroid, mean, 1e-3f, "centroid");
  ASSERT_EQ(s.models[0].meshes, std::vector<int>{0});
}

// Scale (-1, 1, 1) mirrors: triangle (0, 1, 2) must become (0, 2, 1) to stay front-facing, a
// tangent (1, 0, 0, +1) becomes (-1, 0, 0) in glTF x, i.e. Source (-1, 0, 0), with w = -1.
TEST(GltfImport, MirroringFlipsWindingAndHandedness) {
  TempDir dir;
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const int nrm = b.add_floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  const int tan = b.add_floats({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, -1}, "VEC4", 4);
  const int idx = b.add_accessor(std::vector<uint16_t>{0, 1, 2}, 5123, "SCALAR", 1);
  b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}, {"NORMAL", nrm}, {"TANGENT", tan}}, idx)}, {"scale", {-1, 1, 1}}});
  const Scene s = load_gltf(b.write(dir), no_defaults());
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(std::get<std::vector<uint16_t>>(m.indices), (std::vector<uint16_t>{0, 2, 1}));
  expect_near(glm::vec3(m.tangents[0]), glm::vec3(-1, 0, 0), 1e-6f, "tangent");
  EXPECT_EQ(m.tangents[0].w, -1.0f);
  EXPECT_EQ(m.tangents[2].w, 1.0f);
  // Normal (0, 0, 1) glTF under x -> -x stays (0, 0, 1) = Source (0, -1, 0).
  expect_near(m.normals[0], glm::vec3(0, -1, 0), 1e-6f, "normal");
  // Still front-facing: the wound normal agrees with the vertex normal.
  const glm::vec3 wound = glm::cross(m.positions[m.vertex_of_corner(1)] - m.positions[m.vertex_of_corner(0)], m.positions[m.vertex_of_corner(2)] - m.positions[m.vertex_of_corner(0)]);
  EXPECT_GT(glm::dot(wound, m.normals[0]), 0.0f);
}

TEST(GltfImport, EveryIndexTypeAndNoIndices) {
  TempDir dir;
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
  const int i8 = b.add_accessor(std::vector<uint8_t>{0, 1, 2, 2, 1, 3}, 5121, "SCALAR", 1);
  const int i16 = b.add_accessor(std::vector<uint16_t>{0, 1, 3, 0, 3, 2}, 5123, "SCALAR", 1);
  const int i32 = b.add_accessor(std::vector<uint32_t>{3, 2, 1, 0, 1, 2}, 5125, "SCALAR", 1);
  for (int i : {i8, i16, i32}) b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}}, i)}});
  const int tri = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  b.add_node({{"mesh", b.add_mesh({{"POSITION", tri}})}});
  GltfImportOptions o = no_defaults();
  const Scene s = load_gltf(b.write(dir), o);
  ASSERT_EQ(s.meshes.size(), 4u);
  // Without NORMAL each triangle gets its own vertices (flat normals), so compare the positions
  // the indices select, in order.
  auto corners = [](const Mesh& m) {
    std::vector<glm::vec3> c;
    for (size_t i = 0; i < 3 * m.triangle_count(); ++i) c.push_back(m.positions[m.vertex_of_corner(i)]);
    return c;
  };
  const glm::vec3 p0 = source_inches(0, 0, 0), p1 = source_inches(1, 0, 0), p2 = source_inches(0, 1, 0), p3 = source_inches(1, 1, 0);
  EXPECT_TRUE(std::holds_alternative<std::vector<uint16_t>>(s.meshes[0].indices)) << "8-bit widens to 16";
  EXPECT_EQ(corners(s.meshes[0]), (std::vector<glm::vec3>{p0, p1, p2, p2, p1, p3}));
  EXPECT_TRUE(std::holds_alternative<std::vector<uint16_t>>(s.meshes[1].indices));
  EXPECT_EQ(corners(s.meshes[1]), (std::vector<glm::vec3>{p0, p1, p3, p0, p3, p2}));
  EXPECT_TRUE(std::holds_alternative<std::vector<uint32_t>>(s.meshes[2].indices));
  EXPECT_EQ(corners(s.meshes[2]), (std::vector<glm::vec3>{p3, p2, p1, p0, p1, p2}));
  EXPECT_FALSE(s.meshes[3].indexed()) << "a list without indices stays one";
  EXPECT_EQ(corners(s.meshes[3]), (std::vector<glm::vec3>{p0, p1, p2}));
  // Flat normals: glTF +Z (the triangles face the viewer) = Source -Y.
  for (const glm::vec3& n : s.meshes[3].normals) expect_near(n, glm::vec3(0, -1, 0), 1e-6f, "flat normal");
}

// The specification's orders: strip triangle i = (v_i, v_{i+1+i%2}, v_{i+2-i%2}),
// fan triangle i = (v_{i+1}, v_{i+2}, v_0).
TEST(GltfImport, StripsAndFansBecomeLists) {
  TempDir dir;
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 0});
  const int nrm = b.add_floats(std::vector<float>(15, 0.0f), "VEC3", 3);
  const int ind = b.add_accessor(std::vector<uint16_t>{4, 3, 2, 1, 0}, 5123, "SCALAR", 1);
  b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}, {"NORMAL", nrm}}, ind, 5)}});
  b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}, {"NORMAL", nrm}}, ind, 6)}});
  const Scene s = load_gltf(b.write(dir), no_defaults());
  EXPECT_EQ(std::get<std::vector<uint16_t>>(s.meshes[0].indices), (std::vector<uint16_t>{4, 3, 2, 3, 1, 2, 2, 1, 0}));
  EXPECT_EQ(std::get<std::vector<uint16_t>>(s.meshes[1].indices), (std::vector<uint16_t>{3, 2, 4, 2, 1, 4, 1, 0, 4}));
}

TEST(GltfImport, PointsAndLinesAreRefused) {
  TempDir dir;
  const char* names[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
  for (int mode = 0; mode < 4; ++mode) {
    GltfBuilder b;
    const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
    b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}}, -1, mode)}});
    const std::string path = b.write(dir, "mode" + std::to_string(mode) + ".gltf");
    expect_gltf_error(path, std::string("mesh 0 primitive 0 is ") + names[mode] + "; luxel draws triangles only",
                      [&] { load_gltf(path); });
  }
}

// TEXCOORD_0 as normalized unsigned bytes: 0, 255, 51 -> 0, 1, 0.2; COLOR_0 as normalized
// unsigned shorts (VEC3: alpha 1): 65535 -> 1, 13107 -> 0.2. TEXCOORD_1 (floats) -> uv1.
TEST(GltfImport, NormalizedIntegerAttributesAndUv1) {
  TempDir dir;
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const int nrm = b.add_floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  const int uv = b.add_accessor(std::vector<uint8_t>{0, 255, 0, 0, 51, 51, 0, 0, 0, 0, 0, 0}, 5121, "VEC2", 2, true);
  // One element is 2 bytes: the view's stride must be 4 (vertex attributes align to 4 bytes).
  b.doc["bufferViews"].back()["byteStride"] = 4;
  b.doc["accessors"].back()["count"] = 3;
  const int uv1 = b.add_floats({0.25f, 0.5f, 0.75f, 1, 0, 0}, "VEC2", 2);
  const int col = b.add_accessor(std::vector<uint16_t>{65535, 13107, 0, 0, 65535, 0, 0, 0, 65535}, 5123, "VEC3", 3, true);
  b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}, {"TEXCOORD_1", uv1}, {"COLOR_0", col}})}});
  GltfImportOptions o = no_defaults();
  o.generate_tangents = false;
  const Scene s = load_gltf(b.write(dir), o);
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(m.uv0[0], glm::vec2(0, 1));
  EXPECT_EQ(m.uv0[1], glm::vec2(51 / 255.0f, 51 / 255.0f));
  EXPECT_FLOAT_EQ(m.uv0[1].x, 0.2f);
  EXPECT_EQ(m.uv1[1], glm::vec2(0.75f, 1.0f));
  EXPECT_EQ(m.colors[0], glm::vec4(1.0f, 13107 / 65535.0f, 0, 1));
  EXPECT_FLOAT_EQ(m.colors[0].g, 0.2f);
  EXPECT_EQ(m.colors[2], glm::vec4(0, 0, 1, 1));
  EXPECT_TRUE(m.tangents.empty());
}

TEST(GltfImport, AttributeTypesOutsideTheSpecificationAreRefused) {
  TempDir dir;
  GltfBuilder b;
  const int pos = b.add_accessor(std::vector<uint16_t>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, 5123, "VEC3", 3);
  b.doc["accessors"].back()["count"] = 3;
  b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}})}});
  const std::string path = b.write(dir);
  expect_gltf_error(path, "mesh 0 primitive 0 POSITION (accessor 0) may not be UNSIGNED_SHORT", [&] { load_gltf(path); });
}

TEST(GltfImport, MaterialsFollowTheTableAndExtrasOverride) {
  TempDir dir;
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  b.doc["materials"] = {
      {{"name", "plastic"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1.0, 0.75}}, {"roughnessFactor", 0.5}, {"metallicFactor", 0.0}}},
       {"alphaMode", "MASK"}, {"alphaCutoff", 0.3}, {"doubleSided", true},
       {"emissiveFactor", {1.0, 0.5, 0.0}},
       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}},
      {{"name", "wall"},
       {"pbrMetallicRoughness", {{"roughnessFactor", 0.5}}},
       {"extras", {{"luxel", {{"shader", "LightmappedGeneric"}, {"phongexponent", 20}, {"envmaptint", {0.1, 0.2, 0.3}},
                              {"envmap", "env_cubemap"}, {"envmapmask", "basealpha"}, {"halflambert", true}}}}}},
      {{"name", "mirror"}, {"pbrMetallicRoughness", {{"roughnessFactor", 0.2}, {"metallicFactor", 1.0}, {"baseColorFactor", {1.0, 0.5, 0.0, 1.0}}}}},
  };
  for (int mat = 0; mat < 3; ++mat) b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}}, -1, -1, mat)}});
  const Scene s = load_gltf(b.write(dir), no_defaults());
  ASSERT_EQ(s.materials.size(), 3u);
  const Material& p = s.materials[0];
  EXPECT_EQ(p.name, "plastic");
  EXPECT_EQ(p.family, ShaderFamily::vertexlit_generic);
  EXPECT_EQ(p.color, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
  EXPECT_EQ(p.alpha, AlphaMode::alpha_test);
  EXPECT_FLOAT_EQ(p.alpha_cutoff, 0.3f);
  EXPECT_TRUE(p.double_sided);
  EXPECT_EQ(p.emissive, glm::vec3(4.0f, 2.0f, 0.0f));  // factor x strength
  // roughness 0.5: GGX alpha 0.25, Blinn-Phong exponent 2 / 0.25^2 - 2 = 30.
  EXPECT_TRUE(p.phong);
  EXPECT_FLOAT_EQ(p.phong_exponent, 30.0f);
  EXPECT_EQ(p.envmap, EnvmapSource::none);  // not metallic
  const Material& w = s.materials[1];
  EXPECT_EQ(w.family, ShaderFamily::lightmapped_generic);
  EXPECT_FLOAT_EQ(w.phong_exponent, 20.0f);
  EXPECT_EQ(w.envmap, EnvmapSource::nearest_sample);
  EXPECT_EQ(w.envmap_mask, EnvmapMask::base_alpha);
  EXPECT_EQ(w.envmap_tint, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_TRUE(w.half_lambert);
  // metallic 1, roughness 0.2: env map tinted lerp(0.04, base, 1) * (1 - 0.2) = base * 0.8.
  const Material& m = s.materials[2];
  EXPECT_EQ(m.envmap, EnvmapSource::nearest_sample);
  expect_near(m.envmap_tint, glm::vec3(0.8f, 0.4f, 0.0f), 1e-6f, "envmap tint");
  // The LightmappedGeneric primitive is world geometry, the others are models.
  ASSERT_EQ(s.models.size(), 2u);
  EXPECT_EQ(s.models[0].meshes, std::vector<int>{0});
  EXPECT_EQ(s.models[1].meshes, std::vector<int>{2});
}

// A data-URI PNG; KHR_texture_transform's texCoord overrides the textureInfo's; a third UV set
// is refused (luxel has two).
TEST(GltfImport, TextureTransformPicksTheUvSet) {
  TempDir dir;
  PixelImage px;
  px.width = 2, px.height = 1;
  px.rgba8 = {10, 20, 30, 40, 50, 60, 70, 80};
  const std::vector<uint8_t> png = encode_png(px, "px");
  GltfBuilder b;
  b.doc["images"] = {{{"uri", "data:image/png;base64," + base64(png)}}};
  b.doc["samplers"] = {{{"wrapS", 33648}, {"wrapT", 33071}, {"magFilter", 9728}, {"minFilter", 9987}}};
  b.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
  b.doc["extensionsUsed"] = {"KHR_texture_transform"};
  json info = {{"index", 0}, {"texCoord", 0}};
  info["extensions"]["KHR_texture_transform"] = {{"texCoord", 1}, {"offset", {0.5, 0.25}}};
  json material;
  material["pbrMetallicRoughness"]["baseColorTexture"] = info;
  material["normalTexture"] = {{"index", 0}};
  b.doc["materials"] = json::array({material});
  const std::string path = b.write(dir);
  const Scene s = load_gltf(path, no_defaults());
  const Material& m = s.materials[0];
  EXPECT_EQ(m.base.uv_set, 1);
  EXPECT_EQ(m.base.offset, glm::vec2(0.5f, 0.25f));
  // One image read two ways: the base color as sRGB, the normal map as linear.
  ASSERT_EQ(s.textures.size(), 2u);
  const Texture& base = s.textures[size_t(m.base.texture)];
  const Texture& bump = s.textures[size_t(m.bump.texture)];
  EXPECT_EQ(base.color_space, ColorSpace::srgb);
  EXPECT_EQ(bump.color_space, ColorSpace::linear);
  EXPECT_EQ(base.faces[0].rgba8, px.rgba8);
  EXPECT_EQ(base.wrap_u, Wrap::mirror);
  EXPECT_EQ(base.wrap_v, Wrap::clamp);
  EXPECT_EQ(base.mag, Filter::nearest);
  EXPECT_EQ(base.min, Filter::linear);
  EXPECT_TRUE(base.mipmaps);
  b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"]["texCoord"] = 2;
  const std::string bad = b.write(dir, "uv2.gltf");
  expect_gltf_error(bad, "material 0 base color texture reads TEXCOORD_2; luxel reads TEXCOORD_0 and _1", [&] { load_gltf(bad); });
}

TEST(GltfImport, UnknownShaderInExtrasIsNamed) {
  TempDir dir;
  GltfBuilder b;
  b.doc["materials"] = {{{"extras", {{"luxel", {{"shader", "Refract"}}}}}}};
  const std::string path = b.write(dir);
  expect_gltf_error(path, "material 0 extras ask for shader 'Refract'", [&] { load_gltf(path); });
}

// An index must be an integer that fits an int: 2.5 or 1e300 names nothing (converting 1e300 to
// int is undefined), and the refusal names the number as the file wrote it.
TEST(GltfImport, IndicesThatAreNotIntegersAreNamed) {
  TempDir dir;
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}}, {{"type", "point"}}, {{"type", "point"}}}}}}};
  b.add_node({{"name", "lamp"}, {"extensions", {{"KHR_lights_punctual", {{"light", 2.5}}}}}});
  const std::string half = b.write(dir, "half.gltf");
  expect_gltf_error(half, "nodes[0].extensions.KHR_lights_punctual.light is a fractional number (2.5), not an index", [&] { load_gltf(half); });
  b.doc["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 1e300;
  const std::string huge = b.write(dir, "huge.gltf");
  expect_gltf_error(huge, "nodes[0].extensions.KHR_lights_punctual.light is a fractional number (1e+300), not an index", [&] { load_gltf(huge); });

  GltfBuilder m;
  m.doc["materials"] = {{{"extras", {{"luxel", {{"bumpmap", {{"index", -1e300}}}}}}}}};
  const std::string texture = m.write(dir, "texture.gltf");
  expect_gltf_error(texture, "material 0 extras bumpmap refers to texture -1.0000000000000001e+300, which is not an index",
                    [&] { load_gltf(texture); });
}

// KHR_lights_punctual: a point light of 10 cd, color (1, 0.5, 0.25), 2 m up. At 50 inches
// (50 / kInches m) glTF gives 10 / (50 / kInches)^2 = 10 kInches^2 / 2500 per unit color; Source gives
// color / (quadratic d^2) with d = 50.
TEST(GltfImport, PunctualLightsKeepTheirInverseSquareFalloff) {
  TempDir dir;
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"] = {{"KHR_lights_punctual",
                          {{"lights",
                            {{{"type", "point"}, {"intensity", 10.0}, {"color", {1.0, 0.5, 0.25}}, {"range", 3.0}},
                             {{"type", "spot"}, {"intensity", 2.0}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}},
                             {{"type", "directional"}, {"intensity", 3.0}}}}}}};
  b.add_node({{"translation", {0, 2, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  b.add_node({{"translation", {1, 0, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  // Rotated -90 degrees about X: local -Z (forward) becomes glTF -Y (straight down) = Source -Z.
  b.add_node({{"rotation", {-std::sin(M_PI / 4), 0, 0, std::cos(M_PI / 4)}}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
  const Scene s = load_gltf(b.write(dir), no_defaults());
  ASSERT_EQ(s.lights.size(), 3u);
  const Light& p = s.lights[0];
  EXPECT_EQ(p.type, LightType::point);
  expect_near(p.position, glm::vec3(0, 0, float(2 * kInches)), 1e-4f, "point position");
  const double d = 50.0;
  const double gltf_at_d = 10.0 / ((d / kInches) * (d / kInches));
  const double source_at_d = p.color.r / (p.constant + p.linear * d + p.quadratic * d * d);
  EXPECT_NEAR(source_at_d / gltf_at_d, 1.0, 1e-5);
  EXPECT_FLOAT_EQ(p.color.g / p.color.r, 0.5f);
  EXPECT_FLOAT_EQ(p.range, float(3.0 * kInches));
  const Light& spot = s.lights[1];
  EXPECT_EQ(spot.type, LightType::spot);
  EXPECT_FLOAT_EQ(spot.inner_cone, 0.2f);
  EXPECT_FLOAT_EQ(spot.outer_cone, 0.6f);
  expect_near(spot.direction, glm::vec3(0, 1, 0), 1e-6f, "spot direction (glTF -Z = Source +Y)");
  const Light& sun = s.lights[2];
  EXPECT_EQ(sun.type, LightType::directional);
  EXPECT_EQ(sun.color, glm::vec3(3.0f));
  expect_near(sun.direction, glm::vec3(0, 0, -1), 1e-6f, "sun direction");
}

TEST(GltfImport, CamerasFirstByDefaultOrAsAsked) {
  TempDir dir;
  GltfBuilder b;
  b.doc["cameras"] = {{{"type", "perspective"}, {"name", "wide"}, {"perspective", {{"yfov", 1.2}, {"znear", 0.1}, {"zfar", 100.0}, {"aspectRatio", 1.5}}}},
                      {{"type", "orthographic"}, {"name", "plan"}, {"orthographic", {{"xmag", 4.0}, {"ymag", 2.0}, {"znear", 0.5}, {"zfar", 50.0}}}}};
  b.add_node({{"camera", 0}, {"translation", {0, 1, 5}}});
  b.add_node({{"camera", 1}, {"translation", {0, 10, 0}}, {"rotation", {-std::sin(M_PI / 4), 0, 0, std::cos(M_PI / 4)}}});
  const std::string path = b.write(dir);
  const Scene first = load_gltf(path, no_defaults());
  ASSERT_EQ(first.cameras.size(), 2u);
  const Camera& c = first.cameras[0];
  EXPECT_EQ(c.name, "wide");
  EXPECT_EQ(c.projection, Projection::perspective);
  expect_near(c.position, source_inches(0, 1, 5), 1e-4f, "position");
  // Looking down glTF -Z = Source +Y.
  expect_near(glm::normalize(c.target - c.position), glm::vec3(0, 1, 0), 1e-6f, "forward");
  expect_near(c.up, glm::vec3(0, 0, 1), 1e-6f, "up");
  EXPECT_FLOAT_EQ(c.vertical_fov, 1.2f);
  EXPECT_FLOAT_EQ(c.aspect, 1.5f);
  EXPECT_NEAR(c.near_plane, 0.1 * kInches, 1e-4);
  EXPECT_NEAR(c.far_plane, 100 * kInches, 1e-2);
  GltfImportOptions o = no_defaults();
  o.camera = 1;
  const Scene second = load_gltf(path, o);
  const Camera& plan = second.cameras[0];
  EXPECT_EQ(plan.name, "plan");
  EXPECT_EQ(plan.projection, Projection::orthographic);
  EXPECT_NEAR(plan.ortho_height, 4.0 * kInches, 1e-3);  // 2 x ymag
  EXPECT_FLOAT_EQ(plan.aspect, 2.0f);
  expect_near(glm::normalize(plan.target - plan.position), glm::vec3(0, 0, -1), 1e-6f, "looks down");
  EXPECT_EQ(second.cameras[1].name, "wide");
  o.camera = 2;
  expect_gltf_error(path, "camera 2 asked for; the file has 2", [&] { load_gltf(path, o); });
}

// Without cameras or lights: a camera whose frame (at the default 16:9) holds the whole bounding
// box, and lights. tests/scenes/framing_test.cpp checks the framing rule itself.
TEST(GltfImport, DefaultCameraFramesTheBoundsAndDefaultLightsShowThem) {
  TempDir dir;
  GltfBuilder b;
  const int pos = b.add_positions({-3, 0, 1, 5, 2, -1, 0, 4, 0});
  b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}})}});
  const Scene s = load_gltf(b.write(dir));
  ASSERT_EQ(s.cameras.size(), 1u);
  const Camera& c = s.cameras[0];
  const Bounds bounds = bounds_of(s);
  const glm::vec3 forward = glm::normalize(c.target - c.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, c.up)), up = glm::cross(right, forward);
  const float tan_y = std::tan(0.5f * c.vertical_fov), tan_x = GltfImportOptions{}.framing_aspect * tan_y;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x, (corner & 2) ? bounds.max.y : bounds.min.y,
                      (corner & 4) ? bounds.max.z : bounds.min.z);
    const glm::vec3 to = p - c.position;
    const float depth = glm::dot(to, forward);
    EXPECT_LT(std::abs(glm::dot(to, right)) / depth, tan_x) << "corner " << corner;
    EXPECT_LT(std::abs(glm::dot(to, up)) / depth, tan_y) << "corner " << corner;
    EXPECT_GT(depth, c.near_plane);
    EXPECT_LT(depth, c.far_plane);
  }
  ASSERT_EQ(s.lights.size(), 2u);
  // The key light reaches the side the camera sees: it travels away from the camera's side.
  EXPECT_GT(glm::dot(s.lights[0].direction, forward), 0.0f);
  // With a light in the file, none is added.
  b.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}}}}}}};
  b.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  EXPECT_EQ(load_gltf(b.write(dir, "lit.gltf")).lights.size(), 1u);
}

TEST(GltfImport, TranslationAnimationsMoveModels) {
  // A parent node scaled x2 holding an animated child with a mesh: the child's translation goes
  // from its rest (1, 0, 0) m to (1, 2, -3) m and back; its change, through the parent's scale and
  // glTF's axes (x, y, z) m -> (x, -z, y) inches, is the model's path.
  for (const char* interpolation : {"LINEAR", "CUBICSPLINE"}) {
    TempDir dir;
    GltfBuilder b;
    const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int child = b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}})}, {"translation", {1, 0, 0}}}, false);
    b.add_node({{"children", {child}}, {"scale", {2, 2, 2}}});
    const bool cubic = std::string(interpolation) == "CUBICSPLINE";
    std::vector<float> values;
    for (glm::vec3 v : {glm::vec3(1, 0, 0), glm::vec3(1, 2, -3), glm::vec3(1, 0, 0)}) {
      if (cubic) values.insert(values.end(), {9, 9, 9});  // in-tangent, ignored
      values.insert(values.end(), {v.x, v.y, v.z});
      if (cubic) values.insert(values.end(), {9, 9, 9});  // out-tangent, ignored
    }
    const int times = b.add_floats({0.5f, 2.0f, 4.0f}, "SCALAR", 1);
    const int translations = b.add_floats(values, "VEC3", 3);
    b.doc["animations"] = json::array(
        {{{"channels", json::array({{{"sampler", 0}, {"target", {{"node", child}, {"path", "translation"}}}}})},
          {"samplers", json::array({{{"input", times}, {"output", translations}, {"interpolation", interpolation}}})}}});
    const Scene s = load_gltf(b.write(dir, "walk.gltf"));
    ASSERT_EQ(s.models.size(), 1u);
    const std::vector<ModelKey>& path = s.models[0].path;
    ASSERT_EQ(path.size(), 3u) << interpolation;
    const float parent_scale = 2.0f / 0.0254f;  // inches per meter
    EXPECT_EQ(path[0].time, 0.5f);
    EXPECT_EQ(path[2].time, 4.0f);
    expect_near(path[0].offset, glm::vec3(0.0f), 1e-4f, "rest");
    expect_near(path[1].offset, glm::vec3(0.0f, 3.0f * parent_scale, 2.0f * parent_scale), 1e-2f, "moved");
    expect_near(path[2].offset, glm::vec3(0.0f), 1e-4f, "back");
  }
  // A channel whose times go back is one line naming it.
  TempDir dir;
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const int node = b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}})}});
  const int times = b.add_floats({1.0f, 0.5f}, "SCALAR", 1);
  const int translations = b.add_floats({0, 0, 0, 1, 1, 1}, "VEC3", 3);
  b.doc["animations"] = json::array(
      {{{"channels", json::array({{{"sampler", 0}, {"target", {{"node", node}, {"path", "translation"}}}}})},
        {"samplers", json::array({{{"input", times}, {"output", translations}}})}}});
  const std::string path = b.write(dir, "back.gltf");
  expect_gltf_error(path, "animation 0 channel 0 key 1 is not finite or not later", [&] { load_gltf(path); });
}

}  // namespace
}  // namespace luxel::scenes::test
