// NaN and infinity in every numeric field of a glTF scene, loaded and rendered.
//
// A small valid scene (a textured, lit quad; a perspective and an orthographic camera; point, spot
// and directional lights; a texture transform, a sampler, accessor bounds, the scene's Source
// extras: background, fog, exposure) is written once as it is, then once per numeric leaf of its
// JSON with that value replaced by 1e300 and by -1e300. JSON has no NaN nor infinity, and the JSON
// reader refuses 1e999 (checked below); 1e300 is a finite double that becomes +-infinity where
// luxel keeps it as a float, and what is computed from it (inf - inf, 0 x inf) NaN. NaN itself
// gets in through the binary buffers: each float of every vertex attribute is replaced by NaN,
// +inf and -inf in its turn.
//
// Each variant must either be refused, load_gltf or the Renderer throwing one line that names the
// file (GltfError "FILE: ...", or the renderer's "FILE: ..." for a scene it cannot draw), or render
// a sensible frame. Sensible here: the renderer writes NaN as 0 (rasterizer::pack_rgba8), and the
// unmodified scene has no pixel whose color is 0 (its background is a blue-grey, its quad is lit
// and emissive), so a rendered variant may have no pixel whose rgb is (0, 0, 0): such a pixel is a
// NaN or a -infinity that reached a shader. (A variant may legitimately change the frame
// otherwise: an infinite light range is glTF's "no range", a camera turned away sees only the
// background...)

#include "frame_support.hpp"
#include "scenes/gltf_support.hpp"

#include "luxel/rasterizer/context.hpp"
#include "luxel/scenes/image_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace luxel::frame {
namespace {

using scenes::test::json;
using scenes::test::TempDir;

/// Stands for the value being replaced while the JSON is dumped; the text is put in afterwards.
constexpr const char* kPlaceholder = "@non-finite@";

/// The buffer: a unit quad (positions, normals, uv0, tangents, colors) and its six indices.
struct QuadBuffer {
  std::vector<float> positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  std::vector<float> uvs = {0, 1, 1, 1, 1, 0, 0, 0};
  std::vector<float> tangents = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
  std::vector<float> colors = {1, 1, 1, 1, 0.8f, 0.9f, 1, 1, 1, 0.7f, 0.9f, 1, 0.9f, 1, 1, 1};
  std::vector<uint16_t> indices = {0, 1, 2, 0, 2, 3};

  /// Every attribute array, named as glTF names it.
  std::vector<std::pair<const char*, std::vector<float>*>> attributes() {
    return {{"POSITION", &positions}, {"NORMAL", &normals}, {"TEXCOORD_0", &uvs}, {"TANGENT", &tangents}, {"COLOR_0", &colors}};
  }
};

/// A 2x2 RGBA PNG as a data URI.
std::string png_data_uri() {
  scenes::PixelImage image;
  image.width = image.height = 2;
  image.rgba8 = {255, 200, 150, 255, 100, 150, 200, 255, 200, 255, 100, 255, 150, 150, 150, 255};
  return "data:image/png;base64," + scenes::test::base64(scenes::encode_png(image, "checker"));
}

/// The scene's glTF with the buffer's bytes.
json scene_json(QuadBuffer& q) {
  scenes::test::GltfBuilder b;
  const int pos = b.add_positions(q.positions);
  b.doc["accessors"][size_t(pos)]["min"] = {-1, -1, 0};
  b.doc["accessors"][size_t(pos)]["max"] = {1, 1, 0};
  json attributes = {{"POSITION", pos}, {"NORMAL", b.add_floats(q.normals, "VEC3", 3)}, {"TEXCOORD_0", b.add_floats(q.uvs, "VEC2", 2)},
                     {"TANGENT", b.add_floats(q.tangents, "VEC4", 4)}, {"COLOR_0", b.add_floats(q.colors, "VEC4", 4)}};
  const int indices = b.add_accessor(q.indices, 5123, "SCALAR", 1);
  b.doc["images"] = {{{"uri", png_data_uri()}}};
  b.doc["samplers"] = {{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 33071}}};
  b.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
  b.doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_lights_punctual", "KHR_materials_emissive_strength"};
  b.doc["materials"] = {
      {{"pbrMetallicRoughness",
        {{"baseColorFactor", {0.8, 0.7, 0.6, 1.0}},
         {"metallicFactor", 0.5},
         {"roughnessFactor", 0.3},
         {"baseColorTexture",
          {{"index", 0}, {"texCoord", 0},
           {"extensions", {{"KHR_texture_transform", {{"offset", {0.1, 0.2}}, {"rotation", 0.3}, {"scale", {2.0, 2.0}}}}}}}}}},
       {"emissiveFactor", {0.02, 0.02, 0.02}},
       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}}},
       {"alphaMode", "MASK"},
       {"alphaCutoff", 0.25},
       {"extras", {{"luxel", {{"phongexponent", 20}, {"phongboost", 1.5}, {"rimlightexponent", 4}, {"envmaptint", {0.2, 0.2, 0.2}}}}}}}};
  b.add_node({{"mesh", b.add_mesh(attributes, indices, -1, 0)},
              {"translation", {0.0, 0.0, -0.5}},
              {"rotation", {0.0, 0.0, 0.0, 1.0}},
              {"scale", {1.0, 1.0, 1.0}}});
  b.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}, {"zfar", 100.0}, {"aspectRatio", 1.5}}}},
                      {{"type", "orthographic"}, {"orthographic", {{"xmag", 1.5}, {"ymag", 1.0}, {"znear", 0.1}, {"zfar", 50.0}}}}};
  b.add_node({{"camera", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 3, 1}}});
  b.add_node({{"camera", 1}, {"translation", {0.0, 0.0, 4.0}}});
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"color", {1.0, 0.9, 0.8}}, {"intensity", 0.5}, {"range", 50.0}},
      {{"type", "spot"}, {"color", {0.8, 0.9, 1.0}}, {"intensity", 0.5}, {"range", 40.0},
       {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.7}}}},
      {{"type", "directional"}, {"color", {1.0, 1.0, 1.0}}, {"intensity", 0.2}}};
  b.add_node({{"translation", {0.5, 0.5, 1.5}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  b.add_node({{"translation", {-0.5, 0.0, 2.0}}, {"rotation", {0.0, 0.0, 0.0, 1.0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  b.add_node({{"rotation", {-0.3826834, 0.0, 0.0, 0.9238795}}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
  b.doc["scenes"][0]["extras"]["luxel"] = {
      {"background", {0.2, 0.3, 0.4}},
      {"fog", {{"mode", "range"}, {"color", {0.5, 0.5, 0.6}}, {"start", 10.0}, {"end", 400.0}, {"maxdensity", 0.5}}},
      {"exposure", {{"minscale", 1.0}, {"maxscale", 1.0}, {"rate", 1.0}, {"percenttarget", 60.0}, {"percentbright", 2.0}, {"bloomscale", 0.5}}}};
  json d = json::parse(b.text());
  return d;
}

/// The JSON pointers of every number in `j` (arrays and objects walked; the base64 data is text).
void numeric_leaves(const json& j, const std::string& at, std::vector<std::string>& out) {
  if (j.is_number()) out.push_back(at);
  if (j.is_array())
    for (size_t i = 0; i < j.size(); ++i) numeric_leaves(j[i], at + "/" + std::to_string(i), out);
  if (j.is_object())
    for (const auto& [key, value] : j.items()) numeric_leaves(value, at + "/" + key, out);
}

/// `d` with the number at `pointer` written as `text`.
std::string with_number(json d, const std::string& pointer, const std::string& text) {
  d[json::json_pointer(pointer)] = kPlaceholder;
  std::string s = d.dump();
  const std::string quoted = std::string("\"") + kPlaceholder + "\"";
  s.replace(s.find(quoted), quoted.size(), text);
  return s;
}

/// What happened to one variant: "" when it was refused properly or rendered sensibly, else why not.
std::string judge(const std::string& path) {
  scenes::Scene scene;
  try {
    scene = scenes::load_gltf(path);
  } catch (const scenes::GltfError& e) {
    const std::string m = e.what();
    if (m.rfind(path + ": ", 0) != 0 || m.find('\n') != std::string::npos) return "refused with a bad message: " + m;
    return "";
  }

  FrameSettings settings;
  // No bloom: its blur would spread light over a black pixel (HdrThroughThePostPasses covers it).
  settings.width = 48, settings.height = 32, settings.samples = 1;
  try {
    const rasterizer::Image image = render_frame(scene, settings);
    for (size_t p = 0; p < image.rgba.size(); p += 4)
      if (image.rgba[p] == 0 && image.rgba[p + 1] == 0 && image.rgba[p + 2] == 0)
        return "rendered a black pixel (" + std::to_string(p / 4 % 48) + ", " + std::to_string(p / 4 / 48) + ")";
  } catch (const std::exception& e) {
    const std::string m = e.what();
    if (m.rfind(path + ": ", 0) != 0 || m.find('\n') != std::string::npos) return "the renderer refused it with: " + m;
  }
  return "";
}

TEST(NonFiniteScene, JsonCannotSayInfinity) {
  TempDir dir;
  QuadBuffer q;
  const json d = scene_json(q);
  const std::string path = dir.file("huge-intensity.gltf");
  scenes::test::write_text(path, with_number(d, "/extensions/KHR_lights_punctual/lights/2/intensity", "1e999"));
  scenes::test::expect_gltf_error(path, "malformed JSON: number overflow parsing '1e999'", [&] { scenes::load_gltf(path); });
}

TEST(NonFiniteScene, TheSceneAsWrittenRendersWithoutBlackPixels) {
  TempDir dir;
  QuadBuffer q;
  const std::string path = dir.file("scene.gltf");
  scenes::test::write_text(path, scene_json(q).dump());
  EXPECT_EQ(judge(path), "");
}

TEST(NonFiniteScene, EveryNumericFieldBeyondFloat) {
  TempDir dir;
  QuadBuffer q;
  const json d = scene_json(q);
  std::vector<std::string> leaves;
  numeric_leaves(d, "", leaves);
  ASSERT_GT(leaves.size(), 100u);
  for (const std::string& leaf : leaves) {
    // Sanitizer builds take the positive value only (each variant costs 25 ms there, not 1).
    for (const char* text : {"1e300", "-1e300"}) {
      if (kReduced && text[0] == '-') continue;
      const std::string path = dir.file("variant.gltf");
      scenes::test::write_text(path, with_number(d, leaf, text));
      const std::string problem = judge(path);
      EXPECT_EQ(problem, "") << leaf << " = " << text;
    }
  }
}

TEST(NonFiniteScene, EveryVertexAttributeFloatAsNanAndInfinity) {
  TempDir dir;
  const float values[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()};
  QuadBuffer clean;
  for (const auto& [name, array] : clean.attributes()) {
    for (size_t i = 0; i < array->size(); ++i) {
      for (float v : values) {
        if (kReduced && !std::isnan(v)) continue;  // sanitizer builds: NaN only
        QuadBuffer q;
        for (auto& [other, values_of] : q.attributes())
          if (std::string(other) == name) (*values_of)[i] = v;
        const std::string path = dir.file("variant.gltf");
        scenes::test::write_text(path, scene_json(q).dump());
        EXPECT_EQ(judge(path), "") << name << " float " << i << " = " << v;
      }
    }
  }
}

}  // namespace
}  // namespace luxel::frame
