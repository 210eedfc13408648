// UvTransform (scene.hpp) against KHR_texture_transform's own definition: uv' = T R S uv with
// the extension's 3x3 matrices, multiplied out here in double. The inputs are off every axis, so
// a rotation applied the other way, or scale and rotation swapped, land elsewhere.

#include "luxel/scenes/scene.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace luxel::scenes::test {
namespace {

using Matrix = double[3][3];

void multiply(const Matrix& a, const Matrix& b, Matrix& out) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      out[r][c] = 0.0;
      for (int k = 0; k < 3; ++k) out[r][c] += a[r][k] * b[k][c];
    }
}

TEST(UvTransform, IsTheExtensionsTranslationRotationScale) {
  TextureRef ref;
  ref.offset = {0.1f, -0.3f};
  ref.scale = {1.5f, 0.7f};
  for (float rotation : {0.392699f, -1.2f, 2.5f}) {
    ref.rotation = rotation;
    const double c = std::cos(double(rotation)), s = std::sin(double(rotation));
    // As the extension's README writes them, row by row.
    const Matrix translation = {{1, 0, ref.offset.x}, {0, 1, ref.offset.y}, {0, 0, 1}};
    const Matrix rotate = {{c, s, 0}, {-s, c, 0}, {0, 0, 1}};
    const Matrix scale = {{ref.scale.x, 0, 0}, {0, ref.scale.y, 0}, {0, 0, 1}};
    Matrix tr, trs;
    multiply(translation, rotate, tr);
    multiply(tr, scale, trs);
    const UvTransform transform = UvTransform::of(ref);
    for (glm::vec2 uv : {glm::vec2(0.25f, 0.8f), glm::vec2(-0.6f, 0.35f), glm::vec2(1.0f, 0.0f)}) {
      const double u = trs[0][0] * uv.x + trs[0][1] * uv.y + trs[0][2];
      const double v = trs[1][0] * uv.x + trs[1][1] * uv.y + trs[1][2];
      const glm::vec2 got = transform(uv);
      EXPECT_NEAR(got.x, u, 1e-6) << "rotation " << rotation << " uv " << uv.x << ", " << uv.y;
      EXPECT_NEAR(got.y, v, 1e-6) << "rotation " << rotation << " uv " << uv.x << ", " << uv.y;
    }
  }
}

TEST(UvTransform, TheDefaultChangesNothing) {
  const UvTransform identity = UvTransform::of(TextureRef{});
  EXPECT_EQ(identity(glm::vec2(0.3f, -2.5f)), glm::vec2(0.3f, -2.5f));
}

}  // namespace
}  // namespace luxel::scenes::test
