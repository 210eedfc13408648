#pragma once
// The camera of a camera path at a given time (scene.hpp's CameraKey): position and target
// follow a uniform Catmull-Rom spline through the keys (each segment parameterized by the
// fraction of its own time span; the end keys repeated as their outer neighbours), so the
// camera passes through every key; every other field is the earlier key's. Before the first key
// it is the first key's camera, after the last the last's.

#include "luxel/scenes/scene.hpp"

#include <vector>

namespace luxel::scenes {

/// Throws std::invalid_argument for an empty path, a non-finite time, or keys whose times do not
/// increase strictly.
Camera camera_at(const std::vector<CameraKey>& path, float time);

}  // namespace luxel::scenes
