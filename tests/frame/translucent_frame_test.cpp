// Translucent meshes in the frame: drawn after the opaque ones, farthest first, whatever order
// the scene lists them in, each blended over the 8-bit target (SrcAlpha, InvSrcAlpha) in linear
// space on the decoded destination (the rasterizer's sRGB-write rule). The expected pixels are
// computed here from the clear colour through the two blends, the target's 8-bit rounding
// included; a frame that drew them in submission order, or nearest first, fails.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

namespace luxel::frame {
namespace {

constexpr int kPaneSide = 64;
const glm::dvec3 kPaneBackground(0.1, 0.2, 0.1);
const glm::dvec4 kFarPane(0.9, 0.2, 0.1, 0.5), kNearPane(0.1, 0.3, 0.9, 0.6);

/// Looking down at two translucent unlit squares: the far one (z = 0) over x in [-1, 0.5], the
/// near one (z = 1) over [-0.5, 1]; `near_first` lists the near one first.
scenes::Scene two_panes(bool near_first) {
  scenes::Scene s = top_down();
  s.background = glm::vec3(kPaneBackground);
  scenes::Material far, near;
  far.family = near.family = scenes::ShaderFamily::unlit_generic;
  far.alpha = near.alpha = scenes::AlphaMode::blend;
  far.color = glm::vec4(kFarPane), near.color = glm::vec4(kNearPane);
  s.materials = {far, near};
  const scenes::Mesh far_mesh = square(-1, -1, 0.5f, 1, 0, 0), near_mesh = square(-0.5f, -1, 1, 1, 1, 1);
  s.meshes = near_first ? std::vector<scenes::Mesh>{near_mesh, far_mesh} : std::vector<scenes::Mesh>{far_mesh, near_mesh};
  return s;
}


/// The 8-bit target after blending `layers` (linear rgb, alpha) in order over the clear colour.
std::array<double, 3> blended(std::initializer_list<glm::dvec4> layers) {
  std::array<double, 3> target{};
  for (int c = 0; c < 3; ++c) target[size_t(c)] = srgb8(kPaneBackground[c]);
  for (const glm::dvec4& l : layers)
    for (int c = 0; c < 3; ++c)
      target[size_t(c)] = srgb8(l.a * l[c] + (1.0 - l.a) * srgb_decode(target[size_t(c)] / 255.0));
  return target;
}

TEST(TranslucentFrame, FarthestFirstInEitherSubmissionOrder) {
  FrameSettings f{kPaneSide, kPaneSide, 1};
  f.exposure = 1.0f;
  f.color_correction = false;
  // Columns: x = -1 + (i + 0.5) / 32; the panes' edges at x = -0.5 (i = 16) and 0.5 (i = 48).
  const auto far_only = blended({kFarPane}), both = blended({kFarPane, kNearPane}), near_only = blended({kNearPane});
  const auto wrong = blended({kNearPane, kFarPane});
  ASSERT_GT(std::abs(both[0] - wrong[0]) + std::abs(both[2] - wrong[2]), 20.0) << "the order must matter";
  for (bool near_first : {false, true}) {
    SCOPED_TRACE(near_first ? "near listed first" : "far listed first");
    const rasterizer::Image image = render_frame(two_panes(near_first), f);
    EXPECT_EQ(channels_off(image, 0, 15, far_only), 0);
    EXPECT_EQ(channels_off(image, 17, 47, both), 0) << "the overlap: far, then near over it";
    EXPECT_EQ(channels_off(image, 49, 64, near_only), 0);
  }
}

}  // namespace
}  // namespace luxel::frame
