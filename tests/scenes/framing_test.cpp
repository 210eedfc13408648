// The camera a glTF file without cameras gets (framing.hpp), on generated assets of very different
// shapes: long, flat, tall, deep, far off the origin, under scaled and rotated parents, in pieces.
// The scene's box is computed here from the nodes' TRS (not from luxel's import), its 8 corners
// projected through the camera as the frame's matrices would (glm's lookAt and perspective, D3D
// depth), at several aspects: the projection is centred within 2% of the frame, fills at least
// 70% of the limiting side, touches no edge, and lies between the near and far planes. The sphere
// fit (distance = r / sin(min(fovy, fovx) / 2)) is measured alongside for comparison.

#include "gltf_support.hpp"
#include "luxel/scenes/framing.hpp"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace luxel::scenes::test {
namespace framing_checks {

/// A node of a generated asset: TRS, and children (indices into the same list), or the box mesh.
struct ShapeNode {
  glm::dvec3 translation{0.0}, scale{1.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // w, x, y, z
  std::vector<int> children;
  bool box = false;
};

struct Shape {
  const char* name;
  std::vector<ShapeNode> nodes;  ///< nodes[0..roots) are the scene's roots
  int roots = 1;
};

glm::dquat about(double degrees, glm::dvec3 axis) { return glm::angleAxis(glm::radians(degrees), glm::normalize(axis)); }

ShapeNode box_node(glm::dvec3 t, glm::dvec3 s, glm::dquat r = glm::dquat(1, 0, 0, 0)) {
  ShapeNode n;
  n.translation = t, n.scale = s, n.rotation = r, n.box = true;
  return n;
}

ShapeNode parent_node(glm::dvec3 t, glm::dvec3 s, glm::dquat r, std::vector<int> children) {
  ShapeNode n;
  n.translation = t, n.scale = s, n.rotation = r, n.children = std::move(children);
  return n;
}

std::vector<Shape> shapes() {
  return {
      {"cube", {box_node({0, 0, 0}, {1, 1, 1})}},
      {"long engine block", {box_node({0, 0.4, 0}, {6, 1.2, 1.5})}},
      {"flat board facing front", {box_node({3, 1, -2}, {4, 2.5, 0.05})}},
      {"flat ground plate", {box_node({0, 0, 0}, {5, 0.02, 3})}},
      {"tall column", {box_node({0, 2.5, 0}, {0.3, 5, 0.3})}},
      {"deep rail", {box_node({0, 0, 0}, {0.4, 0.4, 9})}},
      {"small, far off the origin", {box_node({120, -40, 35}, {0.2, 0.1, 0.3})}},
      {"scaled and rotated parents",
       {parent_node({2, -1, 3}, {2, 2, 2}, about(30, {0, 1, 0}), {1}),
        parent_node({0.5, 0, 0}, {1, 0.5, 1}, about(45, {1, 0, 0}), {2}), box_node({0, 1, 0}, {3, 0.5, 0.7}, about(20, {0, 0, 1}))}},
      {"two pieces apart",
       {box_node({-6, 0, 0}, {1, 1, 1}), parent_node({5, 1, -1}, {0.5, 0.5, 0.5}, about(60, {1, 1, 0}), {2}),
        box_node({0, 0, 0}, {2, 1, 1})},
       2},
  };
}

const std::vector<float> kUnitBox = {-0.5f, -0.5f, -0.5f, 0.5f,  -0.5f, -0.5f, -0.5f, 0.5f,  -0.5f, 0.5f,  0.5f,  -0.5f,
                                     -0.5f, -0.5f, 0.5f,  0.5f,  -0.5f, 0.5f,  -0.5f, 0.5f,  0.5f,  0.5f,  0.5f,  0.5f};
const std::vector<uint16_t> kUnitBoxTriangles = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                                 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};

std::string write_shape(const Shape& shape, const TempDir& dir) {
  GltfBuilder b;
  const int positions = b.add_positions(kUnitBox);
  const int indices = b.add_accessor(kUnitBoxTriangles, 5123, "SCALAR", 1);
  const int mesh = b.add_mesh({{"POSITION", positions}}, indices);
  for (size_t i = 0; i < shape.nodes.size(); ++i) {
    const ShapeNode& n = shape.nodes[i];
    json node = {{"translation", {n.translation.x, n.translation.y, n.translation.z}},
                 {"rotation", {n.rotation.x, n.rotation.y, n.rotation.z, n.rotation.w}},
                 {"scale", {n.scale.x, n.scale.y, n.scale.z}}};
    if (n.box) node["mesh"] = mesh;
    if (!n.children.empty()) node["children"] = n.children;
    b.add_node(node, int(i) < shape.roots);
  }
  return b.write(dir);
}

struct Box {
  glm::dvec3 min{std::numeric_limits<double>::max()}, max{-std::numeric_limits<double>::max()};
  void add(glm::dvec3 p) { min = glm::min(min, p), max = glm::max(max, p); }
};

/// The scene's box in Source inches, from the nodes' TRS composed root to leaf.
void add_node_box(const Shape& shape, int index, const glm::dmat4& parent, Box& box) {
  const ShapeNode& n = shape.nodes[size_t(index)];
  const glm::dmat4 world = parent * glm::translate(glm::dmat4(1.0), n.translation) * glm::mat4_cast(n.rotation) *
                           glm::scale(glm::dmat4(1.0), n.scale);
  if (n.box)
    for (size_t v = 0; v < kUnitBox.size(); v += 3) {
      const glm::dvec4 p = world * glm::dvec4(kUnitBox[v], kUnitBox[v + 1], kUnitBox[v + 2], 1.0);
      box.add(glm::dvec3(p.x, -p.z, p.y) * kInches);  // glTF meters, +Y up -> inches, +Z up
    }
  for (int child : n.children) add_node_box(shape, child, world, box);
}

Box shape_box(const Shape& shape) {
  Box box;
  for (int r = 0; r < shape.roots; ++r) add_node_box(shape, r, glm::dmat4(1.0), box);
  return box;
}

struct Framed {
  double center_x = 0, center_y = 0;  ///< the projection's centre, in fractions of the frame from its centre
  double fill = 0;                    ///< of the limiting side
  double edge = 0;                    ///< the largest |NDC| of a corner: below 1 touches no edge
  double min_depth = 0, max_depth = 0;
};

/// The box's 8 corners through the camera (D3D depth, 0 at near, 1 at far).
Framed project(const Box& box, glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up, double fovy, double aspect, double n, double f) {
  const glm::dmat4 m = glm::perspectiveRH_ZO(fovy, aspect, n, f) * glm::lookAtRH(eye, target, up);
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 corner(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z);
    const glm::dvec4 clip = m * glm::dvec4(corner, 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    lo = glm::min(lo, ndc), hi = glm::max(hi, ndc);
  }
  Framed r;
  r.center_x = 0.25 * (lo.x + hi.x), r.center_y = 0.25 * (lo.y + hi.y);  // NDC spans 2
  r.fill = std::max(0.5 * (hi.x - lo.x), 0.5 * (hi.y - lo.y));
  r.edge = std::max({-lo.x, hi.x, -lo.y, hi.y});
  r.min_depth = lo.z, r.max_depth = hi.z;
  return r;
}

TEST(Framing, ScenesWithoutCamerasAreSeenFromTheFrontCentredAndFilled) {
  const TempDir dir;
  for (const Shape& shape : shapes()) {
    const Box box = shape_box(shape);
    for (const double aspect : {16.0 / 9.0, 4.0 / 3.0, 1.0, 0.5, 3.0}) {
      GltfImportOptions options;
      options.framing_aspect = float(aspect);
      const Scene scene = load_gltf(write_shape(shape, dir), options);
      ASSERT_EQ(scene.cameras.size(), 1u) << shape.name;
      const Camera& c = scene.cameras[0];
      EXPECT_EQ(c.name, "luxel:framing");
      // The scene's box as luxel imported it is the one computed here.
      const Bounds b = bounds_of(scene);
      const double tolerance = 1e-4 * glm::length(box.max - box.min);
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(b.min[a], box.min[a], tolerance) << shape.name;
        EXPECT_NEAR(b.max[a], box.max[a], tolerance) << shape.name;
      }
      // The asset's front: the camera on its +Z side (the scene's -Y), looking along -Z.
      const glm::dvec3 view = glm::normalize(glm::dvec3(c.target) - glm::dvec3(c.position));
      EXPECT_NEAR(view.y, 1.0, 1e-6) << shape.name << ": looks along glTF -Z";
      EXPECT_LT(double(c.position.y), box.min.y) << shape.name << ": in front of the scene";
      const Framed f = project(box, c.position, c.target, c.up, c.vertical_fov, aspect, c.near_plane, c.far_plane);
      EXPECT_LE(std::abs(f.center_x), 0.02) << shape.name << " at " << aspect;
      EXPECT_LE(std::abs(f.center_y), 0.02) << shape.name << " at " << aspect;
      EXPECT_GE(f.fill, 0.70) << shape.name << " at " << aspect;
      EXPECT_LT(f.edge, 0.99) << shape.name << " at " << aspect << ": touches an edge";
      EXPECT_GT(f.min_depth, 0.0) << shape.name << ": before the near plane";
      EXPECT_LT(f.max_depth, 1.0) << shape.name << ": beyond the far plane";
      // The bounding sphere's fit, from the same place, for comparison.
      const double r = 0.5 * glm::length(box.max - box.min);
      const double fovx = 2.0 * std::atan(aspect * std::tan(0.5 * c.vertical_fov));
      const double d = r / std::sin(0.5 * std::min(double(c.vertical_fov), fovx));
      const glm::dvec3 center = 0.5 * (box.min + box.max);
      const Framed s = project(box, center - glm::dvec3(0, d, 0), center, glm::dvec3(0, 0, 1), c.vertical_fov, aspect,
                              0.5 * (d - r), 2.0 * (d + r));
      std::printf("%-28s %4.2f:1  box fit: fill %.3f centre (%+.4f, %+.4f) edge %.3f | sphere fit: fill %.3f\n", shape.name,
                  aspect, f.fill, f.center_x, f.center_y, f.edge, s.fill);
    }
  }
}

TEST(Framing, AnEmptySceneGetsAUsableCamera) {
  const Camera c = framing_camera(Scene{}, 16.0f / 9.0f);
  EXPECT_GT(c.near_plane, 0.0f);
  EXPECT_GT(c.far_plane, c.near_plane);
  EXPECT_TRUE(std::isfinite(c.position.y));
  EXPECT_NE(c.position, c.target);
}

}  // namespace framing_checks
}  // namespace luxel::scenes::test
