#include "luxel/scenes/paths.hpp"

#include <glm/common.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace luxel::scenes {

namespace {

glm::vec3 catmull_rom(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, float s) {
  const float s2 = s * s, s3 = s2 * s;
  return 0.5f * ((2.0f * p1) + (p2 - p0) * s + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * s2 +
                 (3.0f * p1 - p0 - 3.0f * p2 + p3) * s3);
}

template <class Key>
void check_keys(const std::vector<Key>& path, const char* what) {
  for (size_t i = 1; i < path.size(); ++i)
    if (!(path[i].time > path[i - 1].time))
      throw std::invalid_argument(std::string(what) + " key " + std::to_string(i) + " is not later than the one before");
}

}  // namespace

Camera camera_at(const std::vector<CameraKey>& path, float time) {
  if (path.empty()) throw std::invalid_argument("the scene has no camera path");
  if (!std::isfinite(time)) throw std::invalid_argument("camera path time is not finite");
  check_keys(path, "camera path");
  if (time <= path.front().time) return path.front().camera;
  if (time >= path.back().time) return path.back().camera;
  size_t i = 0;
  while (path[i + 1].time <= time) ++i;
  const size_t n = path.size();
  const CameraKey& k1 = path[i];
  const CameraKey& k2 = path[i + 1];
  const CameraKey& k0 = path[i == 0 ? 0 : i - 1];
  const CameraKey& k3 = path[i + 2 < n ? i + 2 : n - 1];
  const float s = (time - k1.time) / (k2.time - k1.time);
  Camera c = k1.camera;
  c.position = catmull_rom(k0.camera.position, k1.camera.position, k2.camera.position, k3.camera.position, s);
  c.target = catmull_rom(k0.camera.target, k1.camera.target, k2.camera.target, k3.camera.target, s);
  return c;
}

glm::vec3 model_offset(const Model& model, float time) {
  const std::vector<ModelKey>& path = model.path;
  if (!std::isfinite(time)) throw std::invalid_argument("model path time is not finite");
  check_keys(path, ("model '" + model.name + "' path").c_str());
  if (path.empty()) return glm::vec3(0.0f);
  if (time <= path.front().time) return path.front().offset;
  if (time >= path.back().time) return path.back().offset;
  size_t i = 0;
  while (path[i + 1].time <= time) ++i;
  const float s = (time - path[i].time) / (path[i + 1].time - path[i].time);
  return glm::mix(path[i].offset, path[i + 1].offset, s);
}

}  // namespace luxel::scenes
