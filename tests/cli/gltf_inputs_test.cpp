// glTF files as users bring them, through `luxel render`: a file with nothing to draw, a schema
// error and an unread required extension are one line naming the file and exit 1, without an
// image; a wrong-typed optional value is one warning line, and the image is written.

#include "cli/run_luxel.hpp"
#include "scenes/gltf_support.hpp"

#include "luxel/scenes/image_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

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

/// How far one 8-bit image is from another, over R, G and B: PSNR (dB, peak 255), the largest
/// difference (of 255) and the share of pixels differing by more than 8.
struct ImageDistance { double psnr = 0, max_error = 0, pixels_over_8 = 0; };
ImageDistance image_distance(const std::string& a_path, const std::string& b_path) {
  const scenes::PixelImage a = scenes::read_image(a_path), b = scenes::read_image(b_path);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  ImageDistance d;
  double squared = 0;
  size_t over = 0;
  const size_t pixels = size_t(a.width) * size_t(a.height);
  for (size_t p = 0; p < pixels && a.rgba8.size() == b.rgba8.size(); ++p) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      const int e = std::abs(int(a.rgba8[4 * p + c]) - int(b.rgba8[4 * p + c]));
      squared += double(e) * e;
      worst = std::max(worst, e);
    }
    d.max_error = std::max(d.max_error, double(worst));
    over += worst > 8;
  }
  const double mse = squared / double(3 * pixels);
  d.psnr = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : INFINITY;
  d.pixels_over_8 = double(over) / double(pixels);
  return d;
}

// A compressed file renders the image of its uncompressed original, within what quantization
// moves: 14-bit positions move triangle edges by up to 0.0012 inches, which flips the coverage of a
// few edge samples (the largest single differences), and UVs move by a few 1/4095 steps. The
// PSNR falls as the box fills more of the frame (more edge pixels); the share of pixels off by
// more than 8 steps is the bound that says the image is the same.
TEST(GltfInputs, CompressedFilesRenderTheirOriginalsImage) {
  TempDir dir;
  const std::string data = luxel::test::data_dir() + "/gltf/box-textured/";
  auto render = [&](const std::string& file, const std::string& name) {
    const std::string image = dir.file(name + ".png");
    const Process p = run_luxel("render --scene '" + data + file + "' --width 160 --height 120 --out '" + image + "' 2>&1 >/dev/null");
    EXPECT_EQ(p.exit_code, 0) << p.out;
    EXPECT_EQ(p.out.find("warning"), std::string::npos) << p.out;
    return image;
  };
  const std::string original = render("glTF-Binary/BoxTextured.glb", "original");
  struct Compressed { const char* file; const char* name; double min_psnr, max_share_over_8; };
  for (const Compressed& c : {Compressed{"glTF-meshopt/BoxTextured.glb", "meshopt", 41.0, 0.005},
                              Compressed{"glTF-Draco/BoxTextured.glb", "draco", 39.0, 0.005}}) {
    const ImageDistance d = image_distance(original, render(c.file, c.name));
    std::printf("%s vs original, 160x120: PSNR %.1f dB, max error %.0f/255, %.2f%% of pixels over 8/255\n", c.name, d.psnr,
                d.max_error, 100.0 * d.pixels_over_8);
    RecordProperty(std::string(c.name) + "_psnr_db", std::to_string(d.psnr));
    RecordProperty(std::string(c.name) + "_max_error", std::to_string(d.max_error));
    EXPECT_GE(d.psnr, c.min_psnr) << c.name;
    EXPECT_LE(d.pixels_over_8, c.max_share_over_8) << c.name;
  }
}

}  // namespace
}  // namespace luxel::cli::test
