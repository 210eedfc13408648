// Exposure zones: which controls hold where, and what validate refuses.

#include "luxel/scenes/scene.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace luxel::scenes {
namespace {

Scene zoned() {
  Scene s;
  s.name = "zones";
  s.exposure.min_scale = 0.5f, s.exposure.max_scale = 2.0f;
  ExposureZone cave{{0, 0, 0}, {100, 100, 50}, {}};
  cave.exposure.min_scale = 1.0f, cave.exposure.max_scale = 8.0f;
  ExposureZone sunlit_room{{50, 50, 0}, {80, 80, 50}, {}};  // inside the cave's box, later: it wins
  sunlit_room.exposure.min_scale = sunlit_room.exposure.max_scale = 0.75f;
  s.exposure_zones = {cave, sunlit_room};
  return s;
}

TEST(ExposureZones, TheLastZoneHoldingThePointWinsElseTheScenes) {
  const Scene s = zoned();
  EXPECT_EQ(exposure_at(s, {10, 10, 10}).max_scale, 8.0f);
  EXPECT_EQ(exposure_at(s, {60, 60, 10}).max_scale, 0.75f);
  EXPECT_EQ(exposure_at(s, {100, 100, 50}).max_scale, 8.0f) << "bounds are inclusive";
  EXPECT_EQ(exposure_at(s, {100.01f, 50, 10}).max_scale, 2.0f);
  EXPECT_EQ(exposure_at(s, {-1, 50, 10}).max_scale, 2.0f);
  EXPECT_NO_THROW(validate(s));
}

TEST(ExposureZones, ValidateRefusesBadBoundsAndValues) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Scene s = zoned();
  s.exposure_zones[0].min.x = 200;  // min > max
  EXPECT_THROW(validate(s), std::invalid_argument);
  s = zoned();
  s.exposure_zones[1].max.z = nan;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s = zoned();
  s.exposure_zones[1].exposure.rate = -1.0f;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s = zoned();
  s.exposure.max_scale = std::numeric_limits<float>::infinity();
  EXPECT_THROW(validate(s), std::invalid_argument);
  s = zoned();
  s.exposure.min_scale = 0.0f;
  EXPECT_THROW(validate(s), std::invalid_argument);
}

}  // namespace
}  // namespace luxel::scenes
