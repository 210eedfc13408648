#include "luxel/scenes/scene.hpp"

#include <glm/vector_relational.hpp>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace luxel::scenes {

UvTransform UvTransform::of(const TextureRef& ref) {
  return {ref.offset, ref.scale, std::cos(ref.rotation), std::sin(ref.rotation)};
}

size_t Mesh::index_count() const {
  return std::visit([](const auto& v) { return v.size(); }, indices);
}

uint32_t Mesh::vertex_of_corner(size_t i) const {
  if (!indexed()) return static_cast<uint32_t>(i);
  return std::visit([i](const auto& v) { return static_cast<uint32_t>(v[i]); }, indices);
}

std::vector<char> meshes_in_models(const Scene& scene) {
  std::vector<char> in_model(scene.meshes.size(), 0);
  for (const Model& m : scene.models)
    for (int i : m.meshes)
      if (i >= 0 && size_t(i) < in_model.size()) in_model[size_t(i)] = 1;
  return in_model;
}

Bounds bounds_of(const Scene& scene) {
  Bounds b;
  for (const Mesh& m : scene.meshes) {
    for (const glm::vec3& p : m.positions) {
      b.min = b.empty ? p : glm::min(b.min, p);
      b.max = b.empty ? p : glm::max(b.max, p);
      b.empty = false;
    }
  }
  return b;
}

namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool non_negative(float v) { return std::isfinite(v) && v >= 0.0f; }

/// A box with finite bounds, min <= max on every axis.
bool ordered_box(glm::vec3 min, glm::vec3 max) {
  return finite(min) && finite(max) && glm::all(glm::lessThanEqual(min, max));
}

[[noreturn]] void fail(const Scene& scene, const std::string& what) {
  throw std::invalid_argument((scene.name.empty() ? std::string("scene") : scene.name) + ": " + what);
}

void check_ref(const Scene& scene, const TextureRef& ref, const std::string& where) {
  if (ref.texture < -1 || ref.texture >= static_cast<int>(scene.textures.size()))
    fail(scene, where + " refers to texture " + std::to_string(ref.texture) + " of " +
                    std::to_string(scene.textures.size()));
  if (ref.uv_set != 0 && ref.uv_set != 1) fail(scene, where + " reads UV set " + std::to_string(ref.uv_set));
}

void check_texture(const Scene& scene, const Texture& t, size_t i) {
  const std::string where = "texture " + std::to_string(i) + " '" + t.name + "'";
  const size_t faces = t.shape == TextureShape::cube ? 6 : 1;
  if (t.faces.size() != faces)
    fail(scene, where + " has " + std::to_string(t.faces.size()) + " images, not " + std::to_string(faces));
  for (const PixelImage& f : t.faces) {
    if (f.width < 1 || f.height < 1) fail(scene, where + " is empty");
    if (t.shape == TextureShape::cube && (f.width != f.height || f.width != t.faces[0].width))
      fail(scene, where + " is a cube whose faces are not squares of one size");
    const size_t texels = static_cast<size_t>(f.width) * static_cast<size_t>(f.height) * 4;
    if (f.rgba8.empty() == f.rgba32f.empty())
      fail(scene, where + " must hold either 8-bit or float texels");
    if ((f.is_hdr() ? f.rgba32f.size() : f.rgba8.size()) != texels)
      fail(scene, where + " holds the wrong number of texels for " + std::to_string(f.width) + "x" +
                      std::to_string(f.height));
  }
}

/// A shader computes with every number a material holds: one that is not finite (a glTF file's
/// 1e300 kept as a float is infinity) gives NaN or infinity in the frame, e.g. pow(x, -inf) or
/// inf x 0. Named by their .vmt names (gltf.hpp).
void check_material_numbers(const Scene& scene, const Material& m, const std::string& where) {
  const std::pair<const char*, std::vector<float>> numbers[] = {
      {"color", {m.color.r, m.color.g, m.color.b, m.color.a}},
      {"detailscale", {m.detail_scale}},
      {"detailblendfactor", {m.detail_blend}},
      {"envmaptint", {m.envmap_tint.r, m.envmap_tint.g, m.envmap_tint.b}},
      {"envmapcontrast", {m.envmap_contrast}},
      {"envmapsaturation", {m.envmap_saturation}},
      {"envmapfresnel", {m.envmap_fresnel}},
      {"fresnelreflection", {m.fresnel_reflection}},
      {"phongexponent", {m.phong_exponent}},
      {"phongexponentfactor", {m.phong_exponent_factor}},
      {"phongboost", {m.phong_boost}},
      {"phongfresnelranges", {m.phong_fresnel_ranges.x, m.phong_fresnel_ranges.y, m.phong_fresnel_ranges.z}},
      {"phongtint", {m.phong_tint.r, m.phong_tint.g, m.phong_tint.b}},
      {"rimlightexponent", {m.rim_exponent}},
      {"rimlightboost", {m.rim_boost}},
      {"heroboost", {m.hero_boost}},
      {"selfillumtint", {m.self_illum_tint.r, m.self_illum_tint.g, m.self_illum_tint.b}},
      {"emissive", {m.emissive.r, m.emissive.g, m.emissive.b}},
      {"alphatestreference", {m.alpha_cutoff}},
      {"scroll1", {m.water_scroll.x, m.water_scroll.y}},
      {"reflectamount", {m.reflect_amount}},
      {"refractamount", {m.refract_amount}},
      {"reflecttint", {m.reflect_tint.r, m.reflect_tint.g, m.reflect_tint.b}},
      {"refracttint", {m.refract_tint.r, m.refract_tint.g, m.refract_tint.b}},
      {"fogcolor", {m.water_fog_color.r, m.water_fog_color.g, m.water_fog_color.b}},
      {"fogstart", {m.water_fog_start}},
      {"fogend", {m.water_fog_end}}};
  for (const auto& [name, values] : numbers)
    for (float v : values)
      if (!std::isfinite(v)) fail(scene, where + " $" + name + " is not finite");
  for (const auto& [name, ref] : {std::pair<const char*, const TextureRef*>{"basetexture", &m.base}, {"bumpmap", &m.bump},
                                  {"detail", &m.detail}, {"envmapmask", &m.envmap_mask_texture},
                                  {"phongexponenttexture", &m.phong_exponent_texture}, {"normalmap", &m.water_normal}})
    if (!std::isfinite(ref->offset.x) || !std::isfinite(ref->offset.y) || !std::isfinite(ref->scale.x) ||
        !std::isfinite(ref->scale.y) || !std::isfinite(ref->rotation))
      fail(scene, where + " $" + name + " has a texture transform that is not finite");
}

void check_mesh(const Scene& scene, const Mesh& m, size_t i) {
  const std::string where = "mesh " + std::to_string(i) + " '" + m.name + "'";
  const size_t n = m.vertex_count();
  auto same_length = [&](size_t size, const char* what) {
    if (size != 0 && size != n)
      fail(scene, where + " has " + std::to_string(size) + " " + what + " for " + std::to_string(n) + " positions");
  };
  same_length(m.normals.size(), "normals");
  same_length(m.tangents.size(), "tangents");
  same_length(m.uv0.size(), "uv0");
  same_length(m.uv1.size(), "uv1");
  same_length(m.colors.size(), "colors");
  if (m.material < -1 || m.material >= static_cast<int>(scene.materials.size()))
    fail(scene, where + " refers to material " + std::to_string(m.material));
  for (size_t v = 0; v < n; ++v)
    if (!finite(m.positions[v])) fail(scene, where + " position " + std::to_string(v) + " is not finite");
  for (size_t v = 0; v < m.tangents.size(); ++v)
    if (m.tangents[v].w != 1.0f && m.tangents[v].w != -1.0f)
      fail(scene, where + " tangent " + std::to_string(v) + " handedness is not +-1");
  if (!m.indexed() && n % 3 != 0)
    fail(scene, where + " is not indexed and has " + std::to_string(n) + " vertices, not a multiple of 3");
  const size_t count = m.index_count();
  if (count % 3 != 0) fail(scene, where + " has " + std::to_string(count) + " indices, not a multiple of 3");
  std::visit(
      [&](const auto& indices) {  // one visit for the whole array, not one per index
        for (size_t k = 0; k < indices.size(); ++k)
          if (indices[k] >= n)
            fail(scene, where + " index " + std::to_string(k) + " = " + std::to_string(indices[k]) + " is beyond its " +
                            std::to_string(n) + " vertices");
      },
      m.indices);
}

void check_color_correction(const Scene& scene, const ColorCorrection& c, size_t i) {
  const std::string where = "color correction " + std::to_string(i);
  if (c.lut.empty()) fail(scene, where + " has no LUT");
  if (!finite(c.position)) fail(scene, where + " has a position that is not finite");
  for (float falloff : {c.min_falloff, c.max_falloff})
    if (!non_negative(falloff) && falloff != -1.0f) fail(scene, where + " has a falloff that is not finite, >= 0 or -1");
  for (float v : {c.max_weight, c.fade_in, c.fade_out})
    if (!non_negative(v)) fail(scene, where + " has a weight or fade that is negative or not finite");
  for (size_t k = 0; k < c.inputs.size(); ++k)
    if (!std::isfinite(c.inputs[k].time) || (k > 0 && c.inputs[k].time < c.inputs[k - 1].time))
      fail(scene, where + " input " + std::to_string(k) + " has a time that is not finite or earlier than the one before");
}

}  // namespace

bool box_holds(glm::vec3 min, glm::vec3 max, glm::vec3 p) {
  return glm::all(glm::greaterThanEqual(p, min)) && glm::all(glm::lessThanEqual(p, max));
}

const Exposure& exposure_at(const Scene& scene, glm::vec3 p) {
  for (size_t i = scene.exposure_zones.size(); i-- > 0;) {
    const ExposureZone& z = scene.exposure_zones[i];
    if (box_holds(z.min, z.max, p)) return z.exposure;
  }
  return scene.exposure;
}

bool has_translucent_texels(const Texture& texture) {
  for (const PixelImage& f : texture.faces) {
    for (size_t i = 3; i < f.rgba8.size(); i += 4)
      if (f.rgba8[i] < 255) return true;
    for (size_t i = 3; i < f.rgba32f.size(); i += 4)
      if (f.rgba32f[i] < 1.0f) return true;
  }
  return false;
}

void validate(const Scene& scene) {
  for (size_t i = 0; i < scene.textures.size(); ++i) check_texture(scene, scene.textures[i], i);
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    const std::string where = "material " + std::to_string(i) + " '" + m.name + "'";
    for (const TextureRef* r : {&m.base, &m.bump, &m.detail, &m.envmap_texture, &m.envmap_mask_texture,
                                &m.phong_exponent_texture, &m.water_normal})
      check_ref(scene, *r, where);
    check_material_numbers(scene, m, where);
    if (m.envmap == EnvmapSource::texture &&
        (!m.envmap_texture.bound() || scene.textures[m.envmap_texture.texture].shape != TextureShape::cube))
      fail(scene, where + " asks for an env map texture but has no cube bound");
    // The helper keeps $basealphaenvmapmask over a base with alpha and passes it with BUMPMAP:
    // a combo lightmappedgeneric_ps2_3_x.h skips, so what the engine drew is not in the SDK.
    if (m.family == ShaderFamily::lightmapped_generic && m.envmap != EnvmapSource::none && m.bump.bound() &&
        m.envmap_mask == EnvmapMask::base_alpha && m.base.bound() && has_translucent_texels(scene.textures[m.base.texture]))
      fail(scene, where + " is LightmappedGeneric with $bumpmap and $basealphaenvmapmask over a base texture with alpha, "
                          "a combo the SDK never compiles (SKIP $BASEALPHAENVMAPMASK && $BUMPMAP); use "
                          "$normalmapalphaenvmapmask");
    // vertexlitgeneric_dx9_helper.cpp's InitParams deletes the env map of a bumped material masked
    // by its base alpha or an $envmapmask (with a warning): the engine draws none.
    if (m.family == ShaderFamily::vertexlit_generic && m.envmap != EnvmapSource::none && m.bump.bound() &&
        (m.envmap_mask == EnvmapMask::base_alpha || m.envmap_mask == EnvmapMask::texture))
      fail(scene, where + " is VertexLitGeneric with $bumpmap and an env map masked by " +
                      (m.envmap_mask == EnvmapMask::base_alpha ? "$basealphaenvmapmask" : "$envmapmask") +
                      ", whose env map the SDK deletes; use $normalmapalphaenvmapmask or no mask");
  }
  if (!finite(scene.background)) fail(scene, "the background color is not finite");
  if (!finite(scene.fog.color) || !std::isfinite(scene.fog.start) || !std::isfinite(scene.fog.end) ||
      !std::isfinite(scene.fog.max_density) || !std::isfinite(scene.fog.water_z))
    fail(scene, "the fog has a value that is not finite");
  for (size_t i = 0; i < scene.meshes.size(); ++i) check_mesh(scene, scene.meshes[i], i);
  for (size_t i = 0; i < scene.models.size(); ++i)
    for (int mesh : scene.models[i].meshes)
      if (mesh < 0 || mesh >= static_cast<int>(scene.meshes.size()))
        fail(scene, "model " + std::to_string(i) + " refers to mesh " + std::to_string(mesh));
  for (size_t i = 0; i < scene.models.size(); ++i) {
    const Model& m = scene.models[i];
    if (!finite(m.centroid)) fail(scene, "model " + std::to_string(i) + " '" + m.name + "' has a centroid that is not finite");
    for (size_t k = 0; k < m.path.size(); ++k)
      if (!std::isfinite(m.path[k].time) || !finite(m.path[k].offset) || (k > 0 && !(m.path[k].time > m.path[k - 1].time)))
        fail(scene, "model " + std::to_string(i) + " '" + m.name + "' path key " + std::to_string(k) +
                        " is not finite or not later than the one before");
  }
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    if (!finite(l.position) || !finite(l.direction) || !finite(l.color))
      fail(scene, "light " + std::to_string(i) + " '" + l.name + "' is not finite");
    if (l.constant < 0 || l.linear < 0 || l.quadratic < 0 || l.constant + l.linear + l.quadratic <= 0)
      fail(scene, "light " + std::to_string(i) + " '" + l.name + "' has no positive falloff term");
  }
  for (size_t i = 0; i < scene.cameras.size(); ++i) {
    const Camera& c = scene.cameras[i];
    if (!finite(c.position) || !finite(c.target) || c.position == c.target ||
        (c.projection == Projection::perspective && !(c.vertical_fov > 0.0f && c.vertical_fov < 3.1415f)) ||
        (c.projection == Projection::orthographic && !(c.ortho_height > 0.0f && std::isfinite(c.ortho_height))) || !(c.near_plane > 0.0f) || !(c.far_plane > c.near_plane))
      fail(scene, "camera " + std::to_string(i) + " '" + c.name + "' is degenerate");
  }
  auto check_texture_index = [&](int t, const std::string& where) {
    if (t < -1 || t >= static_cast<int>(scene.textures.size())) fail(scene, where + " refers to texture " + std::to_string(t));
  };
  check_texture_index(scene.sky_texture, "the sky");
  for (size_t i = 0; i < scene.cubemap_samples.size(); ++i)
    check_texture_index(scene.cubemap_samples[i].texture, "cube-map sample " + std::to_string(i));
  if (scene.lightmaps) {
    check_texture_index(scene.lightmaps->flat, "the flat lightmap");
    for (int t : scene.lightmaps->textures) check_texture_index(t, "the lightmaps");
  }
  auto check_exposure = [&](const Exposure& e, const std::string& where) {
    for (float v : {e.min_scale, e.max_scale, e.rate, e.percent_target, e.percent_bright, e.bloom_scale})
      if (!non_negative(v)) fail(scene, where + " has a value that is negative or not finite");
    if (!(e.min_scale > 0.0f)) fail(scene, where + " has a minimum scale that is not positive");
  };
  check_exposure(scene.exposure, "the exposure");
  for (size_t i = 0; i < scene.exposure_zones.size(); ++i) {
    const ExposureZone& z = scene.exposure_zones[i];
    const std::string where = "exposure zone " + std::to_string(i);
    if (!ordered_box(z.min, z.max)) fail(scene, where + " has bounds that are not finite or not ordered");
    check_exposure(z.exposure, where);
  }
  for (size_t i = 0; i < scene.color_corrections.size(); ++i) check_color_correction(scene, scene.color_corrections[i], i);
  for (size_t i = 0; i < scene.color_correction_volumes.size(); ++i) {
    const ColorCorrectionVolume& v = scene.color_correction_volumes[i];
    const std::string where = "color correction volume " + std::to_string(i);
    if (v.lut.empty()) fail(scene, where + " has no LUT");
    if (!ordered_box(v.min, v.max)) fail(scene, where + " has bounds that are not finite or not ordered");
    if (!non_negative(v.fade_duration)) fail(scene, where + " has a fade duration that is negative or not finite");
  }
  if (const auto& v = scene.irradiance_volume) {
    const size_t samples = static_cast<size_t>(std::max(v->counts.x, 0)) * std::max(v->counts.y, 0) * std::max(v->counts.z, 0);
    if (!v->cubes.empty() && v->cubes.size() != samples)
      fail(scene, "the irradiance volume holds " + std::to_string(v->cubes.size()) + " cubes for " +
                      std::to_string(samples) + " samples");
  }
}

}  // namespace luxel::scenes
