// `luxel report speed-error`'s frame sections (msaa, shader_models, world_lighting,
// ambient_sampling, tone_mapping, color_correction) on a small courtyard frame (a quick bake, made
// on demand in the build tree's cache), run twice:
//  - MSAA: the error against the supersampled frame (its textures at the frame's mips) falls from
//    1 sample to 8;
//  - world lighting: RNM follows the bumped normal on the walls, the reference's noise is far below
//    every approximation's error;
//  - each section's reference row is exactly its reference (ps_3_0, trilinear): 0 steps and an
//    infinite PSNR (null in the JSON), and its cheapest row (ps_2_0, nearest) is not;
//  - tone mapping in the shader into 8 bits is the float target tone-mapped afterwards within a
//    step: nothing blends in the capture it is measured on, so only the last rounding may differ;
//  - the engine's LUTs of the built-in grades stay within color_correction.hpp's 2 steps;
//  - the rows state scene, resolution, reference and CPU; the second run gives the same numbers but
//    for the timing columns, and the same plots, which are PNGs of the size the JSON says;
//  - every section states findings, in the JSON and as "finding: " lines of the text, and those of
//    MSAA, shader models and tone mapping state their rows' numbers as the table prints them;
// and the box filter behind the MSAA references, in both spaces, against sums worked by hand.

#include "cli/run_luxel.hpp"

#include "report/box_filter.hpp"

#include "luxel/frame/image_difference.hpp"
#include "luxel/scenes/image_io.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace luxel::cli {
namespace {

namespace fs = std::filesystem;
using test::Process;
using test::printed;
using test::run_luxel;


const char* const kSections[] = {"msaa",           "shader_models", "texture_sampling", "world_lighting",
                                 "ambient_sampling", "tone_mapping", "color_correction"};

/// The report of the frame sections into `out` (ctest runs each test in its own process: the one
/// run the fixture makes serves a test, and only the determinism test makes a second).
Process run_report(const fs::path& out) {
  return run_luxel("report speed-error --sections msaa,shader_models,texture_sampling,world_lighting,ambient_sampling,tone_mapping,color_correction "
                   "--scene builtin:courtyard --bake quick --width 64 --height 36 --repeats 1 --out " +
                   out.string() + " 2>/dev/null");
}

class ReportFrames : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("luxel_report_frames_test_" + std::to_string(getpid()));
    run_ = run_report(root_ / "a");
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  static nlohmann::json section(const char* run, const std::string& name) {
    const nlohmann::json report = nlohmann::json::parse(test::file_text(root_ / run / "speed_error.json"));
    for (const nlohmann::json& s : report["sections"])
      if (s["name"] == name) return s;
    throw std::runtime_error("no section " + name);
  }

  static inline fs::path root_;
  static inline Process run_;
};

TEST_F(ReportFrames, RowsStateWhatTheyMeasured) {
  ASSERT_EQ(run_.exit_code, 0) << run_.out;
  for (const char* name : kSections) {
    const nlohmann::json s = section("a", name);
    ASSERT_FALSE(s["rows"].empty()) << name;
    for (const nlohmann::json& row : s["rows"]) {
      // world_lighting measures points on the scene's surfaces, a group of them per row.
      const bool points = std::string(name) == "world_lighting";
      EXPECT_EQ(row["scene"].get<std::string>().rfind("builtin:courtyard", 0), 0u) << name;
      EXPECT_EQ(row["resolution"], points ? "1000 points" : "64x36") << name;
      for (const char* field : {"variant", "reference", "cpu"}) EXPECT_FALSE(row[field].get<std::string>().empty()) << name;
      for (const auto& [key, ms] : row["timing"].items()) EXPECT_GT(ms.get<double>(), 0.0) << name << " " << key;
    }
  }
  EXPECT_NE(section("a", "msaa")["rows"][0]["reference"].get<std::string>().find("512x288 with 1 sample per pixel"),
            std::string::npos);
  const std::string text = test::file_text(root_ / "a" / "speed_error.txt");
  for (const char* name : kSections) {
    const nlohmann::json findings = section("a", name)["findings"];
    EXPECT_FALSE(findings.empty()) << name;
    for (const nlohmann::json& finding : findings)
      EXPECT_NE(text.find("\nfinding: " + finding.get<std::string>() + "\n"), std::string::npos) << finding;
  }
}

TEST_F(ReportFrames, MsaaErrorFallsAsSamplesRise) {
  // Four rows against the box filter in the resolve's space, then four against linear light.
  const nlohmann::json rows = section("a", "msaa")["rows"];
  ASSERT_EQ(rows.size(), 8u);
  std::vector<int> samples;
  for (const nlohmann::json& row : rows) samples.push_back(row["cost"]["samples"]);
  EXPECT_EQ(samples, (std::vector<int>{1, 2, 4, 8, 1, 2, 4, 8}));
  EXPECT_EQ(rows[0]["variant"], "MSAA vs sRGB-space box");
  EXPECT_EQ(rows[4]["variant"], "MSAA vs linear-light box");
  const nlohmann::json &one = rows[0]["error"], &eight = rows[3]["error"];
  EXPECT_GT(one["mean_steps"].get<double>(), eight["mean_steps"].get<double>());
  EXPECT_LT(one["psnr_db"].get<double>(), eight["psnr_db"].get<double>());
  // The reference reads its textures at the frame's mips (FrameSettings::texture_lod_bias); at
  // its own, every textured pixel is sharper than MSAA can draw it: 4.4 steps at 8 samples here.
  EXPECT_LT(eight["mean_steps"].get<double>(), 3.0);
  // A finding per reference: the mean error at the fewest samples and at the most, as printed.
  const nlohmann::json findings = section("a", "msaa")["findings"];
  ASSERT_EQ(findings.size(), 2u);
  for (size_t f = 0; f < 2; ++f) {
    const std::string expected = rows[4 * f]["variant"].get<std::string>() + ": the mean error goes from " +
                                 printed(rows[4 * f]["error"]["mean_steps"], "%.4f") + " steps at 1 sample to " +
                                 printed(rows[4 * f + 3]["error"]["mean_steps"], "%.4f") + " at 8 (down ";
    EXPECT_EQ(findings[f].get<std::string>().rfind(expected, 0), 0u) << findings[f] << "\nexpected: " << expected;
  }
}

/// The last row is the section's reference drawn again: 0 against it; the first, the cheapest
/// approximation, is not.
void expect_reference_last(const nlohmann::json& rows, const std::string& reference_variant) {
  ASSERT_GE(rows.size(), 2u);
  const nlohmann::json& last = rows.back();
  EXPECT_EQ(last["variant"], reference_variant);
  EXPECT_EQ(last["error"]["max_steps"], 0);
  EXPECT_EQ(last["error"]["mean_steps"], 0.0);
  EXPECT_TRUE(last["error"]["psnr_db"].is_null());  // +infinity
  EXPECT_GT(rows[0]["error"]["max_steps"].get<int>(), 0) << rows[0]["variant"];
  EXPECT_TRUE(std::isfinite(rows[0]["error"]["psnr_db"].get<double>())) << rows[0]["variant"];
}

TEST_F(ReportFrames, ShaderModelsAgainstPs30) {
  const nlohmann::json rows = section("a", "shader_models")["rows"];
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0]["variant"], "ps_2_0");
  EXPECT_EQ(rows[1]["variant"], "ps_2_b");
  expect_reference_last(rows, "ps_3_0");
  for (const nlohmann::json& row : rows) EXPECT_GT(row["cost"]["slots_per_pixel"].get<double>(), 0.0);
  // ps_2_b's finding says "the same bytes" exactly when its row has no differing pixel.
  const nlohmann::json findings = section("a", "shader_models")["findings"];
  ASSERT_GE(findings.size(), 2u);
  const nlohmann::json& ps_2_b = rows[1]["error"];
  const bool same = ps_2_b["differing_share"].get<double>() == 0.0 && ps_2_b["max_steps"].get<int>() == 0;
  EXPECT_EQ(findings[1], "ps_2_b against ps_3_0: " + (same ? std::string("the same bytes (0 pixels differ)")
                                                            : printed(100.0 * ps_2_b["differing_share"].get<double>(), "%.2f") +
                                                                  " % of the pixels differ, by up to " +
                                                                  printed(ps_2_b["max_steps"], "%.0f") + " step"));
  EXPECT_EQ(findings[0].get<std::string>().rfind("ps_2_0 against ps_3_0: " +
                                                     printed(100.0 * rows[0]["error"]["differing_share"].get<double>(), "%.2f") +
                                                     " % of the pixels differ, by up to ",
                                                 0),
            0u)
      << findings[0];
}

TEST_F(ReportFrames, HardwareSamplingAgainstIdeal) {
  const nlohmann::json rows = section("a", "texture_sampling")["rows"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["variant"], "hardware");
  expect_reference_last(rows, "ideal");
}

TEST_F(ReportFrames, NearestAmbientAgainstTrilinear) {
  const nlohmann::json rows = section("a", "ambient_sampling")["rows"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["cost"]["volume_samples"], 1);
  EXPECT_EQ(rows[1]["cost"]["volume_samples"], 8);
  expect_reference_last(rows, "trilinear");
}

TEST_F(ReportFrames, InShaderToneMapIsTheFloatTargetsWithinAStep) {
  const nlohmann::json rows = section("a", "tone_mapping")["rows"];
  ASSERT_EQ(rows.size(), 3u);
  for (const nlohmann::json& row : rows) {
    EXPECT_LE(row["error"]["max_steps"].get<int>(), 1) << row["label"];
    EXPECT_LT(row["error"]["differing_share"].get<double>(), 0.05) << row["label"];
    EXPECT_EQ(row["cost"]["target_bytes_per_pixel"], 4) << row["label"];
  }
  // The finding states the largest difference over the scales.
  int largest = 0;
  for (const nlohmann::json& row : rows) largest = std::max(largest, row["error"]["max_steps"].get<int>());
  const nlohmann::json findings = section("a", "tone_mapping")["findings"];
  ASSERT_EQ(findings.size(), 1u);
  const std::string expected = largest == 0 ? "the 8-bit target gives the float target's bytes at every scale measured"
                                            : "the 8-bit target is within " + std::to_string(largest) +
                                                  (largest == 1 ? " step" : " steps") + " of the float target at every scale measured";
  EXPECT_EQ(findings[0].get<std::string>().rfind(expected, 0), 0u) << findings[0];
}

TEST_F(ReportFrames, EngineLutsStayNearTheExactGrades) {
  // postfx/color_correction.hpp: the built-in presets through the engine's lattice are within 2
  // steps of the exact grade over every 8-bit color; 16^3 and 64^3 lattices follow, the volume's
  // bytes as their cost.
  const nlohmann::json rows = section("a", "color_correction")["rows"];
  ASSERT_EQ(rows.size(), 12u);
  for (size_t i = 0; i < rows.size(); ++i) {
    const nlohmann::json& row = rows[i];
    const int size = i < 4 ? 16 : i < 8 ? 32 : 64;
    EXPECT_EQ(row["cost"]["lut_kib"].get<double>(), size * size * size * 4 / 1024.0) << i;
    EXPECT_EQ(row["variant"].get<std::string>().rfind(std::to_string(size) + "^3 8-bit LUT", 0), 0u) << i;
    if (size == 32) {
      EXPECT_LE(row["error"]["max_steps"].get<int>(), 2) << row["label"];
    }
    EXPECT_LE(row["error"]["max_steps"].get<int>(), 6) << row["label"] << " " << size;
    EXPECT_GT(row["cost"]["slots_per_pixel"].get<double>(), 0.0) << row["label"];
  }
}

TEST_F(ReportFrames, TwoRunsGiveTheSameNumbersAndPlots) {
  const Process second = run_report(root_ / "b");
  ASSERT_EQ(second.exit_code, 0) << second.out;
  for (const char* name : kSections) {
    nlohmann::json a = section("a", name), b = section("b", name);
    for (nlohmann::json* s : {&a, &b})
      for (nlohmann::json& row : (*s)["rows"]) row.erase("timing");
    EXPECT_EQ(a, b) << name;
    EXPECT_EQ(test::file_text(root_ / "a" / (std::string(name) + ".png")), test::file_text(root_ / "b" / (std::string(name) + ".png"))) << name;
  }
}

TEST_F(ReportFrames, PlotsArePngsOfTheSizeTheJsonSays) {
  for (const char* name : kSections) {
    const nlohmann::json plot = section("a", name)["plot"];
    ASSERT_EQ(plot["file"], std::string(name) + ".png");
    const scenes::PixelImage png = scenes::read_image((root_ / "a" / plot["file"].get<std::string>()).string());
    EXPECT_EQ(png.width, plot["width"].get<int>()) << name;
    EXPECT_EQ(png.height, plot["height"].get<int>()) << name;
  }
}

rasterizer::Image image_of(int width, int height, const std::vector<uint8_t>& red) {
  rasterizer::Image image(width, height);
  for (size_t i = 0; i < red.size(); ++i) {
    image.rgba[i * 4] = red[i];
    image.rgba[i * 4 + 3] = 255;
  }
  return image;
}

/// The rows of one section run on its own on a tiny courtyard (the sections that draw many frames
/// or captures, kept out of the fixture's run, which every test of it repeats). Run twice, it
/// must give the same JSON but for the timings, and the same plot; not under ASan, where the
/// second run would double the suite's slowest tests for a property the release suite checks.
nlohmann::json one_section_rows(const std::string& section, int width = 32, int height = 18) {
  const fs::path root = fs::temp_directory_path() / ("luxel_report_" + section + "_test_" + std::to_string(getpid()));
  auto run = [&](const char* name) {
    const Process p = run_luxel("report speed-error --sections " + section + " --scene builtin:courtyard --bake quick --width " +
                                std::to_string(width) + " --height " + std::to_string(height) + " --repeats 1 --out " +
                                (root / name).string() + " 2>/dev/null");
    EXPECT_EQ(p.exit_code, 0) << p.out;
    const std::string json = test::file_text(root / name / "speed_error.json");
    nlohmann::json rows = json.empty() ? nlohmann::json::array() : nlohmann::json::parse(json)["sections"][0]["rows"];
    for (nlohmann::json& row : rows) row.erase("timing");
    return rows;
  };
  const nlohmann::json rows = run("a");
#if !defined(__SANITIZE_ADDRESS__)
  EXPECT_EQ(run("b"), rows) << section << ": a second run";
  EXPECT_EQ(test::file_text(root / "a" / (section + ".png")), test::file_text(root / "b" / (section + ".png"))) << section;
#endif
  fs::remove_all(root);
  return rows;
}

// The exposure section on its own (60 frames per row): a row per counting method and latency; the
// two methods count the same samples, so they give the same targets; a later read-back lags
// more, so the mean error grows with the latency; once every bucket has been counted (the second
// half) the engine's target is near the exact one.
TEST(ReportExposure, RowsPerCountingAndLatencyWithTheSameTargetsForBothCountings) {
  const nlohmann::json rows = one_section_rows("exposure");
  ASSERT_EQ(rows.size(), 8u);
  for (size_t i = 0; i < 4; ++i) {
    const nlohmann::json& direct = rows[i];
    const nlohmann::json& stencil = rows[i + 4];
    EXPECT_EQ(direct["variant"], "direct query");
    EXPECT_EQ(stencil["variant"], "stencil + query");
    EXPECT_EQ(direct["cost"]["query_latency"], int(i + 1));
    EXPECT_EQ(stencil["cost"]["query_latency"], int(i + 1));
    EXPECT_EQ(direct["error"], stencil["error"]) << "latency " << i + 1;
    const double max = direct["error"]["max_stops"], mean = direct["error"]["mean_stops"],
                 late = direct["error"]["mean_stops_second_half"];
    EXPECT_TRUE(std::isfinite(max)) << i;
    EXPECT_GE(max, mean) << i;
    EXPECT_LT(late, mean) << "latency " << i + 1 << ": the filled histogram is nearer the exact one";
    EXPECT_LT(late, 0.1) << "latency " << i + 1;
    if (i > 0) {
      EXPECT_GE(mean, rows[i - 1]["error"]["mean_stops"].get<double>()) << "latency " << i + 1;
    }
  }
  EXPECT_GT(rows[3]["error"]["mean_stops"].get<double>(), rows[0]["error"]["mean_stops"].get<double>());
}

// The cubemaps section: brackets 1 to 4 stops apart and one exposure alone against float captures.
// Fewer captures, more error; within the bounds frame's cubemaps test sets for 2 and 4 stops (a
// merge without its division or of one exposure fails them, tests/frame/cubemaps_test.cpp), and
// the one exposure far outside them.
TEST(ReportCubemaps, MergedBracketsAgainstFloatCaptures) {
  const nlohmann::json rows = one_section_rows("cubemaps");
  ASSERT_EQ(rows.size(), 5u);
  const char* const variants[] = {"1 stops apart", "2 stops apart", "3 stops apart", "4 stops apart", "one exposure"};
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i]["variant"], variants[i]);
    if (i == 0) continue;
    EXPECT_LT(rows[i]["cost"]["captures_per_face"].get<int>(), rows[i - 1]["cost"]["captures_per_face"].get<int>()) << i;
    EXPECT_GT(rows[i]["error"]["p99_stops"].get<double>(), rows[i - 1]["error"]["p99_stops"].get<double>()) << i;
  }
  EXPECT_LE(rows[1]["error"]["max_stops"].get<double>(), 0.03);
  EXPECT_LE(rows[1]["error"]["p99_stops"].get<double>(), 0.02);
  EXPECT_LE(rows[3]["error"]["max_stops"].get<double>(), 0.05);
  EXPECT_LE(rows[3]["error"]["p99_stops"].get<double>(), 0.035);
  EXPECT_GT(rows[4]["error"]["max_stops"].get<double>(), 1.0) << "one exposure cannot hold the sky and the shade";
  EXPECT_EQ(rows[4]["cost"]["captures_per_face"], 1);
}

// The ambient_popping section: the courtyard's moving models along 240 frames. The nearest sample
// steps as a model crosses cells, the trilinear blend moves smoothly, and the time averaging damps
// both: each of those halves (at least) the largest jump of the reading without it. Each is also
// judged against the exact cube at the model (the fifth row).
TEST(ReportAmbientPopping, AveragingAndTrilinearDampTheNearestSamplesSteps) {
  const nlohmann::json rows = one_section_rows("ambient_popping");
  ASSERT_EQ(rows.size(), 5u);
  auto jump = [&](size_t i) { return rows[i]["error"]["max_jump"].get<double>(); };
  EXPECT_EQ(rows[0]["cost"]["volume_samples"], 1);
  EXPECT_EQ(rows[2]["cost"]["volume_samples"], 8);
  EXPECT_EQ(rows[0]["cost"]["time_constant_s"], 0.0);
  EXPECT_GT(rows[1]["cost"]["time_constant_s"].get<double>(), 0.0);
  EXPECT_GT(jump(0), 0.1) << "the nearest sample steps between cells";
  EXPECT_LT(2 * jump(1), jump(0)) << "averaging damps the nearest sample's steps";
  EXPECT_LT(2 * jump(2), jump(0)) << "the trilinear blend has no steps";
  EXPECT_LE(jump(3), jump(2));
  for (size_t i = 0; i < rows.size(); ++i) EXPECT_LE(rows[i]["error"]["mean_jump"].get<double>(), jump(i)) << i;
  // Against the exact cube at the model (bake::ambient_cubes_at): the reference row is itself, the
  // lookups stray from it, the trilinear blend less on average than the nearest sample; the light's
  // own changes along the path are smaller than the nearest sample's steps.
  auto error = [&](size_t i, const char* which) { return rows[i]["error"][which].get<double>(); };
  EXPECT_EQ(rows[4]["variant"], "exact (the reference)");
  EXPECT_EQ(error(4, "max_error"), 0.0);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_GT(error(i, "mean_error"), 0.0) << i;
    EXPECT_LE(error(i, "mean_error"), error(i, "max_error")) << i;
    EXPECT_LT(error(i, "max_error"), 2.0) << i;
  }
  EXPECT_LT(error(2, "mean_error"), error(0, "mean_error")) << "the trilinear blend is nearer the exact cube";
  EXPECT_LT(jump(4), jump(0)) << "the nearest sample pops beyond the light's own changes";
}

// The world_lighting section on the quick-baked courtyard: per group of surfaces (walls, floors),
// the flat lightmap, RNM as the engine combines it, RNM with maps rescaled to average the flat
// one, and the reference again with another seed. The reference's own noise is far below every
// approximation's error. On the walls (lit from the side by the torches) RNM follows the bumped
// normal: its mean error is under half the flat map's (with the bitangent's sign flipped in the
// reference's frame, RNM's error rises above the flat map's and this fails). RNM costs three maps
// and more slots.
TEST_F(ReportFrames, WorldLightingRnmFollowsTheBumpOnTheWallsAndTheReferenceNoiseIsFarBelow) {
  const nlohmann::json rows = section("a", "world_lighting")["rows"];
  ASSERT_EQ(rows.size(), 8u);
  const char* const variants[] = {"flat lightmap", "RNM (the engine's)", "RNM, maps averaging the flat one", "reference, another seed"};
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i]["variant"], variants[i % 4]) << i;
    EXPECT_EQ(rows[i]["scene"], std::string("builtin:courtyard ") + (i < 4 ? "walls" : "floors")) << i;
  }
  auto mean = [&](size_t i) { return rows[i]["error"]["mean_error"].get<double>(); };
  for (size_t g = 0; g < rows.size(); g += 4) {
    EXPECT_EQ(rows[g]["cost"]["lightmaps_per_pixel"], 1);
    EXPECT_EQ(rows[g + 1]["cost"]["lightmaps_per_pixel"], 3);
    EXPECT_EQ(rows[g]["cost"]["bytes_per_luxel"], 4);
    EXPECT_EQ(rows[g + 1]["cost"]["bytes_per_luxel"], 16);
    EXPECT_LT(rows[g]["cost"]["slots"].get<double>(), rows[g + 1]["cost"]["slots"].get<double>());
    EXPECT_TRUE(rows[g + 3]["cost"]["slots"].is_null()) << "the reference is no shader";
    EXPECT_LT(mean(g + 3), 0.02) << g;
    for (size_t v = 0; v < 3; ++v) {
      EXPECT_LT(10 * mean(g + 3), mean(g + v)) << g << " " << v;
      EXPECT_LE(mean(g + v), rows[g + v]["error"]["p95_error"].get<double>()) << g << " " << v;
      EXPECT_LE(std::abs(rows[g + v]["error"]["bias"].get<double>()), mean(g + v)) << g << " " << v;
    }
  }
  EXPECT_LT(2 * mean(1), mean(0)) << "on the walls RNM follows the bumped normal";
}

// The vertex_lighting section: per-vertex attenuation changes some model pixels, a little, and
// costs fewer slots than per pixel on the same model; each per-pixel row is its own reference.
// At 64x36: the courtyard's lights are far from its models, and on fewer pixels the one-step
// differences may all round away.
TEST(ReportVertexLighting, PerVertexAttenuationAgainstPerPixel) {
  const nlohmann::json rows = one_section_rows("vertex_lighting", 64, 36);
  ASSERT_EQ(rows.size(), 4u);
  for (size_t i = 0; i < rows.size(); i += 2) {
    const nlohmann::json &pixel = rows[i], &vertex = rows[i + 1];
    EXPECT_EQ(pixel["variant"], "per pixel");
    EXPECT_EQ(vertex["variant"], "per vertex");
    EXPECT_EQ(pixel["error"]["max_steps"], 0);
    EXPECT_GT(vertex["error"]["differing_share"].get<double>(), 0.0) << "the models' pixels change";
    EXPECT_LT(vertex["error"]["differing_share"].get<double>(), 0.2) << "only the models' pixels";
    EXPECT_LT(vertex["cost"]["slots_per_pixel"].get<double>(), pixel["cost"]["slots_per_pixel"].get<double>());
  }
}

TEST(BoxFilterDown, RoundsEachBlocksMeanHalfUpAsTheResolve) {
  // Two 2x2 blocks side by side: sums 1 (mean 0.25 -> 0), 2 (0.5 -> 1, half up) and, below, 6
  // (1.5 -> 2) and 1020 (255).
  const rasterizer::Image big = image_of(4, 4, {0, 0, 1, 1,        //
                                                0, 1, 0, 0,        //
                                                1, 2, 255, 255,    //
                                                2, 1, 255, 255});
  const rasterizer::Image small = box_filter_down(big, 2);
  ASSERT_EQ(small.width, 2);
  ASSERT_EQ(small.height, 2);
  EXPECT_EQ(small.pixel(0, 0)[0], 0);
  EXPECT_EQ(small.pixel(1, 0)[0], 1);
  EXPECT_EQ(small.pixel(0, 1)[0], 2);
  EXPECT_EQ(small.pixel(1, 1)[0], 255);
  EXPECT_EQ(small.pixel(1, 1)[3], 255);
  // Factor 1 is the image itself: against it, nothing differs and the PSNR is infinite.
  const frame::ImageDifference same = frame::image_difference(box_filter_down(big, 1), big);
  EXPECT_TRUE(same.identical());
  EXPECT_TRUE(std::isinf(same.psnr_db));
  EXPECT_THROW(box_filter_down(big, 3), std::invalid_argument);
}

TEST(BoxFilterDown, LinearLightAveragesDecodedValues) {
  // Black and white halves: 127.5 stored, rounded half up to 128; in linear light the mean is
  // 0.5, sRGB-encoded 0.7354 x 255 = 187.5, rounded to 188. Alpha stays stored.
  const rasterizer::Image big = image_of(2, 2, {0, 255, 255, 0});
  EXPECT_EQ(box_filter_down(big, 2, BoxSpace::stored).pixel(0, 0)[0], 128);
  const rasterizer::Image linear = box_filter_down(big, 2, BoxSpace::linear_light);
  EXPECT_EQ(linear.pixel(0, 0)[0], 188);
  EXPECT_EQ(linear.pixel(0, 0)[1], 0);
  EXPECT_EQ(linear.pixel(0, 0)[3], 255);
}

}  // namespace
}  // namespace luxel::cli
