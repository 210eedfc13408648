// Determinism of whole frames: the built-in `fill` and `tris` scenes (at reduced size) resolve to
// identical bytes, and report identical stats, with 1, 2, 3 and 8 threads, frame after frame.

#include "luxel/frame/builtin.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace luxel::frame {
namespace {

struct Frame {
  std::vector<uint8_t> rgba;
  rasterizer::DrawStats stats;
};

Frame render(std::string_view name, const FrameSettings& settings, int threads, int frames) {
  rasterizer::Context ctx(threads);
  auto scene = make_builtin_scene(name, settings);
  Frame f;
  for (int i = 0; i < frames; ++i) {
    scene->render(ctx);
    if (i > 0) {
      EXPECT_TRUE(scene->image().rgba == f.rgba) << name << ": frame " << i << " differs from frame 0";
    }
    f.rgba = scene->image().rgba;
    f.stats = scene->stats();
  }
  return f;
}

bool same_stats(const rasterizer::DrawStats& a, const rasterizer::DrawStats& b) {
  return a.triangles == b.triangles && a.bad_index == b.bad_index && a.non_finite == b.non_finite &&
         a.outside == b.outside && a.clipped == b.clipped && a.clip_overflow == b.clip_overflow &&
         a.culled == b.culled && a.degenerate == b.degenerate &&
         a.rasterized == b.rasterized && a.stamps_full == b.stamps_full && a.stamps_partial == b.stamps_partial &&
         a.stamps_wide_edges == b.stamps_wide_edges && a.stamps_shaded == b.stamps_shaded;
}

void check(std::string_view name, const FrameSettings& settings) {
  const Frame one = render(name, settings, 1, 2);
  ASSERT_EQ(one.rgba.size(), size_t(settings.width) * settings.height * 4);
  // Not a blank image: the scene drew something.
  bool varied = false;
  for (size_t i = 4; i < one.rgba.size() && !varied; ++i) varied = one.rgba[i] != one.rgba[i % 4];
  EXPECT_TRUE(varied) << name;
  for (int threads : {2, 3, 8}) {
    const Frame f = render(name, settings, threads, 2);
    EXPECT_TRUE(f.rgba == one.rgba) << name << " " << settings.width << "x" << settings.height << "x" << settings.samples
                                    << ": " << threads << " threads differ from 1 thread";
    EXPECT_TRUE(same_stats(f.stats, one.stats)) << name << ": stats differ with " << threads << " threads";
  }
}

#if defined(__SANITIZE_ADDRESS__) || !defined(__OPTIMIZE__)
constexpr bool kReduced = true;
#else
constexpr bool kReduced = false;
#endif

TEST(FrameDeterminism, FillScene) {
  check("fill", {200, 120, 4});
  check("fill", {131, 67, 1});
}

TEST(FrameDeterminism, TrisScene) {
  check("tris", {kReduced ? 96 : 320, kReduced ? 64 : 180, 4});
  if (!kReduced) check("tris", {131, 67, 8});
}

TEST(FrameDeterminism, UnknownScenesAndBadSettingsThrow) {
  EXPECT_THROW(make_builtin_scene("no-such-scene", {}), std::invalid_argument);
  EXPECT_THROW(make_builtin_scene("fill", {0, 10, 1}), std::invalid_argument);
  EXPECT_THROW(make_builtin_scene("fill", {10, 10, 3}), std::invalid_argument);
}

}  // namespace
}  // namespace luxel::frame
