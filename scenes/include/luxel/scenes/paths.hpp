#pragma once
// What moves with the scene's clock: the camera along Scene::camera_path, models along
// Model::path.
//
// Camera: position and target follow a uniform Catmull-Rom spline through the keys (each segment
// parameterized by the fraction of its own time span; the end keys repeated as their outer
// neighbours), so the camera passes through every key; every other field is the earlier key's.
// Before the first key it is the first key's camera, after the last the last's.
//
// Model: its offset is interpolated linearly between the keys (glTF's LINEAR translation), held
// at the first key's before it and the last key's after it; a model without a path stays put.

#include "luxel/scenes/scene.hpp"

#include <vector>

namespace luxel::scenes {

/// Throws std::invalid_argument for an empty path, a non-finite time, or keys whose times do not
/// increase strictly.
Camera camera_at(const std::vector<CameraKey>& path, float time);

/// The world translation of `model`'s meshes and centroid at `time` (0 without a path). Throws
/// std::invalid_argument for a non-finite time or keys whose times do not increase strictly.
glm::vec3 model_offset(const Model& model, float time);

}  // namespace luxel::scenes
