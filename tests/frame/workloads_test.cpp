// The peer workloads W1 `fill` and W2 `tris` as scenes: the frame draws them to the bytes the
// renderer that owned them drew before they became scene data (frame/src/workload_scenes.cpp, at
// main 2082e6a), and to what the peer's definition says (bench/README.md).

#include "frame/frame_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace luxel::frame {
namespace {

/// FNV-1a, 64 bits, of the image's bytes.
uint64_t fnv1a(const std::vector<uint8_t>& bytes) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (uint8_t b : bytes) h = (h ^ b) * 0x100000001b3ull;
  return h;
}

// The whole workload, as the peer draws it (render_builtin keeps fewer of tris's triangles where
// kReduced).
rasterizer::Image render(std::string_view name, const FrameSettings& settings) {
  return render_frame(scenes::make_builtin_scene(name, {settings.width, settings.height}), settings, 2);
}

// Hashes of the images main 2082e6a rendered (its `luxel render`, PNGs decoded to RGBA8).
TEST(Workloads, FillBytesAsBeforeTheMove) {
  EXPECT_EQ(fnv1a(render("fill", {131, 67, 1}).rgba), 0x6584251ccadee4fdull);
  EXPECT_EQ(fnv1a(render("fill", {96, 64, 4}).rgba), 0xcffaebe5df9f4525ull);
  EXPECT_EQ(fnv1a(render("fill", {200, 120, 4}).rgba), 0x0c8389c1f9c7d985ull);
}

TEST(Workloads, TrisBytesAsBeforeTheMove) {
  EXPECT_EQ(fnv1a(render("tris", {96, 64, 4}).rgba), 0xe3618f95e15d9261ull);
  EXPECT_EQ(fnv1a(render("tris", {131, 67, 1}).rgba), 0x51ad19201914c387ull);
}

// The peer's frame is clear, draw, resolve (its README: "What one frame is"): the workloads' frames
// run no pass on the finished image (their scenes fix the exposure, so no histogram), which the
// frame benchmark would otherwise time against the peer's.
TEST(Workloads, FramesAreDrawAndResolveOnly) {
  for (const char* name : {"fill", "tris"}) {
    FrameSettings settings{64, 36, 4};
    settings.time_passes = true;
    const scenes::Scene scene = scenes::make_builtin_scene(name, {settings.width, settings.height});
    Renderer renderer(scene, settings);
    rasterizer::ContextOptions one_thread;
    one_thread.threads = 1;
    rasterizer::Context ctx(one_thread);
    for (int frame = 0; frame < 2; ++frame) renderer.render(ctx);
    std::vector<std::string> passes;
    for (const PassTime& p : renderer.pass_times()) passes.push_back(p.pass);
    EXPECT_EQ(passes, (std::vector<std::string>{"opaque", "resolve"})) << name;
  }
}

// The peer: "The final image is layer 7: orange, 0.9x at the left edge ramping to 1.0x at the
// right", written as it is (no sRGB), the ramp's u interpolated at pixel centers.
TEST(Workloads, FillIsLayerSevenRamped) {
  const int w = 160, h = 90;
  const rasterizer::Image image = render("fill", {w, h, 1});
  const double color[3] = {0.95, 0.55, 0.15};
  int off = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const double expected = 255.0 * color[c] * (0.9 + 0.1 * (x + 0.5) / w);
        off += std::abs(image.pixel(x, y)[c] - expected) > 0.5 + 1e-3;
      }
  EXPECT_EQ(off, 0);
}

// Every tris pixel is the clear color (0.1 -> byte 26) or a triangle's, whose channels the
// generator draws from 64..255; and at the peer's size about 4% of the pixels stay background
// (3 M pixels^2 of triangles on 0.92 M pixels: exp(-3.3) uncovered).
TEST(Workloads, TrisPixelsAreBackgroundOrTriangleColors) {
  const int w = 1280, h = 720;
  const rasterizer::Image image = render("tris", {w, h, 1});
  int background = 0, other = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = image.pixel(x, y);
      if (p[0] == 26 && p[1] == 26 && p[2] == 26) ++background;
      else if (p[0] < 64 || p[1] < 64 || p[2] < 64 || p[3] != 255) ++other;
    }
  EXPECT_EQ(other, 0);
  EXPECT_GT(background, w * h * 2 / 100);
  EXPECT_LT(background, w * h * 7 / 100);
}

}  // namespace
}  // namespace luxel::frame
