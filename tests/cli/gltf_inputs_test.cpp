// glTF files as users bring them, through `luxel render`: a file with nothing to draw, a schema
// error and an unread required extension are one line naming the file and exit 1, without an
// image; a wrong-typed optional value is one warning line, and the image is written.

#include "cli/run_luxel.hpp"
#include "scenes/gltf_support.hpp"

#include <gtest/gtest.h>

namespace luxel::cli::test {
namespace {

using scenes::test::GltfBuilder;
using scenes::test::TempDir;

GltfBuilder cli_triangle() {
  GltfBuilder b;
  const int pos = b.add_positions({-1, -1, 0, 1, -1, 0, 0, 1, 0});
  b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}})}});
  return b;
}

/// `luxel render` of `scene` into `image` at 32x24, stderr captured (stdout dropped).
Process render_gltf(const std::string& scene, const std::string& image) {
  return run_luxel("render --scene '" + scene + "' --width 32 --height 24 --out '" + image + "' 2>&1 >/dev/null");
}

/// The lines of `s` that are warnings.
size_t warning_lines(const std::string& s) {
  size_t n = 0;
  for (size_t at = s.find(": warning: "); at != std::string::npos; at = s.find(": warning: ", at + 1)) ++n;
  return n;
}

TEST(GltfInputs, NothingToDrawIsOneLineAndExitOne) {
  TempDir dir;
  GltfBuilder b;
  b.add_node({{"name", "empty"}});
  const std::string scene = b.write(dir, "nothing.gltf"), image = dir.file("never.png");
  const Process p = render_gltf(scene, image);
  EXPECT_EQ(p.exit_code, 1);
  EXPECT_EQ(p.out, "luxel render: " + scene + ": nothing to draw: its scene places no triangles\n");
  EXPECT_FALSE(std::filesystem::exists(image));
}

TEST(GltfInputs, ASchemaErrorIsOneLineNamingThePath) {
  TempDir dir;
  GltfBuilder b = cli_triangle();
  b.doc["meshes"][0]["primitives"] = b.doc["meshes"][0]["primitives"][0];
  const std::string scene = b.write(dir, "object-primitives.gltf"), image = dir.file("never.png");
  const Process p = render_gltf(scene, image);
  EXPECT_EQ(p.exit_code, 1);
  EXPECT_EQ(p.out, "luxel render: " + scene + ": meshes[0].primitives is an object, not an array\n");
  EXPECT_FALSE(std::filesystem::exists(image));

  GltfBuilder s = cli_triangle();
  s.doc["scene"] = 1;
  const std::string missing = s.write(dir, "missing-scene.gltf");
  const Process q = render_gltf(missing, image);
  EXPECT_EQ(q.exit_code, 1);
  EXPECT_EQ(q.out, "luxel render: " + missing + ": scene names scenes[1], which does not exist (the file has 1)\n");
}

TEST(GltfInputs, AnUnreadRequiredExtensionIsOneLine) {
  TempDir dir;
  GltfBuilder b = cli_triangle();
  b.doc["extensionsUsed"] = b.doc["extensionsRequired"] = {"KHR_texture_basisu"};
  const std::string scene = b.write(dir, "basisu.gltf"), image = dir.file("never.png");
  const Process p = render_gltf(scene, image);
  EXPECT_EQ(p.exit_code, 1);
  EXPECT_EQ(p.out, "luxel render: " + scene + ": requires extension KHR_texture_basisu, which luxel does not read\n");
}

TEST(GltfInputs, AWrongTypedOptionalValueWarnsAndRenders) {
  TempDir dir;
  GltfBuilder b = cli_triangle();
  b.doc["materials"] = {{{"pbrMetallicRoughness", {{"roughnessFactor", "rough"}}}}};
  b.doc["meshes"][0]["primitives"][0]["material"] = 0;
  b.doc["extensionsUsed"] = {"KHR_materials_sheen"};
  const std::string scene = b.write(dir, "typo.gltf"), image = dir.file("typo.png");
  const Process p = render_gltf(scene, image);
  EXPECT_EQ(p.exit_code, 0) << p.out;
  EXPECT_EQ(warning_lines(p.out), 2u) << p.out;
  EXPECT_NE(p.out.find("luxel render: warning: " + scene +
                       ": materials[0].pbrMetallicRoughness.roughnessFactor is a string (\"rough\"), not a number; 1 is used\n"),
            std::string::npos)
      << p.out;
  EXPECT_NE(p.out.find("luxel render: warning: " + scene + ": uses extension KHR_materials_sheen, which luxel does not read; drawn without it\n"),
            std::string::npos)
      << p.out;
  EXPECT_TRUE(std::filesystem::exists(image));
}

}  // namespace
}  // namespace luxel::cli::test
