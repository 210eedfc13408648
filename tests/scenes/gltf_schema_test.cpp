// Files that break the glTF schema where luxel reads it: what would lose geometry, a material, a
// texture or a node is refused in one line naming the JSON path; a wrong-typed or out-of-range
// optional value is one warning naming the path and the value used, and the file loads.
// Extensions: required and not read refuses, used and not read warns.

#include "gltf_support.hpp"

#include <filesystem>

namespace luxel::scenes::test {
namespace {

/// One triangle under one root node, with a material (0) of its own.
GltfBuilder schema_triangle() {
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  b.doc["materials"] = json::array({json::object()});
  b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}}, -1, -1, 0)}});
  return b;
}

/// Loads `path`, expecting it to load; returns the warnings it gave.
std::vector<std::string> schema_warnings(const std::string& path, Scene* out = nullptr) {
  std::vector<std::string> warnings;
  GltfImportOptions options = no_defaults();
  options.warn = [&](const std::string& line) { warnings.push_back(line); };
  Scene scene = load_gltf(path, options);
  if (out) *out = std::move(scene);
  for (const std::string& w : warnings) {
    EXPECT_EQ(w.rfind(path + ": ", 0), 0u) << w;
    EXPECT_EQ(w.find('\n'), std::string::npos) << w;
  }
  return warnings;
}

TEST(GltfSchema, PrimitivesThatAreNotAnArrayAreRefused) {
  TempDir dir;
  GltfBuilder b = schema_triangle();
  b.doc["meshes"][0]["primitives"] = b.doc["meshes"][0]["primitives"][0];  // an object, not [object]
  const std::string path = b.write(dir);
  expect_gltf_error(path, "meshes[0].primitives is an object, not an array", [&] { load_gltf(path); });
  b.doc["meshes"][0].erase("primitives");
  const std::string none = b.write(dir, "none.gltf");
  expect_gltf_error(none, "meshes[0] has no primitives", [&] { load_gltf(none); });
}

TEST(GltfSchema, ASceneThatDoesNotExistIsRefused) {
  TempDir dir;
  GltfBuilder b = schema_triangle();
  b.doc["scene"] = 3;
  const std::string path = b.write(dir);
  expect_gltf_error(path, "scene names scenes[3], which does not exist (the file has 1)", [&] { load_gltf(path); });
  b.doc.erase("scenes");
  b.doc["scene"] = 0;
  const std::string no_scenes = b.write(dir, "no-scenes.gltf");
  expect_gltf_error(no_scenes, "scene names scenes[0], which does not exist (the file has 0)", [&] { load_gltf(no_scenes); });
}

TEST(GltfSchema, WrongTypedAndDanglingIndicesAreRefused) {
  TempDir dir;
  struct Case { const char* name; std::function<void(json&)> edit; const char* problem; };
  const Case cases[] = {
      {"mesh-string", [](json& d) { d["nodes"][0]["mesh"] = "0"; }, "nodes[0].mesh is a string (\"0\"), not an index"},
      {"mesh-fraction", [](json& d) { d["nodes"][0]["mesh"] = 0.5; }, "nodes[0].mesh is a fractional number (0.5), not an index"},
      {"mesh-dangling", [](json& d) { d["nodes"][0]["mesh"] = 4; }, "nodes[0].mesh names meshes[4], which does not exist (the file has 1)"},
      {"scene-nodes", [](json& d) { d["scenes"][0]["nodes"] = 0; }, "scenes[0].nodes is a number, not an array"},
      {"child", [](json& d) { d["nodes"][0]["children"] = {7}; }, "nodes[0].children[0] names nodes[7], which does not exist"},
      {"material", [](json& d) { d["meshes"][0]["primitives"][0]["material"] = 2; },
       "meshes[0].primitives[0].material names materials[2], which does not exist (the file has 1)"},
      {"attribute", [](json& d) { d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = "0"; },
       "meshes[0].primitives[0].attributes.POSITION is a string (\"0\"), not an index"},
      {"attributes", [](json& d) { d["meshes"][0]["primitives"][0]["attributes"] = json::array(); },
       "meshes[0].primitives[0].attributes is an array, not an object"},
      {"texture", [](json& d) { d["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", "0"}}}}; },
       "materials[0].pbrMetallicRoughness.baseColorTexture.index is a string (\"0\"), not an index"},
      {"pbr", [](json& d) { d["materials"][0]["pbrMetallicRoughness"] = json::array(); },
       "materials[0].pbrMetallicRoughness is an array, not an object"},
      {"nodes-object", [](json& d) { d["nodes"] = d["nodes"][0]; }, "nodes is an object, not an array"},
      {"material-number", [](json& d) { d["materials"][0] = 1; }, "materials[0] is a number, not an object"},
      {"accessor-count", [](json& d) { d["accessors"][0]["count"] = "3"; }, "accessors[0].count is a string (\"3\"), not an integer"},
      {"view-buffer", [](json& d) { d["bufferViews"][0]["buffer"] = 1; }, "bufferViews[0].buffer names buffers[1], which does not exist"},
      {"required-list", [](json& d) { d["extensionsRequired"] = "KHR_draco_mesh_compression"; },
       "extensionsRequired is a string, not an array"},
  };
  for (const Case& c : cases) {
    GltfBuilder b = schema_triangle();
    json doc = json::parse(b.text());
    c.edit(doc);
    const std::string path = dir.file(std::string(c.name) + ".gltf");
    write_text(path, doc.dump());
    SCOPED_TRACE(c.name);
    expect_gltf_error(path, c.problem, [&] { load_gltf(path); });
  }
}

TEST(GltfSchema, WrongTypedOptionalValuesWarnAndTheDefaultIsUsed) {
  TempDir dir;
  std::filesystem::copy_file(asset("box-textured/glTF/CesiumLogoFlat.png"), dir.file("logo.png"));
  GltfBuilder b = schema_triangle();
  b.doc["images"] = {{{"uri", "logo.png"}}};
  b.doc["textures"] = {{{"source", 0}}};
  b.doc["materials"][0] = {{"normalTexture", {{"index", 0}, {"scale", "2"}}},
                           {"pbrMetallicRoughness", {{"roughnessFactor", 3.0}, {"metallicFactor", "shiny"}, {"baseColorFactor", "red"}}},
                           {"doubleSided", 1}};
  b.doc["nodes"][0]["translation"] = "up";
  const std::string path = b.write(dir);
  Scene scene;
  const std::vector<std::string> warnings = schema_warnings(path, &scene);
  const std::vector<std::string> expected = {
      path + ": nodes[0].translation is a string (\"up\"), not 3 numbers; [0, 0, 0] is used",
      path + ": materials[0].pbrMetallicRoughness.baseColorFactor is a string (\"red\"), not 4 numbers; [1, 1, 1, 1] is used",
      path + ": materials[0].pbrMetallicRoughness.metallicFactor is a string (\"shiny\"), not a number; 1 is used",
      path + ": materials[0].pbrMetallicRoughness.roughnessFactor is 3, outside [0, 1]; 1 is used",
      path + ": materials[0].normalTexture.scale is a string (\"2\"), not a number; 1 is used",
      path + ": materials[0].doubleSided is a number (1), not a boolean; false is used",
  };
  EXPECT_EQ(warnings, expected);
  // The defaults named are the ones read: the triangle is where it was, the material as stated.
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].positions[1], source_inches(1, 0, 0));
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].color, glm::vec4(1.0f));
  EXPECT_FALSE(scene.materials[0].double_sided);
  EXPECT_FALSE(scene.materials[0].phong);  // roughness 1: no highlight
  EXPECT_TRUE(scene.materials[0].bump.bound());
}

TEST(GltfSchema, AValidFileGivesNoWarning) {
  TempDir dir;
  GltfBuilder b = schema_triangle();
  b.doc["materials"][0] = {{"pbrMetallicRoughness", {{"roughnessFactor", 0.5}, {"baseColorFactor", {1, 0.5, 0.25, 1}}}}};
  EXPECT_TRUE(schema_warnings(b.write(dir)).empty());
  EXPECT_TRUE(schema_warnings(asset("box-textured/glTF-Binary/BoxTextured.glb")).empty());
}

TEST(GltfSchema, ExtensionsRequiredAndNotReadRefuseUsedOnesWarn) {
  TempDir dir;
  GltfBuilder b = schema_triangle();
  b.doc["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_texture_transform"};
  const std::string used = b.write(dir, "used.gltf");
  EXPECT_EQ(schema_warnings(used),
            std::vector<std::string>{used + ": uses extension KHR_materials_clearcoat, which luxel does not read; drawn without it"});
  b.doc["extensionsRequired"] = {"KHR_materials_clearcoat"};
  const std::string required = b.write(dir, "required.gltf");
  expect_gltf_error(required, "requires extension KHR_materials_clearcoat, which luxel does not read", [&] { load_gltf(required); });
  // What luxel reads, it may be required to read.
  b.doc["extensionsUsed"] = b.doc["extensionsRequired"] = {"KHR_texture_transform", "KHR_materials_unlit"};
  EXPECT_TRUE(schema_warnings(b.write(dir, "read.gltf")).empty());
}

}  // namespace
}  // namespace luxel::scenes::test
