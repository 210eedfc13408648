// Grades: each operator against numbers worked out by hand from its definition (grade.hpp), the
// clamp between layers, parameter checks naming the operator, and the presets' looks measured on
// the engine's lattice (darker and bluer by night, nearly grey and faded when archival, warm and
// cool casts on grey).

#include "luxel/postfx/grade.hpp"
#include "luxel/postfx/lut.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace luxel::postfx {
namespace {

glm::vec3 graded(const GradeOperator& op, glm::vec3 c) { return apply_grade(Grade{{op}}, c); }

TEST(Grade, LevelsMapsInputRangeThroughGammaOntoOutputRange) {
  const Levels l{0.1f, 0.8f, 2.0f, 0.05f, 0.9f};
  // x = 0.45: (0.45 - 0.1) / 0.7 = 0.5, 0.5^(1/2) = 0.70711, 0.05 + 0.85 * 0.70711 = 0.65104.
  EXPECT_NEAR(graded(l, glm::vec3(0.45f)).x, 0.651041f, 1e-5f);
  EXPECT_NEAR(graded(l, glm::vec3(0.05f)).y, 0.05f, 1e-6f) << "below in_black: out_black";
  EXPECT_NEAR(graded(l, glm::vec3(0.95f)).z, 0.9f, 1e-6f) << "above in_white: out_white";
}

TEST(Grade, ColorBalanceWeighsOffsetsByTheLumasBernsteinBasis) {
  const ColorBalance b{{0.1f, 0.0f, 0.0f}, {0.0f, 0.1f, 0.0f}, {0.0f, 0.0f, 0.1f}};
  // c = (0.2, 0.4, 0.6): L = 0.0598 + 0.2348 + 0.0684 = 0.363; (1-L)^2 = 0.405769,
  // 2L(1-L) = 0.462462, L^2 = 0.131769.
  const glm::vec3 out = graded(b, glm::vec3(0.2f, 0.4f, 0.6f));
  EXPECT_NEAR(out.x, 0.2405769f, 1e-6f);
  EXPECT_NEAR(out.y, 0.4462462f, 1e-6f);
  EXPECT_NEAR(out.z, 0.6131769f, 1e-6f);
}

TEST(Grade, SaturationScalesTheDistanceFromTheLuma) {
  const glm::vec3 c(0.2f, 0.4f, 0.6f);  // L = 0.363
  const glm::vec3 grey = graded(Saturation{0.0f}, c);
  EXPECT_NEAR(grey.x, 0.363f, 1e-6f);
  EXPECT_NEAR(grey.z, 0.363f, 1e-6f);
  const glm::vec3 vivid = graded(Saturation{1.5f}, c);  // 0.363 + 1.5 (c - 0.363)
  EXPECT_NEAR(vivid.x, 0.1185f, 1e-6f);
  EXPECT_NEAR(vivid.y, 0.4185f, 1e-6f);
  EXPECT_NEAR(vivid.z, 0.7185f, 1e-6f);
}

TEST(Grade, CurvesAreMonotoneCubicsThroughTheirPoints) {
  // (0, 0), (0.5, 0.8), (1, 1): secants 1.6 and 0.4, tangents 1.6, 1.0, 0.4 (no Fritsch-Carlson
  // limiting needed). Hermite at t = 0.5 of each interval, h = 0.5:
  //   x = 0.25: 0.5 * 0 + 0.125 * 0.5 * 1.6 + 0.5 * 0.8 - 0.125 * 0.5 * 1.0 = 0.4375
  //   x = 0.75: 0.5 * 0.8 + 0.125 * 0.5 * 1.0 + 0.5 * 1 - 0.125 * 0.5 * 0.4 = 0.9375
  const Curve curve{{{0.0f, 0.0f}, {0.5f, 0.8f}, {1.0f, 1.0f}}};
  EXPECT_NEAR(curve(0.25f), 0.4375f, 1e-6f);
  EXPECT_NEAR(curve(0.75f), 0.9375f, 1e-6f);
  EXPECT_EQ(curve(0.5f), 0.8f);
  const Curve line{{{0.2f, 0.1f}, {0.4f, 0.3f}, {0.8f, 0.7f}}};
  for (float x : {0.25f, 0.5f, 0.63f}) EXPECT_NEAR(line(x), x - 0.1f, 1e-6f) << "collinear points give their line";
  EXPECT_EQ(line(0.1f), 0.1f) << "flat before the first point";
  EXPECT_EQ(line(0.9f), 0.7f) << "flat after the last";
  // A steep step: a plain cubic spline would overshoot past 0.9 and dip below 0; this one stays monotone.
  const Curve step{{{0.0f, 0.0f}, {0.1f, 0.9f}, {1.0f, 1.0f}}};
  float previous = 0.0f;
  for (int i = 0; i <= 1000; ++i) {
    const float y = step(i / 1000.0f);
    EXPECT_GE(y, previous) << i;
    EXPECT_LE(y, 1.0f) << i;
    previous = y;
  }
  // Per channel after the master curve.
  const Curves curves{Curve{{{0.0f, 0.0f}, {1.0f, 0.5f}}}, {}, Curve{{{0.0f, 1.0f}, {1.0f, 0.0f}}}, {}};
  const glm::vec3 out = graded(curves, glm::vec3(0.8f, 0.8f, 0.2f));
  EXPECT_NEAR(out.x, 0.4f, 1e-6f);
  EXPECT_NEAR(out.y, 0.6f, 1e-6f) << "master 0.4, then green inverted";
  EXPECT_NEAR(out.z, 0.1f, 1e-6f);
}

TEST(Grade, EachLayerIsClampedBeforeTheNext) {
  // The balance pushes red to 0.9 + 0.5 * 0.81 = 1.305, clamped to 1; the luma of (1, 0.9, 0.9)
  // is 0.9299 (unclamped it would be 1.0211, and grey would come out as 1).
  const Grade g{{ColorBalance{{0, 0, 0}, {0, 0, 0}, {0.5f, 0.0f, 0.0f}}, Saturation{0.0f}}};
  EXPECT_NEAR(apply_grade(g, glm::vec3(0.9f)).x, 0.9299f, 1e-5f);
}

TEST(Grade, ParametersOutOfRangeAreRefusedNamingTheOperator) {
  auto refused = [](GradeOperator op, const std::string& words) {
    try {
      grade_transform(Grade{{op}}, "test");
      ADD_FAILURE() << words << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused(Levels{0.5f, 0.5f}, "levels: in_black must be below in_white");
  refused(Levels{0.0f, 1.0f, 0.0f}, "levels: gamma");
  refused(Levels{0.0f, 1.0f, 1.0f, 0.0f, INFINITY}, "levels: every value must be finite");
  refused(ColorBalance{{0.0f, std::nanf(""), 0.0f}, {}, {}}, "color balance: every offset must be finite");
  refused(Saturation{-1.0f}, "saturation");
  refused(Curves{Curve{{{0.0f, 0.0f}}}, {}, {}, {}}, "curves: master curve needs at least two points");
  refused(Curves{{}, Curve{{{0.5f, 0.0f}, {0.5f, 1.0f}}}, {}, {}}, "curves: red curve needs strictly increasing x");
  refused(Curves{{}, {}, {}, Curve{{{0.0f, 0.0f}, {1.0f, 1.5f}}}}, "curves: blue curve has a point outside");
}

TEST(Grade, AnEmptyGradeSamplesToTheIdentityLut) {
  EXPECT_EQ(sample_lut(grade_transform(Grade{}, "none")), Lut::identity());
  EXPECT_EQ(Lut::identity().at(1, 30, 31), (Lut::Color24{8, 247, 255})) << "round(255 i / 31)";
}

/// Mean luma, mean chroma (max - min) and mean blue-minus-red of the LUT's entries, over 255.
struct LutLook {
  double luma = 0, chroma = 0, blue_minus_red = 0;
};
LutLook look_of(const Lut& lut) {
  LutLook s;
  for (const Lut::Color24& e : lut.entries) {
    const glm::vec3 c = glm::vec3(e[0], e[1], e[2]) / 255.0f;
    s.luma += grade_luma(c);
    s.chroma += std::max({c.x, c.y, c.z}) - std::min({c.x, c.y, c.z});
    s.blue_minus_red += c.z - c.x;
  }
  const double n = double(lut.entries.size());
  return {s.luma / n, s.chroma / n, s.blue_minus_red / n};
}

TEST(Grade, PresetsHaveTheirLooks) {
  const LutLook neutral = look_of(Lut::identity());
  auto preset = [](const char* name) { return sample_lut(grade_transform(*grade_preset(name), name)); };
  const LutLook night = look_of(preset("day-for-night"));
  EXPECT_LT(night.luma, neutral.luma / 3.0) << "dark";
  EXPECT_LT(night.chroma, neutral.chroma * 0.4) << "desaturated";
  EXPECT_GT(night.blue_minus_red, 0.01) << "blue";
  const Lut archival = preset("archival");
  EXPECT_LT(look_of(archival).chroma, neutral.chroma * 0.3) << "nearly grey";
  EXPECT_GE(archival.at(0, 0, 0)[1], 15) << "faded blacks";
  EXPECT_LE(archival.at(31, 31, 31)[1], 240) << "faded whites";
  const Lut::Color24 warm = preset("warm").at(16, 16, 16), cool = preset("cool").at(16, 16, 16);
  EXPECT_GT(warm[0], warm[2] + 15) << "warm grey is red over blue";
  EXPECT_GT(cool[2], cool[0] + 15) << "cool grey is blue over red";
  EXPECT_FALSE(grade_preset("sepia").has_value());
}

}  // namespace
}  // namespace luxel::postfx
