// save_gltf: a Scene as glTF 2.0 (gltf.hpp). Vertex values are written as the scene holds them,
// under one root node converting Source inches, +Z up, to meters, +Y up, so a re-import copies
// them back bit for bit.

#include "gltf_axes.hpp"
#include "gltf_materials.hpp"
#include "gltf_scene_extras.hpp"
#include "gltf_values.hpp"
#include "luxel/scenes/gltf.hpp"
#include "luxel/scenes/image_io.hpp"
#include "luxel/scenes/load.hpp"
#include "tinygltf.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

namespace luxel::scenes {

namespace {

using tinygltf::Value;

std::vector<double> column_major(const glm::dmat4& m) {
  std::vector<double> out;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out.push_back(m[c][r]);
  return out;
}

class Exporter {
 public:
  Exporter(const Scene& scene, const std::string& path) : scene_(scene), path_(path) {}

  void run() {
    const bool glb = has_extension(path_, ".glb");
    if (!glb && !has_extension(path_, ".gltf")) fail("the file name must end in .gltf or .glb");
    model_.asset.version = "2.0";
    model_.asset.generator = "luxel";
    textures();
    for (const Material& m : scene_.materials)
      model_.materials.push_back(gltf::material_to_gltf(m, [this](int t) { return texture_map_[size_t(t)]; }, extensions_));
    meshes();
    cameras();
    lights();
    tinygltf::Scene s;
    s.nodes = scene_roots_;
    s.extras = gltf::scene_extras(scene_);
    model_.scenes.push_back(s);
    model_.defaultScene = 0;
    if (!buffer_.empty()) {
      tinygltf::Buffer b;
      b.data = std::move(buffer_);
      model_.buffers.push_back(std::move(b));
    }
    model_.extensionsUsed.assign(extensions_.begin(), extensions_.end());
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model_, out, !glb, glb)) fail("tinygltf could not serialize the scene");
    std::ofstream file(path_, std::ios::binary | std::ios::trunc);
    const std::string bytes = out.str();
    if (!file || !file.write(bytes.data(), std::streamsize(bytes.size())) || !file.flush())
      fail(std::string("cannot write it: ") + std::strerror(errno));
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw GltfError(path_ + ": " + what); }

  /// Appends bytes (4-byte aligned) as a buffer view; returns its index.
  int view(const void* data, size_t bytes, int target) {
    while (buffer_.size() % 4) buffer_.push_back(0);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = buffer_.size();
    v.byteLength = bytes;
    v.target = target;
    const auto* p = static_cast<const uint8_t*>(data);
    buffer_.insert(buffer_.end(), p, p + bytes);
    model_.bufferViews.push_back(v);
    return int(model_.bufferViews.size()) - 1;
  }

  template <class T>
  int accessor(const std::vector<T>& values, int component_type, int type, int target) {
    tinygltf::Accessor a;
    a.bufferView = view(values.data(), values.size() * sizeof(T), target);
    a.componentType = component_type;
    a.type = type;
    a.count = values.size();  // one element per value: a glm vector or an index
    model_.accessors.push_back(a);
    return int(model_.accessors.size()) - 1;
  }

  void textures() {
    texture_map_.assign(scene_.textures.size(), -1);
    for (size_t i = 0; i < scene_.textures.size(); ++i) {
      const Texture& t = scene_.textures[i];
      // glTF holds 8-bit flat images only; HDR and cube textures stay behind (gltf.hpp).
      if (t.shape != TextureShape::flat || t.faces.size() != 1 || t.faces[0].is_hdr()) continue;
      std::vector<uint8_t> png;
      try {
        png = encode_png(t.faces[0], "texture " + std::to_string(i) + " '" + t.name + "'");
      } catch (const std::exception& e) {
        fail(e.what());
      }
      tinygltf::Image image;
      image.name = t.name;
      image.mimeType = "image/png";
      image.bufferView = view(png.data(), png.size(), 0);
      model_.images.push_back(std::move(image));
      tinygltf::Sampler s;
      auto wrap = [](Wrap w) {
        return w == Wrap::clamp ? TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE
                                : w == Wrap::mirror ? TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT : TINYGLTF_TEXTURE_WRAP_REPEAT;
      };
      s.wrapS = wrap(t.wrap_u);
      s.wrapT = wrap(t.wrap_v);
      s.magFilter = t.mag == Filter::nearest ? TINYGLTF_TEXTURE_FILTER_NEAREST : TINYGLTF_TEXTURE_FILTER_LINEAR;
      s.minFilter = t.mipmaps ? (t.min == Filter::nearest ? TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR
                                                          : TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR)
                              : (t.min == Filter::nearest ? TINYGLTF_TEXTURE_FILTER_NEAREST : TINYGLTF_TEXTURE_FILTER_LINEAR);
      model_.samplers.push_back(s);
      tinygltf::Texture texture;
      texture.name = t.name;
      texture.source = int(model_.images.size()) - 1;
      texture.sampler = int(model_.samplers.size()) - 1;
      model_.textures.push_back(texture);
      texture_map_[i] = int(model_.textures.size()) - 1;
    }
  }

  tinygltf::Primitive primitive(const Mesh& m) {
    tinygltf::Primitive p;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    p.material = m.material;
    const int pos = accessor(m.positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
    glm::vec3 lo = m.positions[0], hi = m.positions[0];
    for (const glm::vec3& v : m.positions) lo = glm::min(lo, v), hi = glm::max(hi, v);
    model_.accessors[size_t(pos)].minValues = {lo.x, lo.y, lo.z};
    model_.accessors[size_t(pos)].maxValues = {hi.x, hi.y, hi.z};
    p.attributes["POSITION"] = pos;
    auto add = [&](const char* name, const auto& values, int type) {
      if (!values.empty()) p.attributes[name] = accessor(values, TINYGLTF_COMPONENT_TYPE_FLOAT, type, TINYGLTF_TARGET_ARRAY_BUFFER);
    };
    add("NORMAL", m.normals, TINYGLTF_TYPE_VEC3);
    add("TANGENT", m.tangents, TINYGLTF_TYPE_VEC4);
    add("TEXCOORD_0", m.uv0, TINYGLTF_TYPE_VEC2);
    add("TEXCOORD_1", m.uv1, TINYGLTF_TYPE_VEC2);
    add("COLOR_0", m.colors, TINYGLTF_TYPE_VEC4);
    if (!m.indexed())
      ;  // a non-indexed list: glTF draws its vertices in order, as the scene does
    else if (const auto* i16 = std::get_if<std::vector<uint16_t>>(&m.indices))
      p.indices = accessor(*i16, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    else
      p.indices = accessor(std::get<std::vector<uint32_t>>(m.indices), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                           TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    return p;
  }

  /// Models become a node with one mesh of their meshes' primitives; other meshes a node each.
  /// All hang under the root node that converts Source units and axes to glTF's.
  void meshes() {
    tinygltf::Node root;
    root.name = gltf::kRootNodeName;
    root.matrix = column_major(gltf::source_to_gltf());
    std::vector<int> model_of(scene_.meshes.size(), -1);
    for (size_t i = 0; i < scene_.models.size(); ++i)
      for (int m : scene_.models[i].meshes)
        if (m >= 0 && size_t(m) < model_of.size() && model_of[size_t(m)] < 0) model_of[size_t(m)] = int(i);
    std::vector<char> done_model(scene_.models.size(), 0);
    auto drawable = [&](int m) { return scene_.meshes[size_t(m)].triangle_count() > 0; };
    for (size_t i = 0; i < scene_.meshes.size(); ++i) {
      tinygltf::Mesh mesh;
      if (model_of[i] >= 0) {
        if (done_model[size_t(model_of[i])]) continue;
        done_model[size_t(model_of[i])] = 1;
        const Model& model = scene_.models[size_t(model_of[i])];
        mesh.name = model.name;
        for (int m : model.meshes)
          if (model_of[size_t(m)] == model_of[i] && drawable(m)) mesh.primitives.push_back(primitive(scene_.meshes[size_t(m)]));
      } else {
        mesh.name = scene_.meshes[i].name;
        if (drawable(int(i))) mesh.primitives.push_back(primitive(scene_.meshes[i]));
      }
      if (mesh.primitives.empty()) continue;  // glTF meshes need a primitive; empty meshes are not written
      model_.meshes.push_back(std::move(mesh));
      tinygltf::Node node;
      node.name = model_.meshes.back().name;
      node.mesh = int(model_.meshes.size()) - 1;
      if (model_of[i] >= 0) {  // the model's own centroid, in the units of its vertices
        tinygltf::Value::Object luxel;
        const Model& model = scene_.models[size_t(model_of[i])];
        luxel["centroid"] = gltf::floats(model.centroid);
        if (!model.path.empty()) {
          tinygltf::Value::Array path;
          for (const ModelKey& k : model.path) {
            tinygltf::Value::Object key;
            key["time"] = tinygltf::Value(double(k.time));
            key["offset"] = gltf::floats(k.offset);
            path.emplace_back(std::move(key));
          }
          luxel["path"] = tinygltf::Value(std::move(path));
        }
        tinygltf::Value::Object extras;
        extras["luxel"] = tinygltf::Value(std::move(luxel));
        node.extras = tinygltf::Value(std::move(extras));
      }
      model_.nodes.push_back(std::move(node));
      root.children.push_back(int(model_.nodes.size()) - 1);
    }
    model_.nodes.push_back(std::move(root));
    scene_roots_.push_back(int(model_.nodes.size()) - 1);
  }

  /// A node placed at a Source point, its local -Z along `forward` and +Y along `up` (Source
  /// directions), in glTF's meters and axes (cameras and lights are not under the root node:
  /// glTF leaves scaled cameras undefined).
  int placed_node(const std::string& name, glm::vec3 position, glm::vec3 forward, glm::vec3 up) {
    const glm::dmat4 c = gltf::source_to_gltf();
    const glm::dmat3 r(c);
    glm::dvec3 f = glm::normalize(r * glm::dvec3(forward)), u = r * glm::dvec3(up);
    glm::dvec3 x = glm::cross(f, u);
    if (glm::length(x) < 1e-9) x = glm::cross(f, std::abs(f.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0));
    x = glm::normalize(x);
    const glm::dvec3 y = glm::cross(x, f);
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(x, 0);
    m[1] = glm::dvec4(y, 0);
    m[2] = glm::dvec4(-f, 0);
    m[3] = c * glm::dvec4(glm::dvec3(position), 1.0);
    tinygltf::Node node;
    node.name = name;
    node.matrix = column_major(m);
    model_.nodes.push_back(std::move(node));
    scene_roots_.push_back(int(model_.nodes.size()) - 1);
    return int(model_.nodes.size()) - 1;
  }

  void cameras() {
    const double k = gltf::kInches;
    for (const Camera& c : scene_.cameras) {
      tinygltf::Camera g;
      g.name = c.name;
      if (c.projection == Projection::orthographic) {
        g.type = "orthographic";
        g.orthographic.ymag = 0.5 * c.ortho_height / k;
        g.orthographic.xmag = g.orthographic.ymag * (c.aspect > 0.0f ? c.aspect : 1.0f);
        g.orthographic.znear = c.near_plane / k;
        g.orthographic.zfar = c.far_plane / k;
      } else {
        g.type = "perspective";
        g.perspective.yfov = c.vertical_fov;
        g.perspective.aspectRatio = c.aspect > 0.0f ? c.aspect : 0.0;
        g.perspective.znear = c.near_plane / k;
        g.perspective.zfar = c.far_plane / k;
      }
      Value::Object luxel;
      luxel["target_distance"] = Value(double(glm::length(c.target - c.position)));
      Value::Object extras;
      extras["luxel"] = Value(std::move(luxel));
      g.extras = Value(std::move(extras));
      model_.cameras.push_back(g);
      const int node = placed_node(c.name, c.position, c.target - c.position, c.up);
      model_.nodes[size_t(node)].camera = int(model_.cameras.size()) - 1;
    }
  }

  void lights() {
    const double k = gltf::kInches;
    for (const Light& l : scene_.lights) {
      tinygltf::Light g;
      g.name = l.name;
      // Source intensity color / (c + l d + q d^2) against glTF's I / d_m^2 (gltf.hpp): exact for a
      // pure quadratic term, matched at 100 inches otherwise; directional lights carry lux as is.
      glm::dvec3 total(l.color);
      if (l.type != LightType::directional) {
        if (l.constant == 0.0f && l.linear == 0.0f) {
          total /= double(l.quadratic) * k * k;
        } else {
          const double d = 100.0;
          total *= (d / k) * (d / k) / (double(l.constant) + double(l.linear) * d + double(l.quadratic) * d * d);
        }
      }
      const double peak = std::max({total.r, total.g, total.b});
      g.intensity = peak;
      g.color = peak > 0.0 ? std::vector<double>{total.r / peak, total.g / peak, total.b / peak} : std::vector<double>{1, 1, 1};
      if (l.range > 0.0f && l.type != LightType::directional) g.range = l.range / k;
      g.type = l.type == LightType::point ? "point" : l.type == LightType::spot ? "spot" : "directional";
      if (l.type == LightType::spot) {
        g.spot.outerConeAngle = std::clamp(double(l.outer_cone), 1e-4, M_PI / 2);
        g.spot.innerConeAngle = std::clamp(double(l.inner_cone), 0.0, g.spot.outerConeAngle * 0.9999);
      }
      model_.lights.push_back(g);
      const glm::vec3 up = std::abs(l.direction.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
      const int node = placed_node(l.name, l.position, l.direction, up);
      Value::Object ext;
      ext["light"] = Value(int(model_.lights.size()) - 1);
      model_.nodes[size_t(node)].extensions["KHR_lights_punctual"] = Value(std::move(ext));
      extensions_.insert("KHR_lights_punctual");
    }
  }

  const Scene& scene_;
  std::string path_;
  tinygltf::Model model_;
  std::vector<uint8_t> buffer_;
  std::vector<int> texture_map_;
  std::vector<int> scene_roots_;
  std::set<std::string> extensions_;
};

}  // namespace

void save_gltf(const Scene& scene, const std::string& path) { Exporter(scene, path).run(); }

}  // namespace luxel::scenes
