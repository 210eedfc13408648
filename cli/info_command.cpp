// luxel info --scene SCENE [--camera N]: what a scene holds (meshes, vertices, triangles,
// materials per shader family, textures, lights by type, cameras, bounds in inches) and what
// drawing it needs (env maps, lightmaps to bake, alpha test and blending, water, sky, fog), one
// "key: value" line each.

#include "commands.hpp"
#include "scene_argument.hpp"

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

const char* family_name(scenes::ShaderFamily f) {
  switch (f) {
    case scenes::ShaderFamily::lightmapped_generic: return "LightmappedGeneric";
    case scenes::ShaderFamily::vertexlit_generic: return "VertexLitGeneric";
    case scenes::ShaderFamily::unlit_generic: return "UnlitGeneric";
    case scenes::ShaderFamily::water: return "Water";
    case scenes::ShaderFamily::sky: return "Sky";
  }
  return "?";
}

/// "3 (a 1, b 2)" from counts by name, in the order given.
std::string counted(size_t total, const std::vector<std::pair<std::string, size_t>>& parts) {
  std::string s = std::to_string(total);
  std::string inner;
  for (const auto& [name, n] : parts)
    if (n) inner += (inner.empty() ? "" : ", ") + name + " " + std::to_string(n);
  return inner.empty() ? s : s + " (" + inner + ")";
}

std::string vec(glm::vec3 v) {
  char b[96];
  std::snprintf(b, sizeof b, "(%.3f, %.3f, %.3f)", v.x, v.y, v.z);
  return b;
}

void print_info(const scenes::Scene& s) {
  using namespace scenes;
  size_t vertices = 0, triangles = 0, in_models = 0;
  std::vector<char> model_mesh(s.meshes.size(), 0);
  for (const Model& m : s.models)
    for (int i : m.meshes) model_mesh[size_t(i)] = 1;
  for (size_t i = 0; i < s.meshes.size(); ++i) {
    vertices += s.meshes[i].vertex_count();
    triangles += s.meshes[i].triangle_count();
    in_models += model_mesh[i];
  }
  std::printf("scene: %s\n", s.name.c_str());
  std::printf("meshes: %zu (%zu in %zu models, %zu world)\n", s.meshes.size(), in_models, s.models.size(),
              s.meshes.size() - in_models);
  std::printf("vertices: %zu\ntriangles: %zu\n", vertices, triangles);
  std::map<ShaderFamily, size_t> families;
  for (const Material& m : s.materials) families[m.family]++;
  std::vector<std::pair<std::string, size_t>> fam;
  for (const auto& [f, n] : families) fam.push_back({family_name(f), n});
  std::printf("materials: %s\n", counted(s.materials.size(), fam).c_str());
  size_t flat8 = 0, hdr = 0, cubes = 0;
  for (const Texture& t : s.textures) {
    if (t.shape == TextureShape::cube) cubes++;
    else if (!t.faces.empty() && t.faces[0].is_hdr()) hdr++;
    else flat8++;
  }
  std::printf("textures: %s\n", counted(s.textures.size(), {{"8-bit", flat8}, {"HDR", hdr}, {"cube", cubes}}).c_str());
  size_t point = 0, spot = 0, directional = 0;
  for (const Light& l : s.lights) (l.type == LightType::point ? point : l.type == LightType::spot ? spot : directional)++;
  std::printf("lights: %s\n", counted(s.lights.size(), {{"point", point}, {"spot", spot}, {"directional", directional}}).c_str());
  std::printf("cameras: %zu%s\n", s.cameras.size(), s.cameras.empty() ? "" : (" (first: " + s.cameras[0].name + ")").c_str());
  const Bounds b = bounds_of(s);
  if (b.empty) std::printf("bounds: empty\n");
  else std::printf("bounds: min %s max %s size %s inches\n", vec(b.min).c_str(), vec(b.max).c_str(), vec(b.size()).c_str());

  // What drawing it takes, from the materials the meshes use.
  std::vector<char> used(s.materials.size(), 0);
  bool default_material = false;
  for (const Mesh& m : s.meshes) {
    if (m.material >= 0) used[size_t(m.material)] = 1;
    else default_material = true;
  }
  bool envmaps = false, lightmapped = false, alpha_test = false, blend = false, water = false, sky = s.sky_texture >= 0, bump = false;
  for (size_t i = 0; i < s.materials.size(); ++i) {
    if (!used[i]) continue;
    const Material& m = s.materials[i];
    envmaps |= m.envmap != EnvmapSource::none;
    lightmapped |= m.family == ShaderFamily::lightmapped_generic;
    alpha_test |= m.alpha == AlphaMode::alpha_test;
    blend |= m.alpha == AlphaMode::blend || m.translucent;
    water |= m.family == ShaderFamily::water;
    sky |= m.family == ShaderFamily::sky;
    bump |= m.bump.bound();
  }
  std::vector<std::string> needs;
  if (envmaps) needs.push_back("env maps (" + std::to_string(s.cubemap_samples.size()) + " cube-map samples)");
  if (lightmapped) needs.push_back(s.lightmaps ? "lightmaps (baked)" : "lightmaps to bake");
  if (!s.models.empty() && !(s.irradiance_volume && !s.irradiance_volume->cubes.empty())) needs.push_back("ambient cubes to bake");
  if (bump) needs.push_back("bump maps");
  if (alpha_test) needs.push_back("alpha test");
  if (blend) needs.push_back("alpha blending");
  if (water) needs.push_back("water");
  if (sky) needs.push_back("sky");
  if (s.fog.mode != FogMode::none) needs.push_back("fog");
  if (default_material) needs.push_back("the default material");
  std::string line;
  for (const std::string& n : needs) line += (line.empty() ? "" : ", ") + n;
  std::printf("needs: %s\n", line.empty() ? "nothing beyond vertex lighting" : line.c_str());
}

}  // namespace

Runner add_info_command(CLI::App& app) {
  auto options = std::make_shared<SceneArgument>();
  CLI::App* cmd = app.add_subcommand("info", "Describe a scene: counts, bounds and what drawing it needs");
  options->add_to(*cmd);
  return [cmd, options]() -> int {
    if (!cmd->parsed()) return -1;
    int code = 0;
    const std::optional<scenes::Scene> scene = options->load("info", code);
    if (!scene) return code;
    print_info(*scene);
    return 0;
  };
}

}  // namespace luxel::cli
