// The built-in scenes render to the same bytes with every fast path on, all off, and each one
// off alone (fast_paths.hpp): a fast path may change the time and the stats, never the image.

#include "frame/frame_support.hpp"
#include "luxel/rasterizer/fast_paths.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace luxel::frame {
namespace {

using rasterizer::FastPath;
using rasterizer::FastPaths;

std::vector<uint8_t> render(std::string_view name, const FrameSettings& settings, FastPaths paths,
                            rasterizer::DrawStats* stats = nullptr) {
  rasterizer::ContextOptions options;
  options.threads = 2;
  options.fast_paths = paths;
  RenderedFrame f = render_builtin(name, settings, options);
  if (stats) *stats = f.stats;
  return f.image.rgba;
}

void check_fast_paths(std::string_view name, const FrameSettings& settings) {
  rasterizer::DrawStats all_on_stats, all_off_stats;
  const std::vector<uint8_t> all_on = render(name, settings, FastPaths(), &all_on_stats);
  EXPECT_EQ(render(name, settings, FastPaths::none(), &all_off_stats), all_on) << name << ": all fast paths off";
  // The switches reached the rasterizer: with all off, no triangle took the small walk and no
  // stamp skipped its edge tests.
  EXPECT_GT(all_on_stats.small_walks + all_on_stats.stamps_full, 0u) << name;
  EXPECT_EQ(all_off_stats.small_walks + all_off_stats.stamps_full, 0u) << name;
  EXPECT_EQ(all_off_stats.stamps_wide_edges, all_off_stats.stamps_partial) << name;
  for (const rasterizer::FastPathName& p : rasterizer::kFastPathNames)
    EXPECT_EQ(render(name, settings, FastPaths::all_but(p.path)), all_on) << name << ": " << p.name << " off";
}

// Each switch keeps the bytes; a test per scene, so that gtest's shards share them out.
TEST(FrameFastPaths, FillKeepsTheBytes) { check_fast_paths("fill", {kReduced ? 96 : 200, kReduced ? 64 : 120, 4}); }
TEST(FrameFastPaths, TrisKeepsTheBytes) { check_fast_paths("tris", {kReduced ? 96 : 256, kReduced ? 64 : 144, 4}); }
TEST(FrameFastPaths, DemoKeepsTheBytes) {
  check_fast_paths("demo", {kReduced ? 96 : 200, kReduced ? 64 : 120, 4});
  check_fast_paths("demo", {131, 67, 1});
}
TEST(FrameFastPaths, CourtyardKeepsTheBytes) { check_fast_paths("courtyard", {kReduced ? 96 : 200, kReduced ? 64 : 120, 4}); }

}  // namespace
}  // namespace luxel::frame
