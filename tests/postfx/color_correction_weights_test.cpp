// Color-correction entity weights (docs/fidelity.md#color-correction) at times and distances
// where each rule of the fades, the falloff, the volume ramps and the choice of four gives a number
// worked out here.

#include "luxel/postfx/color_correction_weights.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace luxel::postfx {
namespace {

TEST(ColorCorrectionWeights, EntitySpawnsAtOneOrDisabledAtZero) {
  EXPECT_EQ(EntityFade({0.8f, 1.0f, 1.0f, false}).weight(0.0), 1.0f) << "1, not max_weight, as the SDK spawns it";
  EXPECT_EQ(EntityFade({0.8f, 1.0f, 1.0f, true}).weight(0.0), 0.0f);
}

TEST(ColorCorrectionWeights, EntityFadesOverTheirDurationsShortenedByTheWayAlreadyGone) {
  EntityFade e({1.0f, 4.0f, 2.0f, false});
  e.disable(10.0);  // from 1 (= max): the full 2 s
  EXPECT_FLOAT_EQ(e.weight(10.5), 0.75f);
  EXPECT_FLOAT_EQ(e.weight(12.0), 0.0f);
  EntityFade f({1.0f, 4.0f, 2.0f, false});
  f.disable(0.0);
  f.enable(1.5);  // from 0.25: 4 s x (1 - 0.25) = 3 s to go up 0.75
  EXPECT_FLOAT_EQ(f.weight(1.5), 0.25f);
  EXPECT_FLOAT_EQ(f.weight(3.0), 0.625f);
  EXPECT_FLOAT_EQ(f.weight(4.5), 1.0f);
  EXPECT_FLOAT_EQ(f.weight(9.0), 1.0f);
  EntityFade g({0.8f, 1.0f, 2.0f, true});
  g.enable(0.0);  // 0 -> 0.8 in 1 s
  EXPECT_FLOAT_EQ(g.weight(0.25), 0.2f);
  g.disable(0.625);  // from 0.5 < max: 2 s x 0.5 / 0.8 = 1.25 s
  EXPECT_FLOAT_EQ(g.weight(1.25), 0.25f);
  EXPECT_FLOAT_EQ(g.weight(1.875), 0.0f);
}

TEST(ColorCorrectionWeights, EntityWithoutFadesJumps) {
  EntityFade e({0.6f, 0.0f, 0.0f, true});
  e.enable(1.0);
  EXPECT_EQ(e.weight(1.0), 0.6f);
  e.disable(2.0);
  EXPECT_EQ(e.weight(2.0), 0.0f);
}

TEST(ColorCorrectionWeights, FalloffIsLinearBetweenMinAndMaxDistance) {
  EXPECT_FLOAT_EQ(falloff_weight(0.8f, 128.0f, 512.0f, 320.0f), 0.4f);
  EXPECT_FLOAT_EQ(falloff_weight(0.8f, 128.0f, 512.0f, 100.0f), 0.8f);
  EXPECT_FLOAT_EQ(falloff_weight(0.8f, 128.0f, 512.0f, 600.0f), 0.0f);
  EXPECT_FLOAT_EQ(falloff_weight(0.8f, 0.0f, 0.0f, 9000.0f), 0.8f) << "equal falloffs: everywhere";
  EXPECT_FLOAT_EQ(falloff_weight(0.8f, -1.0f, 512.0f, 9000.0f), 0.8f) << "-1: no falloff";
}

TEST(ColorCorrectionWeights, VolumeRampsInAndOut) {
  VolumeFade v(2.0f);
  EXPECT_EQ(v.weight(0.0), 0.0f);
  v.enter(0.0);
  EXPECT_FLOAT_EQ(v.weight(1.0), 0.5f);
  EXPECT_FLOAT_EQ(v.weight(3.0), 1.0f);
  v.leave(3.0);  // from 1: 1 - (t - 3) / 2
  EXPECT_FLOAT_EQ(v.weight(4.0), 0.5f);
  v.enter(4.0);  // from 0.5: 0.5 + (t - 4) / (0.5 x 2)
  EXPECT_FLOAT_EQ(v.weight(4.25), 0.75f);
  v.leave(4.25);  // from 0.75: 1 - min(1, 0.25 + (t - 4.25) / (0.75 x 2))
  EXPECT_FLOAT_EQ(v.weight(4.625), 0.5f);
  EXPECT_FLOAT_EQ(v.weight(9.0), 0.0f);
  VolumeFade instant(0.0f);
  instant.enter(1.0);
  EXPECT_EQ(instant.weight(1.0), 1.0f);
}

TEST(ColorCorrectionWeights, PassBlendsTheFourHeaviest) {
  EXPECT_EQ(heaviest_lookups(std::vector<float>{0.1f, 0.5f, 0.0f, 0.5f, 0.3f, 0.2f}), (std::vector<int>{1, 3, 4, 5}));
  EXPECT_EQ(heaviest_lookups(std::vector<float>{0.0f, std::nanf(""), -0.5f}), std::vector<int>{});
  EXPECT_EQ(heaviest_lookups(std::vector<float>{std::nanf(""), 0.3f, -1.0f, 0.6f}), (std::vector<int>{3, 1}));
  EXPECT_EQ(heaviest_lookups(std::vector<float>{0.2f, 0.7f}), (std::vector<int>{1, 0}));
}

}  // namespace
}  // namespace luxel::postfx
