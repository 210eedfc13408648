// What a cube-map bake reads, hashed (cubemaps.hpp: cubemap_input_hash).
#include "luxel/frame/cubemaps.hpp"

#include "luxel/scenes/content_hash.hpp"

#include <string>
#include <type_traits>
#include <variant>

namespace luxel::frame {

namespace {

/// Raised when what a capture draws or how cubes are made changes, so that kept cubes re-bake.
constexpr int kCubemapFormatVersion = 2;

void hash_ref(scenes::ContentHash& h, const scenes::TextureRef& r) { h.values(r.texture, r.uv_set, r.offset, r.scale, r.rotation); }

void hash_texture(scenes::ContentHash& h, const scenes::Texture& t) {
  h.values(t.shape, t.color_space, t.wrap_u, t.wrap_v, t.mag, t.min, t.mipmaps, t.faces.size());
  for (const scenes::PixelImage& f : t.faces) h.image(f);
}

}  // namespace

uint64_t cubemap_input_hash(const scenes::Scene& scene, const CubemapSettings& settings) {
  scenes::ContentHash h;
  h.values(kCubemapFormatVersion, settings.face_size, settings.stops_apart, settings.model);
  const std::vector<char> in_model = scenes::meshes_in_models(scene);
  h.value(scene.meshes.size());
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const scenes::Mesh& m = scene.meshes[i];
    h.values(m.material, in_model[i]);
    h.vector(m.positions), h.vector(m.normals), h.vector(m.tangents), h.vector(m.uv0), h.vector(m.uv1), h.vector(m.colors);
    std::visit([&](const auto& v) { h.vector(v); }, m.indices);
  }
  h.value(scene.materials.size());
  for (const scenes::Material& m : scene.materials) {
    h.values(m.family, m.color, m.detail_scale, m.detail_blend, m.envmap, m.envmap_mask, m.envmap_tint, m.envmap_contrast,
             m.envmap_saturation, m.envmap_fresnel, m.fresnel_reflection, m.self_illum, m.self_illum_tint, m.emissive, m.alpha,
             m.alpha_cutoff, m.translucent, m.double_sided, m.linear_write);
    h.values(m.phong, m.phong_exponent, m.phong_boost, m.phong_fresnel_ranges, m.phong_tint, m.base_map_alpha_phong_mask,
             m.rim, m.rim_exponent, m.rim_boost, m.rim_mask, m.half_lambert, m.hero_boost, m.phong_exponent_factor,
             m.phong_albedo_tint, m.invert_phong_mask);
    for (const scenes::TextureRef* r : {&m.base, &m.bump, &m.detail, &m.envmap_texture, &m.envmap_mask_texture,
                                        &m.phong_exponent_texture, &m.water_normal})
      hash_ref(h, *r);
  }
  // Every texture but the samples' own cubes (a capture never reads them).
  std::vector<char> sample_cube(scene.textures.size(), 0);
  for (const scenes::CubemapSample& s : scene.cubemap_samples)
    if (s.texture >= 0 && size_t(s.texture) < sample_cube.size()) sample_cube[size_t(s.texture)] = 1;
  for (size_t i = 0; i < scene.textures.size(); ++i)
    if (!sample_cube[i]) hash_texture(h, scene.textures[i]);
  h.values(scene.sky_texture, scene.background, bool(scene.lightmaps));
  if (scene.lightmaps) h.values(scene.lightmaps->width, scene.lightmaps->height, scene.lightmaps->flat, scene.lightmaps->textures);
  h.value(scene.cubemap_samples.size());
  for (const scenes::CubemapSample& s : scene.cubemap_samples) h.values(s.position, s.size);
  return h.h;
}

}  // namespace luxel::frame
