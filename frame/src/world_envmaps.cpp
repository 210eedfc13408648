// vbsp's env-map assignment for world meshes (world_envmaps.hpp).

#include "luxel/frame/world_envmaps.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace luxel::frame {

int envmap_sample_for(const glm::vec3& centre, const glm::vec3& normal, std::span<const scenes::CubemapSample> samples) {
  int in_front = -1, nearest = -1;
  float in_front_distance = 0.0f, nearest_distance = 0.0f;
  for (size_t i = 0; i < samples.size(); ++i) {
    const glm::vec3 to_sample = samples[i].position - centre;
    const float distance = glm::dot(to_sample, to_sample);
    // vbsp normalizes the offset (a sample at the centre: the zero vector, in front).
    const float length = std::sqrt(distance);
    const float facing = length > 0.0f ? glm::dot(to_sample / length, normal) : 0.0f;
    if (facing >= 0.0f && (in_front < 0 || distance < in_front_distance)) in_front = int(i), in_front_distance = distance;
    if (nearest < 0 || distance < nearest_distance) nearest = int(i), nearest_distance = distance;
  }
  return in_front >= 0 ? in_front : nearest;
}

namespace {

/// A plane's key: its unit normal and distance from the origin, rounded so that the triangles of
/// one flat face, whose float planes differ in the last bits, share it.
using PlaneKey = std::tuple<long, long, long, long>;

PlaneKey plane_key(const glm::vec3& normal, float distance) {
  auto q = [](float v, float step) { return std::lround(v / step); };
  return {q(normal.x, 1e-3f), q(normal.y, 1e-3f), q(normal.z, 1e-3f), q(distance, 1e-2f)};
}

}  // namespace

std::vector<EnvmapFaceGroup> envmap_face_groups(const scenes::Mesh& mesh, std::span<const scenes::CubemapSample> samples) {
  if (samples.empty()) return {};
  const size_t triangles = mesh.triangle_count();
  // Per plane: its normal, its vertices (each once, after the sort below), its triangles.
  struct Plane {
    glm::vec3 normal{0.0f};
    std::vector<uint32_t> vertices;
    std::vector<size_t> triangles;
  };
  std::map<PlaneKey, size_t> plane_of_key;
  std::vector<Plane> planes;
  std::vector<int> sample_of_triangle(triangles, -1);
  for (size_t t = 0; t < triangles; ++t) {
    const uint32_t v[3] = {mesh.vertex_of_corner(3 * t), mesh.vertex_of_corner(3 * t + 1), mesh.vertex_of_corner(3 * t + 2)};
    const glm::vec3 a = mesh.positions[v[0]], b = mesh.positions[v[1]], c = mesh.positions[v[2]];
    const glm::vec3 cross = glm::cross(b - a, c - a);
    const float area2 = glm::length(cross);
    if (!(area2 > 0.0f)) {
      sample_of_triangle[t] = envmap_sample_for((a + b + c) / 3.0f, glm::vec3(0.0f), samples);
      continue;
    }
    const glm::vec3 normal = cross / area2;
    const auto [it, added] = plane_of_key.try_emplace(plane_key(normal, glm::dot(normal, a)), planes.size());
    if (added) planes.push_back(Plane{normal, {}, {}});
    Plane& plane = planes[it->second];
    plane.triangles.push_back(t);
    for (uint32_t i : v) plane.vertices.push_back(i);
  }
  for (Plane& plane : planes) {
    std::sort(plane.vertices.begin(), plane.vertices.end());
    plane.vertices.erase(std::unique(plane.vertices.begin(), plane.vertices.end()), plane.vertices.end());
    glm::dvec3 sum(0.0);
    for (uint32_t i : plane.vertices) sum += glm::dvec3(mesh.positions[i]);
    const glm::vec3 centre(sum / double(plane.vertices.size()));
    const int sample = envmap_sample_for(centre, plane.normal, samples);
    for (size_t t : plane.triangles) sample_of_triangle[t] = sample;
  }
  std::vector<EnvmapFaceGroup> groups;
  std::vector<int> group_of_sample(samples.size(), -1);
  for (size_t t = 0; t < triangles; ++t) {
    const int s = sample_of_triangle[t];
    int& g = group_of_sample[size_t(s)];
    if (g < 0) g = int(groups.size()), groups.push_back(EnvmapFaceGroup{s, {}});
    for (size_t k = 0; k < 3; ++k) groups[size_t(g)].indices.push_back(mesh.vertex_of_corner(3 * t + k));
  }
  return groups;
}

}  // namespace luxel::frame
