// Two `luxel bake` runs of one scene into one folder at once, as a script's loop or ctest -j
// starts them: the bake folder's lock makes one bake and the other wait and reuse what it kept,
// so both succeed, exactly one bakes, and the folder holds one whole bake. Without the lock both
// bake and write the same files while the other reads them (a CI run failed so).

#include "test_paths.hpp"
#include "cli/run_luxel.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace luxel::cli {
namespace {

using test::file_text;
using test::Process;
using test::run_luxel;

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(BakeFolder, TwoBakesAtOnceBakeOnceAndBothSucceed) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("luxel-bake-folder-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string bake = luxel::test::luxel_binary() + " bake --scene builtin:courtyard --quick --threads 1 --out " +
                           (dir / "bake").string();
  const std::string a = (dir / "a.txt").string(), b = (dir / "b.txt").string();
  const std::string script = "(" + bake + " > " + a + " 2>&1; echo exit=$? >> " + a + ") & (" + bake + " > " + b +
                             " 2>&1; echo exit=$? >> " + b + ") & wait";
  ASSERT_EQ(std::system(script.c_str()), 0);
  const std::string out = file_text(a) + file_text(b);
  EXPECT_EQ(occurrences(out, "exit=0"), 2u) << out;
  EXPECT_EQ(occurrences(out, "builtin:courtyard: baked in"), 1u) << out;
  EXPECT_EQ(occurrences(out, "up to date in"), 1u) << out;
  // What they left is a whole bake: a third run reuses it.
  EXPECT_NE(run_luxel("bake --scene builtin:courtyard --quick --out " + (dir / "bake").string()).out.find("up to date in"),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

// A bake folder whose flat lightmap was damaged (a disk error, a copy cut short, a hand edit):
// the next run says which file and why on one warning line, bakes again, keeps the new bake, and
// the run after it finds that one whole.
TEST(BakeFolder, ADamagedMapIsNamedAndBakedAgain) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("luxel-bake-damaged-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const std::string bake = "bake --scene builtin:demo --quick --threads 2 --out " + (dir / "bake").string();
  ASSERT_EQ(run_luxel(bake + " 2>/dev/null").exit_code, 0);
  const std::filesystem::path flat = dir / "bake" / "lightmap_flat.exr";
  ASSERT_TRUE(std::filesystem::is_regular_file(flat));
  {
    std::ofstream damage(flat, std::ios::binary | std::ios::trunc);
    damage << "not an OpenEXR file";
  }
  const Process again = run_luxel(bake + " 2>&1");
  EXPECT_EQ(again.exit_code, 0) << again.out;
  std::string warning;
  std::istringstream lines(again.out);
  for (std::string line; std::getline(lines, line);)
    if (line.find("warning") != std::string::npos) warning = line;
  EXPECT_NE(warning.find("lightmap_flat.exr"), std::string::npos) << again.out;
  EXPECT_NE(warning.find("; baking again"), std::string::npos) << again.out;
  EXPECT_NE(again.out.find("builtin:demo: baked in"), std::string::npos) << again.out;
  EXPECT_NE(run_luxel(bake + " 2>&1").out.find("up to date in"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace luxel::cli
