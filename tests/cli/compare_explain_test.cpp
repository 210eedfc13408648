// `luxel compare --explain` (cli/compare_explain.hpp): on scenes made to differ between ps_2_0 and
// ps_2_b by one rule only, every differing pixel is attributed to that rule and to no other; on
// the courtyard, whose pair differs by several, no pixel is left unexplained and the JSON's counts
// add up to the pair's differing pixels.

#include "cli/run_luxel.hpp"

#include "compare_explain.hpp"

#include "luxel/bake/bake.hpp"
#include "luxel/frame/renderer.hpp"
#include "luxel/scenes/builtin.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace luxel::cli {
namespace {

constexpr int kWidth = 128, kHeight = 72;

/// The courtyard, quickly baked once, then changed by `edit`.
scenes::Scene courtyard(const std::function<void(scenes::Scene&)>& edit) {
  static const scenes::Scene baked = [] {
    scenes::Scene s = scenes::make_builtin_scene("courtyard", {kWidth, kHeight});
    bake::BakeSettings b = bake::BakeSettings::quick();
    b.samples = 16;
    b.cube_samples = 16;
    b.supersample = 1;
    b.max_bounces = 2;
    bake::attach(s, bake::bake(s, b));
    return s;
  }();
  scenes::Scene s = baked;
  edit(s);
  return s;
}

rasterizer::Image draw(const scenes::Scene& scene, const frame::FrameSettings& settings) {
  frame::Renderer r(scene, settings);
  rasterizer::Context ctx(2);
  r.render(ctx);
  return r.image();
}

/// The explanation of ps_2_0 against ps_2_b on `scene`.
Explanation explain(const scenes::Scene& scene) {
  frame::FrameSettings f{kWidth, kHeight, 4};
  f.exposure = 1.0f;  // every drawing at one scale, whatever its view's histogram
  frame::FrameSettings lo = f, hi = f;
  lo.model = shading::ShaderModel::ps_2_0;
  hi.model = shading::ShaderModel::ps_2_b;
  const std::optional<Explanation> e =
      explain_pair(draw(scene, lo), draw(scene, hi), lo.model, hi.model, scene, f,
                   [](const scenes::Scene& s, const frame::FrameSettings& settings) { return draw(s, settings); });
  EXPECT_TRUE(e.has_value());
  return e.value_or(Explanation{});
}

void expect_only(const Explanation& e, Cause cause, uint64_t at_least) {
  EXPECT_GE(e.differing, at_least) << "the scene must differ between the cards";
  for (int c = 0; c < kCauses; ++c)
    EXPECT_EQ(e.pixels[size_t(c)], Cause(c) == cause ? e.differing : 0u) << cause_name(Cause(c));
}

/// Every model material drawn the same on both cards (lit per vertex, no skin shader).
void plain_models(scenes::Scene& s) {
  for (scenes::Material& m : s.materials)
    if (m.family == scenes::ShaderFamily::vertexlit_generic) {
      m.phong = false;
      m.bump = scenes::TextureRef{};
      if (m.envmap_mask == scenes::EnvmapMask::normal_alpha) m.envmap_mask = scenes::EnvmapMask::none;
    }
}

TEST(CompareExplain, OnlyTheFogDiffers) {
  expect_only(explain(courtyard([](scenes::Scene& s) {
                plain_models(s);
                ASSERT_NE(s.fog.mode, scenes::FogMode::none);
              })),
              Cause::fog_per_vertex, 1000);
}

TEST(CompareExplain, OnlyTheSkinShaderDiffers) {
  // The hero without a bump map but with $basemapalphaphongmask: the skin shader on ps_2_b, the
  // plain per-vertex path on ps_2_0 (no normalization cube either way); the rest plain, no fog.
  expect_only(explain(courtyard([](scenes::Scene& s) {
                s.fog = scenes::Fog{};
                for (scenes::Material& m : s.materials)
                  if (m.name != "courtyard/bronze" && m.family == scenes::ShaderFamily::vertexlit_generic) m.phong = false,
                      m.bump = scenes::TextureRef{};
                for (scenes::Material& m : s.materials)
                  if (m.name == "courtyard/bronze") {
                    m.bump = scenes::TextureRef{};
                    m.phong_exponent_texture = scenes::TextureRef{};
                    m.rim = false;
                    m.base_map_alpha_phong_mask = true;
                    m.envmap_mask = scenes::EnvmapMask::none;
                  }
              })),
              Cause::skin_shader, 20);
}

TEST(CompareExplain, OnlyTheNormalizationCubeDiffers) {
  // Bumped models without $phong, no fog: the bumped path on both cards, normalized through the
  // cube map on ps_2_0 alone.
  expect_only(explain(courtyard([](scenes::Scene& s) {
                s.fog = scenes::Fog{};
                for (scenes::Material& m : s.materials) m.phong = false;
              })),
              Cause::card_binary, 5);
}

TEST(CompareExplain, CourtyardLeavesNoPixelUnexplained) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("luxel-explain-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const test::Process run = test::run_luxel("compare --scene builtin:courtyard --bake quick --width 160 --height 90 --frames 1 "
                                            "--lights 4 --explain --out " + (dir / "c").string() + " 2>/dev/null");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  std::ifstream f(dir / "c.json");
  const nlohmann::json j = nlohmann::json::parse(f);
  for (const nlohmann::json& pair : j["pairs"]) {
    const std::string what = pair["a"].get<std::string>() + " vs " + pair["b"].get<std::string>();
    const nlohmann::json& e = pair["explain"];
    EXPECT_EQ(e["differing_pixels"], pair["differing_pixels"]) << what;
    uint64_t sum = 0;
    for (const auto& [cause, n] : e["pixels"].items()) sum += n.get<uint64_t>();
    EXPECT_EQ(sum, e["differing_pixels"].get<uint64_t>()) << what;
    EXPECT_EQ(e["pixels"]["unexplained"], 0) << what;
    if (pair["b"] == "ps_3_0" && pair["a"] == "ps_2_b") {
      EXPECT_EQ(e["differing_pixels"], 0) << what;
      continue;
    }
    // The courtyard differs by its range fog, its hero's skin shader, its crates' normalization
    // and, with four lights, the hero's light count.
    for (const char* cause : {"fog_per_vertex", "skin_shader", "card_binary", "light_count"})
      EXPECT_GT(e["involved"][cause].get<uint64_t>(), 0u) << what << ": " << cause;
  }
  EXPECT_NE(run.out.find("pixels by cause"), std::string::npos) << run.out;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace luxel::cli
