// `luxel compare` checked by what it writes: the same PREFIX.png bytes and the same numbers in
// PREFIX.json (all but the timings) for 1 and 2 threads; a pair for every two models, in order;
// the JSON's numbers consistent with each other (slots per pixel from the shader uses it lists,
// a PSNR exactly when the frames differ) and the stdout table holding the same pairs.

#include "cli/run_luxel.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <unistd.h>

namespace luxel::cli {
namespace {

using test::run_luxel;

class CompareCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() / ("luxel-compare-" + std::string(info->name()) + "-" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string prefix(const std::string& name) const { return (dir_ / name).string(); }

  /// Runs compare on a small courtyard frame (every Source family, models that differ); its stdout.
  std::string compare(const std::string& out, const std::string& extra) const {
    const test::Process run = run_luxel("compare --scene builtin:courtyard --bake quick --width 96 --height 64 --msaa 4 --frames 1 --out " +
                                        prefix(out) + " " + extra + " 2>/dev/null");
    EXPECT_EQ(run.exit_code, 0) << run.out;
    return run.out;
  }

  std::filesystem::path dir_;
};

std::string bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  return nlohmann::json::parse(f);
}

/// The JSON without what may change from run to run: timings and the thread count.
nlohmann::json without_timings(nlohmann::json j) {
  j.erase("threads");
  for (auto& m : j["models"]) m.erase("ms_per_frame"), m.erase("ms_min"), m.erase("ms_max");
  for (auto& p : j["pairs"]) p.erase("ms_per_frame");
  return j;
}

TEST_F(CompareCommand, SameSheetAndNumbersForOneAndTwoThreads) {
  compare("one", "--threads 1");
  compare("two", "--threads 2");
  const std::string sheet = bytes(prefix("one") + ".png");
  ASSERT_GT(sheet.size(), 100u);
  EXPECT_TRUE(sheet == bytes(prefix("two") + ".png")) << "the sheets differ";
  EXPECT_EQ(without_timings(read_json(prefix("one") + ".json")), without_timings(read_json(prefix("two") + ".json")));
}

TEST_F(CompareCommand, APairForEveryTwoModelsInOrderWithConsistentNumbers) {
  const std::string table = compare("all", "--threads 2");
  const nlohmann::json j = read_json(prefix("all") + ".json");
  EXPECT_EQ(j["scene"], "builtin:courtyard");
  EXPECT_EQ(j["width"], 96);
  EXPECT_EQ(j["frames"], 1);
  ASSERT_EQ(j["models"].size(), 3u);
  EXPECT_EQ(j["models"][0]["model"], "ps_2_0");
  EXPECT_EQ(j["models"][1]["model"], "ps_2_b");
  EXPECT_EQ(j["models"][2]["model"], "ps_3_0");
  for (const auto& m : j["models"]) {
    EXPECT_GT(m["ms_per_frame"].get<double>(), 0.0);
    // Slots per pixel: sum(pixels x slots) / sum(pixels) of the listed combos, null without any.
    double pixels = 0, slots = 0;
    for (const auto& u : m["shader_uses"]) {
      pixels += u["pixels"].get<double>();
      slots += u["pixels"].get<double>() * u["slots"].get<double>();
    }
    if (pixels == 0) EXPECT_TRUE(m["slots_per_pixel"].is_null()) << m;
    else EXPECT_NEAR(m["slots_per_pixel"].get<double>(), slots / pixels, 1e-9) << m;
  }
  const char* expected[][2] = {{"ps_2_0", "ps_2_b"}, {"ps_2_0", "ps_3_0"}, {"ps_2_b", "ps_3_0"}};
  ASSERT_EQ(j["pairs"].size(), 3u);
  // ps_2_0 runs simpler combos than ps_2_b, so the first pair has numbers to check.
  EXPECT_GT(j["pairs"][0]["differing_pixels"].get<uint64_t>(), 0u);
  EXPECT_GT(j["pairs"][0]["psnr_db"].get<double>(), 0.0);
  for (size_t i = 0; i < 3; ++i) {
    const nlohmann::json& p = j["pairs"][i];
    EXPECT_EQ(p["a"], expected[i][0]);
    EXPECT_EQ(p["b"], expected[i][1]);
    const uint64_t differing = p["differing_pixels"];
    EXPECT_NEAR(p["differing_share"].get<double>(), differing / (96.0 * 64.0), 1e-12);
    EXPECT_EQ(p["psnr_db"].is_null(), differing == 0) << p;
    EXPECT_EQ(p["max_error_steps"].get<int>() == 0, differing == 0) << p;
    EXPECT_EQ(p["mean_error_steps"].get<double>() == 0, differing == 0) << p;
    const auto side = [&](const char* name) {
      for (const auto& m : j["models"])
        if (m["model"] == name) return m;
      return nlohmann::json();
    };
    EXPECT_EQ(p["slots_per_pixel"][0], side(expected[i][0])["slots_per_pixel"]);
    EXPECT_EQ(p["slots_per_pixel"][1], side(expected[i][1])["slots_per_pixel"]);
    EXPECT_EQ(p["ms_per_frame"][0], side(expected[i][0])["ms_per_frame"]);
    EXPECT_NE(table.find(std::string(expected[i][0]) + " vs " + expected[i][1]), std::string::npos) << table;
  }
}

TEST_F(CompareCommand, TwoModelsMakeOnePair) {
  const std::string table = compare("two_models", "--models ps_3_0,ps_2_0");
  const nlohmann::json j = read_json(prefix("two_models") + ".json");
  ASSERT_EQ(j["pairs"].size(), 1u);
  EXPECT_EQ(j["pairs"][0]["a"], "ps_3_0");
  EXPECT_EQ(j["pairs"][0]["b"], "ps_2_0");
  EXPECT_NE(table.find("ps_3_0 vs ps_2_0"), std::string::npos) << table;
  EXPECT_EQ(table.find("ps_2_b"), std::string::npos) << table;
}

}  // namespace
}  // namespace luxel::cli
