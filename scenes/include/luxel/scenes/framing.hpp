#pragma once
// The camera a glTF scene without cameras is seen through: the asset's front, as the Khronos glTF
// Sample Viewer first shows a model, with the whole scene in the frame at the image's aspect.
//
// The rule: the camera on the asset's +Z side (glTF's front; the scene's -Y, gltf.hpp) looks
// along glTF -Z, up +Y, at the center of bounds_of(scene) (the meshes' world positions, every
// node's transform applied, as the frame draws them). Its distance fits the box's projection, not
// its bounding sphere: the box's front face (the nearest, so the largest on screen) fills
// kFramingFill of the frame along the limiting side, and at most that along the other. The box is
// symmetric about the line of sight, so its projection is centred.
//
// Why not the bounding sphere (distance = r / sin(min(fovy, fovx) / 2)): it keeps the view
// inside the sphere's silhouette whatever the direction, and so leaves a box seen from its front
// small. At 45 degrees and 16:9 (tests/scenes/framing_test.cpp) a cube fills 69% of the frame's
// limiting side, a 6:1.2:1.5 engine block 55%, a 4:2.5:0.05 board of samples 49%, a
// 0.2:0.1:0.3 box 40%, a 0.4:0.4:9 rail running away from the camera 7%; at 3:1 the engine
// block 32%. The front view is fixed, so the box itself can be fitted.
//
// Near and far planes bracket the box with room to spare: near at half the distance to its front
// face, far at twice the distance to its back face, so their ratio stays moderate for depth
// precision; a scene without meshes gets a 64-inch box around the origin.

#include "luxel/scenes/scene.hpp"

namespace luxel::scenes {

/// The fraction of the frame's limiting side the scene's box fills.
inline constexpr float kFramingFill = 0.9f;
/// The framing camera's vertical field of view: 45 degrees, the Sample Viewer's.
inline constexpr float kFramingVerticalFov = 0.7853982f;

/// The camera framing `scene` for images of `aspect` = width / height (> 0), named "luxel:framing";
/// its own aspect is left 0 (the image's).
Camera framing_camera(const Scene& scene, float aspect);

}  // namespace luxel::scenes
