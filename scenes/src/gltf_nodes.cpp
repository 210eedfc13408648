// A glTF's node hierarchy flattened: each node's world matrix, the translation animation that
// moves it, the scene's totals refused before any mesh is read, then each node's mesh, camera
// and light placed.

#include "gltf_axes.hpp"
#include "gltf_importer.hpp"
#include "gltf_scene_extras.hpp"
#include "gltf_values.hpp"
#include "luxel/scenes/memory_limit.hpp"
#include "tinygltf.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>

namespace luxel::scenes::gltf {

glm::dmat4 Importer::local_matrix(const tinygltf::Node& n, const std::string& where) const {
  auto all_finite = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double d) { return std::isfinite(d); });
  };
  if (!n.matrix.empty()) {
    if (n.matrix.size() != 16 || !all_finite(n.matrix)) fail(where + " has a matrix that is not 16 finite numbers");
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = n.matrix[size_t(c * 4 + r)];
    return m;
  }
  glm::dmat4 m(1.0);
  if (!n.translation.empty()) {
    if (n.translation.size() != 3 || !all_finite(n.translation)) fail(where + " has a bad translation");
    m[3] = glm::dvec4(n.translation[0], n.translation[1], n.translation[2], 1.0);
  }
  if (!n.rotation.empty()) {
    if (n.rotation.size() != 4 || !all_finite(n.rotation)) fail(where + " has a bad rotation");
    glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
    const double len = glm::length(q);
    if (!(len > 0.0)) fail(where + " has a zero rotation quaternion");
    m = m * glm::mat4_cast(q / len);
  }
  if (!n.scale.empty()) {
    if (n.scale.size() != 3 || !all_finite(n.scale)) fail(where + " has a bad scale");
    m = m * glm::dmat4(glm::dvec4(n.scale[0], 0, 0, 0), glm::dvec4(0, n.scale[1], 0, 0), glm::dvec4(0, 0, n.scale[2], 0),
                       glm::dvec4(0, 0, 0, 1));
  }
  return m;
}

/// Per node, the channel of the first animation that animates its translation, or -1. Only
/// the first animation plays (a file's other clips are not read); rotation, scale and morph
/// weights are not read.
std::vector<int> Importer::translation_channels() const {
  std::vector<int> of(model_.nodes.size(), -1);
  if (model_.animations.empty()) return of;
  const tinygltf::Animation& a = model_.animations[0];
  for (size_t c = 0; c < a.channels.size(); ++c) {
    const tinygltf::AnimationChannel& ch = a.channels[c];
    if (ch.target_path != "translation") continue;
    if (ch.target_node < 0 || size_t(ch.target_node) >= model_.nodes.size())
      fail("animation 0 channel " + std::to_string(c) + " targets node " + std::to_string(ch.target_node));
    if (of[size_t(ch.target_node)] < 0) of[size_t(ch.target_node)] = int(c);
  }
  return of;
}

/// The model path of a translation channel: its keys' times, each offset the animated
/// translation's change from rest, in world space. LINEAR is read exactly; STEP and CUBICSPLINE
/// as linear between their keys' values.
std::vector<ModelKey> Importer::animated_path(const Motion& motion, const std::string& node) const {
  const tinygltf::Animation& a = model_.animations[0];
  const tinygltf::AnimationChannel& ch = a.channels[size_t(motion.channel)];
  const std::string where = node + ": animation 0 channel " + std::to_string(motion.channel);
  if (ch.sampler < 0 || size_t(ch.sampler) >= a.samplers.size()) fail(where + " refers to sampler " + std::to_string(ch.sampler));
  const tinygltf::AnimationSampler& sampler = a.samplers[size_t(ch.sampler)];
  const gltf::Floats times = accessors_->attribute(sampler.input, {"input", {TINYGLTF_TYPE_SCALAR}}, where + " input");
  const gltf::Floats values = accessors_->attribute(sampler.output, {"output", {TINYGLTF_TYPE_VEC3}}, where + " output");
  const bool cubic = sampler.interpolation == "CUBICSPLINE";
  if (values.count != times.count * (cubic ? 3 : 1))
    fail(where + " has " + std::to_string(values.count) + " translations for " + std::to_string(times.count) + " times");
  std::vector<ModelKey> keys;
  for (size_t k = 0; k < times.count; ++k) {
    const float t = *times.at(k);
    if (!std::isfinite(t) || (k > 0 && !(t > keys.back().time))) fail(where + " key " + std::to_string(k) + " is not finite or not later than the one before");
    const float* v = values.at(cubic ? 3 * k + 1 : k);  // a cubic key is (in-tangent, value, out-tangent)
    const glm::dvec3 change = glm::dvec3(v[0], v[1], v[2]) - motion.rest;
    keys.push_back({t, glm::vec3(motion.parent * glm::dvec4(change, 0.0))});
    if (!finite(glm::dvec3(keys.back().offset))) fail(where + " key " + std::to_string(k) + " is not finite");
  }
  return keys;
}

void Importer::walk_nodes() {
  std::vector<int> roots;
  if (!model_.scenes.empty()) {
    const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (size_t(s) >= model_.scenes.size()) fail("scene " + std::to_string(s) + " does not exist");
    roots = model_.scenes[size_t(s)].nodes;
    gltf::read_scene_extras(model_.scenes[size_t(s)].extras, scene_, [this](const std::string& what) { fail(what); });
  } else {
    // No scenes: every node without a parent is drawn.
    std::vector<char> child(model_.nodes.size(), 0);
    for (const auto& n : model_.nodes)
      for (int c : n.children)
        if (c >= 0 && size_t(c) < model_.nodes.size()) child[size_t(c)] = 1;
    for (size_t i = 0; i < model_.nodes.size(); ++i)
      if (!child[i]) roots.push_back(int(i));
  }
  // Depth first, without recursion, each node at most once (a cycle or a shared child is an error).
  // placed: `parent` is the node's world matrix; `motion` the translation animation that moves it.
  struct Item { int node; glm::dmat4 parent; int depth; Motion motion; };
  const std::vector<int> channel_of = translation_channels();
  std::vector<char> seen(model_.nodes.size(), 0);
  std::vector<Item> stack, placed;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, gltf::gltf_to_source(), 1, {}});
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    if (item.node < 0 || size_t(item.node) >= model_.nodes.size())
      fail("refers to node " + std::to_string(item.node) + " of " + std::to_string(model_.nodes.size()));
    if (seen[size_t(item.node)]) fail("node " + std::to_string(item.node) + " is reached twice (a cycle, or two parents)");
    if (item.depth > kMaxGltfNodeDepth) fail("nodes nest deeper than " + std::to_string(kMaxGltfNodeDepth) + " levels");
    seen[size_t(item.node)] = 1;
    const tinygltf::Node& n = model_.nodes[size_t(item.node)];
    const glm::dmat4 world = item.parent * local_matrix(n, node_name(item.node));
    Motion motion = item.motion;  // the nearest animated node's, itself included
    if (const int c = channel_of[size_t(item.node)]; c >= 0) {
      motion.channel = c;
      motion.parent = item.parent;
      motion.rest = n.translation.size() == 3 ? glm::dvec3(n.translation[0], n.translation[1], n.translation[2]) : glm::dvec3(0.0);
    }
    placed.push_back({item.node, world, item.depth, motion});
    for (auto c = n.children.rbegin(); c != n.children.rend(); ++c) stack.push_back({*c, world, item.depth + 1, motion});
  }
  // Instancing multiplies vertices and triangles: the flattened totals are known, and refused,
  // before any is read.
  Flattened total;
  for (const Item& item : placed) {
    const Flattened f = flattened(model_.nodes[size_t(item.node)].mesh);
    total.vertices += f.vertices, total.indices += f.indices, total.bytes += f.bytes;
  }
  if (total.vertices > kMaxGltfSceneVertices)
    fail("the flattened scene has " + std::to_string(total.vertices) + " vertices, more than luxel reads (" +
         std::to_string(kMaxGltfSceneVertices) + ")");
  if (total.indices > kMaxGltfSceneIndices)
    fail("the flattened scene has " + std::to_string(total.indices) + " triangle corners, more than luxel reads (" +
         std::to_string(kMaxGltfSceneIndices) + ")");
  check_memory(buffer_bytes() + image_bytes_ + total.bytes,
               std::to_string(total.indices / 3) + " triangles, " + std::to_string(total.vertices) + " vertices, " +
                   std::to_string(images_read_) + " images, " + format_bytes(buffer_bytes()) + " of buffers");
  for (const Item& item : placed) {
    const tinygltf::Node& n = model_.nodes[size_t(item.node)];
    const std::string where = node_name(item.node);
    if (n.mesh >= 0) add_mesh(n.mesh, item.parent, where, n.extras.Get("luxel"), item.motion);
    if (n.camera >= 0) add_camera(n.camera, item.parent, where);
    if (auto it = n.extensions.find("KHR_lights_punctual"); it != n.extensions.end() && it->second.Get("light").IsNumber()) {
      const tinygltf::Value& light = it->second.Get("light");
      const std::optional<int> index = gltf::integer(light);
      if (!index) fail(where + " refers to light " + gltf::number_text(light) + ", which is not an index");
      add_light(*index, item.parent, where);
    }
  }
}

std::string Importer::node_name(int index) const {
  const tinygltf::Node& n = model_.nodes[size_t(index)];
  return "node " + std::to_string(index) + (n.name.empty() ? "" : " '" + n.name + "'");
}

}  // namespace luxel::scenes::gltf
