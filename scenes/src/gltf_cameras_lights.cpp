// A glTF's cameras and KHR_lights_punctual lights as Source ones, the camera asked for first, and
// the default camera and lights of a file without.

#include "gltf_axes.hpp"
#include "gltf_importer.hpp"
#include "luxel/scenes/framing.hpp"
#include "tinygltf.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>

namespace luxel::scenes::gltf {

glm::vec3 Importer::point(const glm::dmat4& m, glm::dvec3 p) { return glm::vec3(glm::dvec3(m * glm::dvec4(p, 1.0))); }

glm::vec3 Importer::direction(const glm::dmat4& m, glm::dvec3 d) {
  const glm::dvec3 w = glm::dmat3(m) * d;
  const double len = glm::length(w);
  return len > 0.0 ? glm::vec3(w / len) : glm::vec3(0, 0, -1);
}

void Importer::add_camera(int index, const glm::dmat4& world, const std::string& node) {
  if (size_t(index) >= model_.cameras.size()) fail(node + " refers to camera " + std::to_string(index));
  const tinygltf::Camera& g = model_.cameras[size_t(index)];
  const std::string where = "camera " + std::to_string(index);
  Camera c;
  c.name = g.name.empty() ? where : g.name;
  c.position = point(world, glm::dvec3(0.0));
  double distance = 100.0;  // inches to the target (the direction is what glTF gives)
  if (const auto& d = g.extras.Get("luxel").Get("target_distance"); d.IsNumber()) distance = d.GetNumberAsDouble();
  c.target = c.position + direction(world, glm::dvec3(0, 0, -1)) * float(distance);
  c.up = direction(world, glm::dvec3(0, 1, 0));
  const double k = gltf::kInches;
  if (g.type == "orthographic") {
    c.projection = Projection::orthographic;
    c.ortho_height = float(2.0 * g.orthographic.ymag * k);
    c.aspect = g.orthographic.ymag > 0.0 ? float(g.orthographic.xmag / g.orthographic.ymag) : 0.0f;
    c.near_plane = float(std::max(g.orthographic.znear * k, 1e-3));
    c.far_plane = float(g.orthographic.zfar * k);
  } else {
    c.vertical_fov = float(g.perspective.yfov);
    c.aspect = float(g.perspective.aspectRatio);
    c.near_plane = float(g.perspective.znear * k);
    c.far_plane = g.perspective.zfar > 0.0 ? float(g.perspective.zfar * k) : std::max(16384.0f, c.near_plane * 65536.0f);
  }
  cameras_.push_back({index, std::move(c)});
}

void Importer::add_light(int index, const glm::dmat4& world, const std::string& node) {
  if (index < 0 || size_t(index) >= model_.lights.size()) fail(node + " refers to light " + std::to_string(index));
  const tinygltf::Light& g = model_.lights[size_t(index)];
  Light l;
  l.name = g.name.empty() ? "light " + std::to_string(index) : g.name;
  glm::vec3 color(1.0f);
  if (g.color.size() == 3) color = glm::vec3(float(g.color[0]), float(g.color[1]), float(g.color[2]));
  l.color = color * float(g.intensity);
  l.position = point(world, glm::dvec3(0.0));
  l.direction = direction(world, glm::dvec3(0, 0, -1));
  l.constant = 0.0f, l.linear = 0.0f, l.quadratic = gltf::kLightQuadratic;
  l.range = float(g.range * gltf::kInches);
  if (g.type == "directional") l.type = LightType::directional;
  else if (g.type == "spot") {
    l.type = LightType::spot;
    l.inner_cone = float(g.spot.innerConeAngle);
    l.outer_cone = float(g.spot.outerConeAngle);
  } else if (g.type == "point") l.type = LightType::point;
  else fail("light " + std::to_string(index) + " has unknown type '" + g.type + "'");
  scene_.lights.push_back(std::move(l));
}

/// The camera asked for first, the others after it in the order the nodes placed them.
void Importer::order_cameras() {
  if (model_.cameras.empty() && options_.camera == 0) return;
  if (options_.camera < 0 || size_t(options_.camera) >= model_.cameras.size())
    fail("camera " + std::to_string(options_.camera) + " asked for; the file has " + std::to_string(model_.cameras.size()));
  auto chosen = std::find_if(cameras_.begin(), cameras_.end(), [&](const auto& c) { return c.first == options_.camera; });
  if (chosen == cameras_.end()) fail("camera " + std::to_string(options_.camera) + " is not placed by any node of the scene");
  scene_.cameras.push_back(chosen->second);
  for (auto it = cameras_.begin(); it != cameras_.end(); ++it)
    if (it != chosen) scene_.cameras.push_back(it->second);
}

void Importer::add_defaults() {
  if (scene_.cameras.empty() && options_.default_camera)
    scene_.cameras.push_back(framing_camera(scene_, options_.framing_aspect));
  if (scene_.lights.empty() && options_.default_lights) {
    // A key light over the camera's shoulder and a dimmer fill from the other side.
    Light key;
    key.name = "luxel:key";
    key.type = LightType::directional;
    key.direction = -glm::normalize(glm::vec3(-0.8f, -0.6f, 1.0f));
    key.color = glm::vec3(1.0f);
    Light fill = key;
    fill.name = "luxel:fill";
    fill.direction = -glm::normalize(glm::vec3(1.0f, -0.3f, 0.2f));
    fill.color = glm::vec3(0.35f);
    scene_.lights.push_back(key);
    scene_.lights.push_back(fill);
  }
}

}  // namespace luxel::scenes::gltf
