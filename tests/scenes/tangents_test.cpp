// generate_tangents against tangents worked out by hand on triangles in a tilted plane: the
// texture-space derivative dP/du, its projection onto a vertex's normal plane, angle weighting at
// a shared vertex, handedness of mirrored UVs (and the vertex split it causes).

#include "luxel/scenes/tangents.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>

namespace luxel::scenes::test {
namespace {

void expect_near(glm::vec3 a, glm::vec3 b, float tolerance, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tolerance) << what;
  EXPECT_NEAR(a.y, b.y, tolerance) << what;
  EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

// A plane through O spanned by E1 = (2, 1, -1) and E2 = (0, 1, 2) (not orthogonal to each
// other: E1.E2 = -1, and no axis-aligned). A point O + a E1 + b E2 gets uv (a, 1 - b): u grows
// along E1, glTF's v grows against E2 (v runs down the image). Then dP/du = E1, and the image's
// "up" (decreasing v) is +E2.
const glm::vec3 O(1, -2, 3), E1(2, 1, -1), E2(0, 1, 2);

Mesh plane_triangle(float u_sign) {
  Mesh m;
  const glm::vec2 ab[3] = {{0, 0}, {1, 0}, {0.25f, 1}};
  const glm::vec3 n = glm::normalize(glm::cross(E1, E2));  // (3, -4, 2) / sqrt 29
  for (const glm::vec2& c : ab) {
    m.positions.push_back(O + c.x * E1 + c.y * E2);
    m.normals.push_back(n);
    m.uv0.push_back(glm::vec2(u_sign * c.x, 1.0f - c.y));
  }
  m.indices = std::vector<uint16_t>{0, 1, 2};
  return m;
}

TEST(Tangents, ATiltedTriangleGetsDPduWithPositiveHandedness) {
  Mesh m = plane_triangle(1.0f);
  generate_tangents(m);
  ASSERT_EQ(m.tangents.size(), 3u);
  // E1 / |E1| = (2, 1, -1) / sqrt 6, at every vertex; E1 lies in the plane, so projecting keeps it.
  const float s6 = std::sqrt(6.0f);
  for (int v = 0; v < 3; ++v) {
    expect_near(glm::vec3(m.tangents[v]), glm::vec3(2 / s6, 1 / s6, -1 / s6), 1e-6f, "vertex " + std::to_string(v));
    EXPECT_EQ(m.tangents[v].w, 1.0f);
  }
  // The bitangent w * cross(n, t) points up the image, i.e. along +E2 (positive component).
  const glm::vec3 bitangent = m.tangents[0].w * glm::cross(m.normals[0], glm::vec3(m.tangents[0]));
  EXPECT_GT(glm::dot(bitangent, E2), 0.0f);
}

TEST(Tangents, MirroredUvsGiveNegativeHandedness) {
  Mesh m = plane_triangle(-1.0f);  // u grows against E1
  generate_tangents(m);
  const float s6 = std::sqrt(6.0f);
  for (int v = 0; v < 3; ++v) {
    expect_near(glm::vec3(m.tangents[v]), glm::vec3(-2 / s6, -1 / s6, 1 / s6), 1e-6f, "vertex " + std::to_string(v));
    EXPECT_EQ(m.tangents[v].w, -1.0f);
  }
  // The bitangent still points up the image (+E2) once w is applied.
  const glm::vec3 bitangent = m.tangents[0].w * glm::cross(m.normals[0], glm::vec3(m.tangents[0]));
  EXPECT_GT(glm::dot(bitangent, E2), 0.0f);
}

// A vertex normal tilted out of the plane: the tangent is E1 minus its component along that
// normal, normalized. With n = (0, 0, 1): E1 - (E1.n) n = (2, 1, 0) -> (2, 1, 0) / sqrt 5.
TEST(Tangents, TheTangentIsProjectedOntoTheVertexNormalPlane) {
  Mesh m = plane_triangle(1.0f);
  m.normals[1] = glm::vec3(0, 0, 1);
  generate_tangents(m);
  const float s5 = std::sqrt(5.0f);
  expect_near(glm::vec3(m.tangents[1]), glm::vec3(2 / s5, 1 / s5, 0), 1e-6f, "projected");
  EXPECT_NEAR(glm::dot(glm::vec3(m.tangents[1]), m.normals[1]), 0.0f, 1e-6f);
}

// Two triangles in the z = 0 plane share vertex 0 at the origin, normal +Z, both counter-clockwise.
//  A = (0, 1, 2) with (1, 0, 0), (0, 1, 0): uv = (x, 1 - y), so dP/du = +X; its corner at 0 is 90 degrees.
//  B = (0, 3, 4) with (0, -1, 0), (1, -1, 0): uv = (y, 1 + x) (in v-up terms (u, v') = (y, -x), a
//  rotation, so orientation is preserved), so dP/du = +Y; its corner at 0 is 45 degrees.
// MikkTSpace weights by corner angle: (pi/2 (1, 0, 0) + pi/4 (0, 1, 0)) normalized = (2, 1, 0) / sqrt 5.
TEST(Tangents, CornerAnglesWeightASharedVertex) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {1, -1, 0}};
  m.normals.assign(5, glm::vec3(0, 0, 1));
  m.uv0 = {{0, 1}, {1, 1}, {0, 0}, {-1, 1}, {-1, 2}};
  m.indices = std::vector<uint16_t>{0, 1, 2, 0, 3, 4};
  generate_tangents(m);
  ASSERT_EQ(m.vertex_count(), 5u) << "no split: both triangles preserve orientation";
  const float s5 = std::sqrt(5.0f);
  expect_near(glm::vec3(m.tangents[0]), glm::vec3(2 / s5, 1 / s5, 0), 1e-6f, "angle-weighted");
  EXPECT_EQ(m.tangents[0].w, 1.0f);
  expect_near(glm::vec3(m.tangents[1]), glm::vec3(1, 0, 0), 1e-6f, "A only");
  expect_near(glm::vec3(m.tangents[3]), glm::vec3(0, 1, 0), 1e-6f, "B only");
}

// A vertex shared by a preserving and a mirrored triangle is split: each side keeps its own
// tangent and handedness, and the mirrored triangle uses the copy.
TEST(Tangents, AVertexUsedFromBothSidesIsSplit) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  m.normals.assign(4, glm::vec3(0, 0, 1));
  // Right triangle (0, 1, 2): u = x, v = 1 - y. Left triangle (0, 2, 3) mirrored in u: u = -x.
  m.uv0 = {{0, 1}, {1, 1}, {0, 0}, {1, 1}};
  m.indices = std::vector<uint16_t>{0, 1, 2, 0, 2, 3};
  generate_tangents(m);
  ASSERT_EQ(m.vertex_count(), 6u) << "vertices 0 and 2 are used from both sides";
  EXPECT_EQ(m.vertex_of_corner(3), 4u);
  EXPECT_EQ(m.vertex_of_corner(4), 5u);
  EXPECT_EQ(m.vertex_of_corner(5), 3u);
  EXPECT_EQ(m.positions[4], m.positions[0]);
  EXPECT_EQ(m.positions[5], m.positions[2]);
  for (uint32_t v : {0u, 1u, 2u}) {
    expect_near(glm::vec3(m.tangents[v]), glm::vec3(1, 0, 0), 1e-6f, "right side");
    EXPECT_EQ(m.tangents[v].w, 1.0f);
  }
  for (uint32_t v : {3u, 4u, 5u}) {
    expect_near(glm::vec3(m.tangents[v]), glm::vec3(-1, 0, 0), 1e-6f, "left side");
    EXPECT_EQ(m.tangents[v].w, -1.0f);
  }
}

}  // namespace
}  // namespace luxel::scenes::test
