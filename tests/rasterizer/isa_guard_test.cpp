// The CPU check every program runs first (isa_guard.hpp): what the build asks for, and what it
// reports on a CPU that lacks some of it.
#include "luxel/rasterizer/isa_guard.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "luxel/rasterizer/simd.hpp"

namespace luxel::rasterizer {
namespace {

std::vector<std::string> build_extensions() {
  std::vector<std::string> names;
  for (const char* const* e = kBuildIsaExtensions; *e; ++e) names.emplace_back(*e);
  return names;
}

bool has(const std::vector<std::string>& names, const char* name) {
  for (const auto& n : names) {
    if (n == name) return true;
  }
  return false;
}

TEST(IsaGuard, TheBuildAsksForWhatItsLanesUse) {
  const auto names = build_extensions();
  const std::string isa = simd::kIsaName;
  EXPECT_EQ(has(names, "avx2"), isa == "avx2" || isa == "avx512");
  EXPECT_EQ(has(names, "fma"), isa == "avx2" || isa == "avx512");
  EXPECT_EQ(has(names, "avx512f"), isa == "avx512");
  EXPECT_EQ(has(names, "avx512bw"), simd::kLanes == 16);
  EXPECT_EQ(has(names, "sse4.2"), isa != "portable");
}

TEST(IsaGuard, ThisCpuRunsThisBuild) {
  char missing[256] = "untouched";
  EXPECT_EQ(missing_isa_extensions(cpu_has_extension, missing, sizeof missing), 0) << missing;
  EXPECT_STREQ(missing, "");
  for (const auto& name : build_extensions()) EXPECT_TRUE(cpu_has_extension(name.c_str())) << name;
  EXPECT_FALSE(cpu_has_extension("no-such-extension"));
}

// A CPU with SSE4.2 and AVX but nothing later: the guard names everything after them, in the
// build's order, and truncates to the buffer without overrunning it.
bool sandy_bridge_like(const char* name) {
  return std::strcmp(name, "sse4.2") == 0 || std::strcmp(name, "popcnt") == 0 || std::strcmp(name, "avx") == 0;
}

TEST(IsaGuard, NamesWhatAnOlderCpuLacks) {
  std::string expected;
  int count = 0;
  for (const auto& name : build_extensions()) {
    if (sandy_bridge_like(name.c_str())) continue;
    expected += (count++ ? ", " : "") + name;
  }
  if (count == 0) GTEST_SKIP() << "this build asks for nothing after AVX";
  char missing[512];
  EXPECT_EQ(missing_isa_extensions(sandy_bridge_like, missing, sizeof missing), count);
  EXPECT_EQ(std::string(missing), expected);
  EXPECT_EQ(expected.substr(0, 4), "avx2");

  char small[7];
  std::memset(small, 'x', sizeof small);
  EXPECT_EQ(missing_isa_extensions(sandy_bridge_like, small, sizeof small), count);
  EXPECT_EQ(std::string(small), expected.substr(0, 6));
}

}  // namespace
}  // namespace luxel::rasterizer
