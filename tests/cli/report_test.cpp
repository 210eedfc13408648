// `luxel report speed-error` on light probes written here (a uniform lat-long probe, a two-tone
// angular map), small grids and few normals, so that it needs no shared assets:
//  - the JSON's rows state scene, resolution, CPU and reference, with the counted costs;
//  - references: the uniform probe's irradiance is πL exactly, which all three bases represent,
//    so its rows' errors are ~0; R&H's published probes are band-limited, so SH9's rows are ~0;
//    the quadrature behind both is checked against closed forms in
//    tests/shading/sphere_quadrature_test.cpp and environment_image_test.cpp;
//  - a second run writes the same JSON but for the `timing` fields, and the same PNG bytes;
//  - the PNG reads back at the plot's size and the JSON lists each plot's series and labels;
//  - the findings state the rows' own numbers as the table prints them (the range of each basis's
//    error over the peak on the published and on the measured probes; the lanes that agree), in
//    the JSON and as "finding: " lines of the text.

#include "cli/run_luxel.hpp"

#include "luxel/scenes/image_io.hpp"
#include "luxel/shading/source/catalog.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace luxel::cli {
namespace {

namespace fs = std::filesystem;
using test::Process;
using test::printed;
using test::run_luxel;


/// The range of `values` as the findings print it: "A to B", or "A" when both ends print the same.
std::string printed_range(const std::vector<double>& values, const char* format) {
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  const std::string a = printed(*lo, format), b = printed(*hi, format);
  return a == b ? a : a + " to " + b;
}

/// Each basis's largest error over the peak, in %, over the rows that pass `environments`, as the
/// lighting_bases findings name them: "SH9's A to B %, the cube's C to D %, SH4's E to F %".
template <class Keep>
std::string bases_max_of_peak(const nlohmann::json& rows, Keep environments) {
  const std::pair<const char*, const char*> bases[] = {{"SH9 (ps_3_0)", "SH9"}, {"ambient cube (ps_2_0+)", "the cube"},
                                                       {"linear SH4 (ps_2_0+)", "SH4"}};
  std::string text;
  for (const auto& [variant, name] : bases) {
    std::vector<double> values;
    for (const nlohmann::json& row : rows)
      if (row["variant"] == variant && environments(row)) values.push_back(100.0 * row["error"]["max_of_peak"].get<double>());
    text += (text.empty() ? "" : ", ") + std::string(name) + "'s " + printed_range(values, "%.3f") + " %";
  }
  return text;
}

bool published(const nlohmann::json& row) { return row["resolution"].get<std::string>().starts_with("analytic"); }

/// The lighting_bases section's findings against its rows, in the JSON and in the text: the
/// published probes' ranges first, then the measured probes' when there are any, then the costs.
void expect_bases_findings(const nlohmann::json& section, const std::string& text, int measured_probes) {
  const nlohmann::json& findings = section["findings"];
  ASSERT_EQ(findings.size(), measured_probes > 0 ? 3u : 2u) << findings;
  EXPECT_EQ(findings[0], "on R&H 2001's 3 published probes (band-limited) the largest error over the peak irradiance is " +
                             bases_max_of_peak(section["rows"], published));
  if (measured_probes > 0) {
    const std::string measured = findings[1];
    EXPECT_EQ(measured.rfind("on the " + std::to_string(measured_probes) + " measured probes it is " +
                                 bases_max_of_peak(section["rows"], [](const nlohmann::json& row) { return !published(row); }) + "; ",
                             0),
              0u)
        << measured;
  }
  EXPECT_EQ(findings.back(), "SH9 takes 11 ps_3_0 slots and 9 constant registers, the cube 9 and 6, SH4 3 and 4");
  for (const nlohmann::json& finding : findings)
    EXPECT_NE(text.find("\nfinding: " + finding.get<std::string>() + "\n"), std::string::npos) << finding;
}

scenes::PixelImage probe(int width, int height, float top, float bottom) {
  scenes::PixelImage image;
  image.width = width, image.height = height;
  image.rgba32f.resize(size_t(width) * height * 4);
  for (int i = 0; i < height; ++i)
    for (int j = 0; j < width; ++j)
      for (int c = 0; c < 4; ++c) image.rgba32f[(size_t(i) * width + j) * 4 + size_t(c)] = c == 3 ? 1.0f : i < height / 2 ? top : bottom;
  return image;
}

/// The report run twice on the same probes into two folders.
class ReportCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("luxel_report_test_" + std::to_string(getpid()));
    fs::create_directories(root_ / "probes" / "sub");
    scenes::write_image(probe(64, 32, 0.5f, 0.5f), (root_ / "probes" / "uniform.hdr").string());
    scenes::write_image(probe(48, 48, 2.0f, 0.25f), (root_ / "probes" / "sub" / "two_tone.hdr").string());
    for (const char* out : {"a", "b"}) {
      runs_.push_back(run_luxel("report speed-error --sections lighting_bases --normals 200 --grid 96 --repeats 1 --probes " +
                                (root_ / "probes").string() +
                                " --out " + (root_ / out).string() + " 2>/dev/null"));
    }
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  static nlohmann::json json(const char* run) { return nlohmann::json::parse(test::file_text(root_ / run / "speed_error.json")); }

  static inline fs::path root_;
  static inline std::vector<Process> runs_;
};

TEST_F(ReportCommand, WritesRowsThatStateWhatTheyMeasured) {
  ASSERT_EQ(runs_[0].exit_code, 0) << runs_[0].out;
  const nlohmann::json j = json("a");
  ASSERT_EQ(j["sections"].size(), 1u);
  const nlohmann::json& s = j["sections"][0];
  EXPECT_EQ(s["name"], "lighting_bases");
  // Three R&H probes and the two written here, three bases each.
  ASSERT_EQ(s["rows"].size(), 15u);
  std::set<std::string> scenes;
  for (const nlohmann::json& row : s["rows"]) {
    for (const char* field : {"scene", "resolution", "variant", "reference", "cpu"})
      EXPECT_FALSE(row[field].get<std::string>().empty()) << field;
    scenes.insert(row["scene"]);
    const std::string variant = row["variant"];
    const std::pair<int, int> cost(row["cost"]["slots"], row["cost"]["constant_registers"]);
    const std::pair<int, int> expected = variant.starts_with("ambient cube") ? std::pair(9, 6)
                                         : variant.starts_with("linear SH4") ? std::pair(3, 4)
                                                                             : std::pair(11, 9);
    EXPECT_EQ(cost, expected) << variant;
    EXPECT_GT(row["timing"]["ns_per_pixel_simd"].get<double>(), 0.0);
    // The uniform probe: E = πL, which every basis holds exactly; what remains is the reference's
    // quadrature on 64 x 32 pixels (the cosine taken at each pixel's centre): 6e-4.
    if (row["scene"] == "uniform.hdr") {
      EXPECT_LT(row["error"]["max_relative"].get<double>(), 1e-3) << variant;
    }
    // Band-limited radiance: SH9 exact up to the 96-row grid's quadrature, which the fit and the
    // reference share.
    if (row["scene"].get<std::string>().find("R&H") != std::string::npos && variant.starts_with("SH9")) {
      EXPECT_LT(row["error"]["max_relative"].get<double>(), 1e-3) << row["scene"];
    }
  }
  EXPECT_TRUE(scenes.count("sub/two_tone.hdr"));
  EXPECT_EQ(s["rows"][9]["resolution"], "48x48 angular map");  // sorted: sub/two_tone.hdr before uniform.hdr
  EXPECT_EQ(s["rows"][12]["resolution"], "64x32 lat-long");
}

TEST_F(ReportCommand, TwoRunsGiveTheSameNumbersAndPlots) {
  ASSERT_EQ(runs_[1].exit_code, 0) << runs_[1].out;
  nlohmann::json a = json("a"), b = json("b");
  for (nlohmann::json* j : {&a, &b})
    for (nlohmann::json& s : (*j)["sections"])
      for (nlohmann::json& row : s["rows"]) row.erase("timing");
  EXPECT_EQ(a, b);
  EXPECT_EQ(test::file_text(root_ / "a" / "lighting_bases.png"), test::file_text(root_ / "b" / "lighting_bases.png"));
}

TEST_F(ReportCommand, PlotIsAPngWithTheLabelsTheJsonLists) {
  const nlohmann::json j = json("a");
  const nlohmann::json& plot = j["sections"][0]["plot"];
  ASSERT_EQ(plot["file"], "lighting_bases.png");
  const scenes::PixelImage png = scenes::read_image((root_ / "a" / "lighting_bases.png").string());
  EXPECT_EQ(png.width, plot["width"].get<int>());
  EXPECT_EQ(png.height, plot["height"].get<int>());
  std::set<std::string> series, labels;
  for (const nlohmann::json& s : plot["series"]) {
    series.insert(s["name"]);
    for (const nlohmann::json& p : s["points"]) labels.insert(p["label"]);
  }
  EXPECT_EQ(series, (std::set<std::string>{"ambient cube (ps_2_0+)", "linear SH4 (ps_2_0+)", "SH9 (ps_3_0)"}));
  EXPECT_EQ(labels, (std::set<std::string>{"Grace Cathedral R&H", "Eucalyptus Grove R&H", "St. Peter's Basilica R&H", "two_tone",
                                           "uniform"}));
  EXPECT_EQ(plot["x_label"], "ps_3_0 slots (counted)");
  EXPECT_TRUE(plot["log_y"].get<bool>());
}

TEST_F(ReportCommand, FindingsStateTheRowsNumbers) {
  ASSERT_EQ(runs_[0].exit_code, 0) << runs_[0].out;
  expect_bases_findings(json("a")["sections"][0], test::file_text(root_ / "a" / "speed_error.txt"), 2);
}

TEST_F(ReportCommand, PrintsTheTableItWrites) {
  const std::string text = test::file_text(root_ / "a" / "speed_error.txt");
  EXPECT_NE(runs_[0].out.find(text), std::string::npos);
  EXPECT_NE(text.find("cpu: "), std::string::npos);
  EXPECT_NE(text.find("== lighting_bases: "), std::string::npos);
  EXPECT_NE(runs_[0].out.find("speed_error.json, lighting_bases.png"), std::string::npos);
}

TEST(ReportCommandProbes, AMissingFolderSkipsTheProbeRowsWithANote) {
  const fs::path out = fs::temp_directory_path() / ("luxel_report_noprobes_" + std::to_string(getpid()));
  const Process run = run_luxel("report speed-error --sections lighting_bases --normals 20 --grid 16 --repeats 1 --probes " +
                                (out / "none").string() +
                                " --out " + out.string() + " 2>/dev/null");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("is not a folder; the probe rows are skipped"), std::string::npos) << run.out;
  // Without --probes: the same rows, and a note that none was given.
  const Process none = run_luxel("report speed-error --sections lighting_bases --normals 20 --grid 16 --repeats 1 --out " +
                                 (out / "no_option").string() + " 2>/dev/null");
  ASSERT_EQ(none.exit_code, 0) << none.out;
  EXPECT_NE(none.out.find("probes: none given; the probe rows are skipped"), std::string::npos) << none.out;
  EXPECT_EQ(nlohmann::json::parse(test::file_text(out / "speed_error.json"))["sections"][0]["rows"].size(), 9u);
  const nlohmann::json section = nlohmann::json::parse(test::file_text(out / "no_option" / "speed_error.json"))["sections"][0];
  EXPECT_EQ(section["rows"].size(), 9u);
  expect_bases_findings(section, test::file_text(out / "no_option" / "speed_error.txt"), 0);
  fs::remove_all(out);
}

// The lanes section: a row per catalog variant; the SIMD lane gives the scalar lane's bits for
// every pixel of every variant, those whose combine stage samples a texture (the ps_2_0
// normalization cube) included: both lanes read it by the hardware sampling rules.
TEST(ReportLanes, SimdGivesTheScalarLanesBits) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / ("luxel-report-lanes-" + std::to_string(getpid()));
  std::filesystem::remove_all(out);
  const Process run = run_luxel("report speed-error --sections lanes --repeats 1 --out " + out.string() + " 2>/dev/null");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const nlohmann::json s = nlohmann::json::parse(test::file_text((out / "speed_error.json").string()))["sections"][0];
  EXPECT_EQ(s["name"], "lanes");
  ASSERT_EQ(s["rows"].size(), shading::source::shader_catalog().size());
  int texture_reading = 0;
  for (const nlohmann::json& row : s["rows"]) {
    const std::string name = row["scene"].get<std::string>();  // "family combo"
    EXPECT_EQ(name.rfind(row["variant"].get<std::string>() + " ", 0), 0u) << name;
    EXPECT_TRUE(row["label"].get<std::string>().empty()) << name << ": the plot names only the rows that differ";
    if (name.find("normcube") != std::string::npos) ++texture_reading;
    EXPECT_EQ(row["error"]["max_abs"].get<double>(), 0.0) << name;
    EXPECT_EQ(row["error"]["differing_share"].get<double>(), 0.0) << name;
    EXPECT_GT(row["cost"]["slots"].get<double>(), 0.0) << name;
  }
  EXPECT_GT(texture_reading, 0);
  // The finding counts the rows whose lanes agree on every pixel.
  const auto agreeing = std::count_if(s["rows"].begin(), s["rows"].end(),
                                      [](const nlohmann::json& row) { return row["error"]["differing_share"].get<double>() == 0.0; });
  ASSERT_FALSE(s["findings"].empty());
  EXPECT_EQ(s["findings"][0], std::to_string(agreeing) + " of " + std::to_string(s["rows"].size()) +
                                  " variants give the same bits on both lanes for every pixel");
  EXPECT_EQ(s["findings"].size(), agreeing == std::ssize(s["rows"]) ? 1u : 2u) << "the others are described";
  EXPECT_TRUE(std::filesystem::is_regular_file(out / "lanes.png"));
#if !defined(__SANITIZE_ADDRESS__)  // a second run: the same numbers but for the timings (the release suite's check)
  const std::filesystem::path again = out.string() + "-again";
  ASSERT_EQ(run_luxel("report speed-error --sections lanes --repeats 1 --out " + again.string() + " 2>/dev/null").exit_code, 0);
  nlohmann::json first = s["rows"], second = nlohmann::json::parse(test::file_text((again / "speed_error.json").string()))["sections"][0]["rows"];
  for (nlohmann::json* rows : {&first, &second})
    for (nlohmann::json& row : *rows) row.erase("timing");
  EXPECT_EQ(first, second);
  EXPECT_EQ(test::file_text((out / "lanes.png").string()), test::file_text((again / "lanes.png").string()));
  std::filesystem::remove_all(again);
#endif
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace luxel::cli
