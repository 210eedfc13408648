// `luxel cost` checked by what it prints: a row for every variant of the shading catalog on every
// card the catalog lists for it (and no other, pixel or vertex shader model), the SDK binary that
// card runs, the counts the Counted lane measures for that binary, "fits" exactly when the
// printed counts are within the binary's limits (shader_model.hpp), the reason when not, the
// ambient-cube line and the CPU line. Table-driven from shader_catalog(), so the variants a family
// adds are covered without touching this test.

#include "luxel/shading/source/catalog.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/registry.hpp"
#include "luxel/shading/source/vertexlit_vertex_shader.hpp"
#include "cli/run_luxel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace luxel::shading::source {
namespace {

using cli::test::Process;
using cli::test::run_luxel;

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

/// The table's rows by "family|variant|model", each as its trimmed columns.
std::map<std::string, std::vector<std::string>> table_rows(const std::string& out, int& rows) {
  std::map<std::string, std::vector<std::string>> table;
  std::istringstream lines(out);
  std::string line;
  rows = 0;
  while (std::getline(lines, line)) {
    std::vector<std::string> cols;
    std::istringstream fields(line);
    std::string f;
    while (std::getline(fields, f, '|')) cols.push_back(trim(f));
    if (!line.empty() && line.back() == '|') cols.push_back("");
    if (cols.size() != 14 || cols[0] == "shader") continue;
    table[cols[0] + "|" + cols[1] + "|" + cols[2]] = cols;
    ++rows;
  }
  return table;
}

TEST(CostCommand, PrintsEveryCatalogVariantOnItsModelsWithTheCountedCost) {
  const Process run = run_luxel("cost --pixels 64 --repeats 1 2>&1");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  int rows = 0;
  const auto table = table_rows(run.out, rows);
  int expected_rows = 0, refused = 0;
  std::set<std::string> families;
  std::vector<ShaderModel> all_models(std::begin(kPixelModels), std::end(kPixelModels));
  all_models.insert(all_models.end(), std::begin(kVertexModels), std::end(kVertexModels));
  int vertex_rows = 0;
  for (const ShaderVariant& v : shader_catalog()) {
    families.insert(v.family);
    for (ShaderModel m : all_models) {
      const std::string key = v.family + "|" + v.variant + "|" + std::string(caps(m).name);
      const bool listed = std::find(v.models.begin(), v.models.end(), m) != v.models.end();
      const auto row = table.find(key);
      if (!listed) {
        EXPECT_EQ(row, table.end()) << key << ": printed, but the SDK's rules do not allow it there";
        continue;
      }
      ++expected_rows;
      if (m == ShaderModel::vs_2_0 || m == ShaderModel::vs_3_0) ++vertex_rows;
      ASSERT_NE(row, table.end()) << key << " missing from:\n" << run.out;
      const std::vector<std::string>& c = row->second;
      const ShaderModel binary = *v.builds.binary_for(m);
      EXPECT_EQ(c[3], binary_name(binary)) << key;
      const Cost cost = v.measure(binary);
      const int arith = std::stoi(c[4]), tex = std::stoi(c[5]), temps = std::stoi(c[6]), consts = std::stoi(c[7]),
                indir = std::stoi(c[8]);
      EXPECT_EQ(arith, cost.arithmetic_slots) << key;
      EXPECT_EQ(tex, cost.texture_slots) << key;
      EXPECT_EQ(temps, cost.temps) << key;
      EXPECT_EQ(consts, cost.constant_registers()) << key;
      EXPECT_EQ(indir, cost.texture_indirections) << key;
      // Fits: from the printed counts and the caps table, plus what the table does not print.
      const ShaderModelCaps& k = caps(binary);
      const bool within = arith <= k.arithmetic_slots && tex <= k.texture_slots && arith + tex <= k.total_slots &&
                          temps <= k.temps && consts <= k.constants && indir <= k.texture_indirections &&
                          cost.samplers <= k.samplers && cost.inputs <= k.inputs && cost.unsupported.empty();
      EXPECT_EQ(c[10], within ? "yes" : "NO") << key;
      EXPECT_EQ(c[13], within ? "" : fits(cost, k).reason) << key;
      if (!within) ++refused;
    }
  }
  EXPECT_EQ(rows, expected_rows) << "one row per variant and model, no others";
  EXPECT_GT(refused, 0) << "some variant exceeds its model (ps_2_0's per-pixel attenuation), so both answers are checked";
  std::set<std::string> printed;
  for (const auto& [key, cols] : table) printed.insert(cols[0]);
  EXPECT_EQ(printed, families);
  EXPECT_GE(families.size(), 7u);
  EXPECT_TRUE(families.count("VertexLitGeneric_vs")) << "the vertex shader is in the catalog";
  EXPECT_GT(vertex_rows, 0) << "rows on vs_2_0 / vs_3_0, counted against the vertex-shader limits";
}

// The SDK builds LightmappedGeneric, Water, Sky and the post shaders as ps20 and ps20b only, film
// grain as ps20 only, and skin as ps20b and ps30 (stdshader_dx9_20b.txt, stdshader_dx9_30.txt): a
// ps_3_0 card runs and pays for the ps20b binary of the first, a ps_2_b card the ps20 binary of
// film grain, and no ps_2_0 card runs skin.
TEST(CostCommand, ACardRunsTheNewestBinaryTheSdkBuilds) {
  const Process run = run_luxel("cost --pixels 64 --repeats 1 2>&1");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  int rows = 0;
  const auto table = table_rows(run.out, rows);
  std::map<std::string, std::set<std::string>> binaries_of;  // family|card -> binaries printed
  for (const auto& [key, c] : table) binaries_of[c[0] + "|" + c[2]].insert(c[3]);
  for (const char* family : {"LightmappedGeneric", "Water", "Sky_HDR", "bloomadd", "BlurFilter", "Downsample_nohdr",
                             "ColorCorrection", "Engine_Post", "LuminanceRange"}) {
    EXPECT_EQ(binaries_of[std::string(family) + "|ps_3_0"], std::set<std::string>{"ps20b"}) << family;
    EXPECT_EQ(binaries_of[std::string(family) + "|ps_2_b"], std::set<std::string>{"ps20b"}) << family;
    EXPECT_EQ(binaries_of[std::string(family) + "|ps_2_0"], std::set<std::string>{"ps20"}) << family;
  }
  for (const char* card : {"ps_2_0", "ps_2_b", "ps_3_0"})
    EXPECT_EQ(binaries_of[std::string("filmgrain|") + card], std::set<std::string>{"ps20"}) << card;
  EXPECT_EQ(binaries_of["VertexLitGeneric|ps_3_0"], std::set<std::string>{"ps30"});
  EXPECT_EQ(binaries_of["UnlitGeneric|ps_3_0"], std::set<std::string>{"ps30"});
  // Same binary, same row: the ps_3_0 card's LightmappedGeneric counts are the ps_2_b card's.
  int same = 0;
  for (const auto& [key, c] : table) {
    if (c[0] != "LightmappedGeneric" || c[2] != "ps_3_0") continue;
    const auto b = table.find(c[0] + "|" + c[1] + "|ps_2_b");
    ASSERT_NE(b, table.end()) << key;
    EXPECT_EQ(std::vector<std::string>(c.begin() + 3, c.begin() + 11), std::vector<std::string>(b->second.begin() + 3, b->second.begin() + 11))
        << key;
    ++same;
  }
  EXPECT_GT(same, 10);
  for (const auto& [key, c] : table)
    EXPECT_FALSE(c[0] == "VertexLitGeneric" && c[1].find("+phong") != std::string::npos && c[2] == "ps_2_0") << key;
}

TEST(CostCommand, PrintsOnlyTheVertexShaderWhenAskedFor) {
  const Process run = run_luxel("cost --shader vertexlit_vs --pixels 64 --repeats 1 2>&1");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  int rows = 0;
  const auto table = table_rows(run.out, rows);
  for (const auto& [key, cols] : table) {
    EXPECT_EQ(cols[0], "VertexLitGeneric_vs") << "--shader vertexlit_vs prints " << key;
    EXPECT_TRUE(cols[2] == "vs_2_0" || cols[2] == "vs_3_0") << key;
  }
  int expected = 0;
  for (const VertexLitVsCombo& c : kVertexLitVsSpace)
    for (ShaderModel m : kVertexModels) expected += c.valid(m) ? 1 : 0;
  EXPECT_EQ(rows, expected) << "every vertex-shader combo on each vertex model it exists on (4 lights: vs_3_0 only)";
}

TEST(CostCommand, PrintsTheAmbientCubeCountsAndTheCpu) {
  const Process run = run_luxel("cost --shader luminance --pixels 64 --repeats 1 2>&1");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const AmbientCube cube;
  auto body = [&](CountedInputs& in) { return ambient_light<Counted>(in.vector<3>(), cube); };
  const std::string want = "ambient cube: ps_3_0 " + std::to_string(measure(ShaderModel::ps_3_0, body).arithmetic_slots) +
                           ", ps_2_0 " + std::to_string(measure(ShaderModel::ps_2_0, body).arithmetic_slots) +
                           " (+mov oC0), vs_2_0 " + std::to_string(measure(ShaderModel::vs_2_0, body).arithmetic_slots) +
                           " slots";
  EXPECT_NE(run.out.find(want), std::string::npos) << want << " not in:\n" << run.out;
  EXPECT_EQ(run.out.rfind("cpu: ", 0), 0u) << "the first line names the CPU";
  EXPECT_NE(run.out.find(" family "), std::string::npos) << "with its CPUID family and model";
  EXPECT_NE(run.out.find("texture sampling excluded"), std::string::npos);
  int rows = 0;
  const auto table = table_rows(run.out, rows);
  for (const auto& [key, cols] : table) EXPECT_EQ(cols[0], "LuminanceRange") << "--shader luminance prints " << key;
  EXPECT_GT(rows, 0);
}

/// The '|'-separated rows of `out` with `columns` columns, trimmed, header rows (first column
/// "model") left out.
std::vector<std::vector<std::string>> rows_of(const std::string& out, size_t columns) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(out);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> cols;
    std::istringstream fields(line);
    std::string f;
    while (std::getline(fields, f, '|')) cols.push_back(trim(f));
    if (cols.size() == columns && cols[0] != "model") rows.push_back(cols);
  }
  return rows;
}

// `luxel cost --scene`: per model, the pixels, binary and slots of each combo the frame ran. The post
// passes' pixels follow from the image size alone (the engine's full-screen pass shades each pixel
// once; the downsample, a quarter on each side; the blur, that twice), the geometry's from nothing
// the model changes (the same pixels in the same order on every model), the slots of a combo the
// catalog lists from the catalog's own count, and the totals from the rows.
TEST(CostCommand, SceneFrameCostsPerModelFollowFromTheImageAndTheCatalog) {
  constexpr int kWidth = 96, kHeight = 64;
  const Process run = run_luxel("cost --scene builtin:courtyard --bake quick --width 96 --height 64 --msaa 4 --repeats 1 "
                                "--threads 2 2>/dev/null");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_EQ(run.out.rfind("cpu: ", 0), 0u) << "the first line names the CPU";
  const auto combos = rows_of(run.out, 8), passes = rows_of(run.out, 4), totals = rows_of(run.out, 6);
  std::map<std::string, std::vector<uint64_t>> pixels_in_order;
  std::map<std::string, uint64_t> pixels_of, slot_pixels_of;
  std::map<std::string, double> share_of;
  int from_catalog = 0;
  for (const auto& c : combos) {
    const std::string& model = c[0];
    const uint64_t pixels = std::stoull(c[4]), slots = std::stoull(c[5]), slot_pixels = std::stoull(c[6]);
    EXPECT_EQ(slot_pixels, pixels * slots) << c[1] << " " << c[2];
    pixels_in_order[model].push_back(pixels);
    pixels_of[model] += pixels, slot_pixels_of[model] += slot_pixels;
    share_of[model] += std::stod(c[7]);
    const uint64_t screen = kWidth * kHeight, quarter = (kWidth / 4) * (kHeight / 4);
    if (c[1] == "Engine_Post") {
      EXPECT_EQ(pixels, screen) << model;
    }
    if (c[1] == "Downsample_nohdr") {
      EXPECT_EQ(pixels, quarter) << model;
    }
    if (c[1] == "BlurFilter") {
      EXPECT_EQ(pixels, 2 * quarter) << model;
    }
    for (const ShaderVariant& v : shader_catalog()) {
      const ShaderModel m = parse_pixel_model(model);
      if (v.family != c[1] || v.variant != c[2] || std::find(v.models.begin(), v.models.end(), m) == v.models.end()) continue;
      const ShaderModel binary = *v.builds.binary_for(m);
      EXPECT_EQ(c[3], binary_name(binary)) << model << " " << c[1] << " " << c[2];
      EXPECT_EQ(slots, uint64_t(v.measure(binary).total_slots())) << model << " " << c[1] << " " << c[2];
      ++from_catalog;
    }
  }
  EXPECT_GT(from_catalog, 3) << "some of the frame's combos are the catalog's";
  ASSERT_EQ(pixels_in_order.size(), 3u) << "ps_2_0, ps_2_b and ps_3_0 by default";
  EXPECT_EQ(pixels_in_order["ps_2_0"], pixels_in_order["ps_3_0"]);
  EXPECT_EQ(pixels_in_order["ps_2_b"], pixels_in_order["ps_3_0"]);
  ASSERT_EQ(totals.size(), 3u);
  for (const auto& t : totals) {
    const std::string& model = t[0];
    EXPECT_EQ(std::stoull(t[1]), pixels_of[model]) << model;
    EXPECT_EQ(std::stoull(t[2]), slot_pixels_of[model]) << model;
    EXPECT_NEAR(std::stod(t[3]), double(slot_pixels_of[model]) / double(pixels_of[model]), 0.006) << model;
    EXPECT_NEAR(std::stod(t[4]), double(slot_pixels_of[model]) / (kWidth * kHeight), 0.006) << model;
    EXPECT_GT(std::stod(t[5]), 0.0) << model;
    EXPECT_NEAR(share_of[model], 100.0, 0.05 * double(pixels_in_order[model].size())) << model;
  }
  std::set<std::string> opaque;
  for (const auto& p : passes) {
    EXPECT_GE(std::stod(p[3]), 0.0) << p[0] << " " << p[1];
    if (p[1] == "opaque") opaque.insert(p[0]);
  }
  EXPECT_EQ(opaque.size(), 3u) << "every model's opaque pass is timed";
}

TEST(CostCommand, SceneFrameCostsOfOneModel) {
  const Process run = run_luxel("cost --scene builtin:courtyard --bake quick --width 64 --height 32 --msaa 1 --repeats 1 "
                                "--model ps_2_b 2>/dev/null");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const auto totals = rows_of(run.out, 6);
  ASSERT_EQ(totals.size(), 1u) << run.out;
  EXPECT_EQ(totals[0][0], "ps_2_b");
}

}  // namespace
}  // namespace luxel::shading::source
