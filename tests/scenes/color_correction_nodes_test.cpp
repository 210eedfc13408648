// Color-correction nodes with their fades and inputs, and color-correction volumes: what validate
// refuses, and their round trip through the glTF scene's extras (old files still load).

#include "gltf_support.hpp"

#include "luxel/scenes/gltf.hpp"
#include "luxel/scenes/scene.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace luxel::scenes::test {
namespace {

using Kind = ColorCorrectionInput::Kind;

Scene corrected() {
  Scene s;
  s.name = "corrected";
  ColorCorrection node;
  node.lut = "builtin:warm";
  node.position = {10, -20, 30};
  node.min_falloff = 64, node.max_falloff = 256, node.max_weight = 0.75f;
  node.fade_in = 3.0f, node.fade_out = 1.5f, node.start_disabled = true;
  node.inputs = {{1.0f, Kind::enable}, {2.25f, Kind::disable}, {2.25f, Kind::enable}};
  ColorCorrection global;  // no falloff (-1), no fades, no inputs
  global.lut = "grades/night.cube";
  global.min_falloff = global.max_falloff = -1;
  s.color_corrections = {node, global};
  s.color_correction_volumes = {{"builtin:cool", {-100, -50, 0}, {100, 50, 80}, 2.0f}, {"builtin:archival", {0, 0, 0}, {0, 0, 0}, 0.0f}};
  return s;
}

TEST(ColorCorrectionNodes, ValidateAcceptsNodesAndVolumes) { EXPECT_NO_THROW(validate(corrected())); }

TEST(ColorCorrectionNodes, ValidateRefusesBadValues) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  auto refused = [](const Scene& s, const std::string& part) {
    try {
      validate(s);
      ADD_FAILURE() << "accepted; expected '" << part << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  Scene s = corrected();
  s.color_corrections[0].fade_in = -1.0f;
  refused(s, "color correction 0 has a weight or fade that is negative or not finite");
  s = corrected();
  s.color_corrections[1].fade_out = nan;
  refused(s, "color correction 1 has a weight or fade");
  s = corrected();
  s.color_corrections[0].max_weight = inf;
  refused(s, "color correction 0 has a weight or fade");
  s = corrected();
  s.color_corrections[0].min_falloff = -2.0f;
  refused(s, "color correction 0 has a falloff");
  s = corrected();
  s.color_corrections[0].position.y = nan;
  refused(s, "color correction 0 has a position");
  s = corrected();
  s.color_corrections[0].inputs[1].time = 0.5f;  // before the enable at 1
  refused(s, "color correction 0 input 1 has a time that is not finite or earlier than the one before");
  s = corrected();
  s.color_corrections[0].inputs[0].time = nan;
  refused(s, "color correction 0 input 0");
  s = corrected();
  s.color_corrections[1].lut.clear();
  refused(s, "color correction 1 has no LUT");
  s = corrected();
  s.color_correction_volumes[0].min.z = 81.0f;  // above max.z
  refused(s, "color correction volume 0 has bounds that are not finite or not ordered");
  s = corrected();
  s.color_correction_volumes[1].max.x = inf;
  refused(s, "color correction volume 1 has bounds");
  s = corrected();
  s.color_correction_volumes[1].fade_duration = -0.5f;
  refused(s, "color correction volume 1 has a fade duration");
  s = corrected();
  s.color_correction_volumes[0].lut.clear();
  refused(s, "color correction volume 0 has no LUT");
}

TEST(ColorCorrectionNodes, GltfExtrasRoundTripEveryField) {
  TempDir dir;
  Scene s = corrected();
  Camera c;
  c.position = {0, -300, 100};
  s.cameras = {c};
  const std::string path = dir.file("nodes.gltf");
  save_gltf(s, path);
  const Scene back = load_gltf(path);
  ASSERT_EQ(back.color_corrections.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const ColorCorrection& a = s.color_corrections[i];
    const ColorCorrection& b = back.color_corrections[i];
    EXPECT_EQ(b.lut, a.lut);
    EXPECT_EQ(b.position, a.position);
    EXPECT_EQ(b.min_falloff, a.min_falloff);
    EXPECT_EQ(b.max_falloff, a.max_falloff);
    EXPECT_EQ(b.max_weight, a.max_weight);
    EXPECT_EQ(b.fade_in, a.fade_in);
    EXPECT_EQ(b.fade_out, a.fade_out);
    EXPECT_EQ(b.start_disabled, a.start_disabled);
    ASSERT_EQ(b.inputs.size(), a.inputs.size());
    for (size_t k = 0; k < a.inputs.size(); ++k) {
      EXPECT_EQ(b.inputs[k].time, a.inputs[k].time);
      EXPECT_EQ(b.inputs[k].kind, a.inputs[k].kind);
    }
  }
  ASSERT_EQ(back.color_correction_volumes.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const ColorCorrectionVolume& a = s.color_correction_volumes[i];
    const ColorCorrectionVolume& b = back.color_correction_volumes[i];
    EXPECT_EQ(b.lut, a.lut);
    EXPECT_EQ(b.min, a.min);
    EXPECT_EQ(b.max, a.max);
    EXPECT_EQ(b.fade_duration, a.fade_duration);
  }
}

TEST(ColorCorrectionNodes, FilesWrittenBeforeFadesLoadWithTheDefaults) {
  TempDir dir;
  GltfBuilder b;
  b.doc["scenes"][0]["extras"] = {
      {"luxel", {{"colorcorrections", json::array({{{"lut", "builtin:warm"}, {"position", {1, 2, 3}}, {"minfalloff", 8},
                                                    {"maxfalloff", 16}, {"maxweight", 0.5}}})}}}};
  const std::string path = b.write(dir);
  const Scene s = load_gltf(path);
  ASSERT_EQ(s.color_corrections.size(), 1u);
  const ColorCorrection& c = s.color_corrections[0];
  EXPECT_EQ(c.max_weight, 0.5f);
  EXPECT_EQ(c.fade_in, 0.0f);
  EXPECT_EQ(c.fade_out, 0.0f);
  EXPECT_FALSE(c.start_disabled);
  EXPECT_TRUE(c.inputs.empty());
  EXPECT_TRUE(s.color_correction_volumes.empty());
}

TEST(ColorCorrectionNodes, GltfRefusesAnUnknownInputAndBadValues) {
  TempDir dir;
  GltfBuilder b;
  json node = {{"lut", "builtin:warm"}, {"inputs", json::array({{{"time", 1}, {"input", "enable"}}, {{"time", 2}, {"input", "toggle"}}})}};
  b.doc["scenes"][0]["extras"] = {{"luxel", {{"colorcorrections", json::array({node})}}}};
  const std::string path = b.write(dir);
  expect_gltf_error(path, "color correction 0 input 1 is 'toggle', not enable or disable", [&] { load_gltf(path); });
  b.doc["scenes"][0]["extras"]["luxel"]["colorcorrections"][0]["inputs"][1]["input"] = "disable";
  b.doc["scenes"][0]["extras"]["luxel"]["colorcorrectionvolumes"] = json::array({{{"lut", "builtin:cool"}, {"fadeduration", -3}}});
  b.write(dir);
  expect_gltf_error(path, "color correction volume 0 has a fade duration", [&] { load_gltf(path); });
}

}  // namespace
}  // namespace luxel::scenes::test
