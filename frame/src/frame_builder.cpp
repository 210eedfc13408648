// The frame builder (frame_builder.hpp): a view's draws from the scene's meshes and materials.

#include "frame_builder.hpp"

#include "model_lighting.hpp"
#include "source_draws.hpp"
#include "trivial_unlit.hpp"
#include "views.hpp"
#include "water_passes.hpp"

#include "luxel/frame/textures.hpp"
#include "luxel/frame/world_envmaps.hpp"
#include "luxel/rasterizer/srgb.hpp"
#include "luxel/scenes/paths.hpp"
#include "luxel/scenes/tangents.hpp"
#include "luxel/shading/source/normalization_cube.hpp"
#include "luxel/shading/source/registry.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace luxel::frame {

using namespace rasterizer;

namespace {

using namespace shading::source;

Geometry geometry_of(const scenes::Mesh& m) {
  const auto vertices = static_cast<uint32_t>(m.vertex_count());
  if (!m.indexed()) return Geometry::non_indexed(vertices);
  if (const auto* i16 = std::get_if<std::vector<uint16_t>>(&m.indices)) return Geometry::indexed(std::span(*i16), vertices);
  return Geometry::indexed(std::span(std::get<std::vector<uint32_t>>(m.indices)), vertices);
}

template <class T>
const T* data_or_null(const std::vector<T>& v) {
  return v.empty() ? nullptr : v.data();
}

/// The peer workloads' materials (unlit, untextured, no env map, written linear or sRGB, no fog,
/// exposure 1): UnlitGeneric's base+vertexcolor combo with a white base computes color x vertex
/// color x 1; the trivial functor computes the same product per vertex (equal up to float
/// rounding of where the product is taken), and takes the rasterizer's fastest paths.
bool is_trivial_unlit(const scenes::Material& m, Fog fog, float exposure) {
  return m.family == scenes::ShaderFamily::unlit_generic && !m.base.bound() && m.envmap == scenes::EnvmapSource::none &&
         fog == Fog::none && exposure == 1.0f && m.alpha == scenes::AlphaMode::opaque && !m.translucent;
}

/// The mesh's bounding box, moved by `offset` (its model's, at the clock's time).
std::pair<glm::vec3, glm::vec3> mesh_bounds(const scenes::Mesh& m, const glm::vec3& offset) {
  if (m.positions.empty()) return {offset, offset};
  glm::vec3 lo = m.positions[0], hi = lo;
  for (const glm::vec3& p : m.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return {lo + offset, hi + offset};
}

glm::vec3 mesh_center(const scenes::Mesh& m, const glm::vec3& offset) {
  const auto [lo, hi] = mesh_bounds(m, offset);
  return 0.5f * (lo + hi);
}

/// Whether some corner of the mesh's bounding box lies on the kept side of `plane` (n, d).
bool touches(const scenes::Mesh& m, const glm::vec3& offset, const glm::vec4& plane) {
  const auto [lo, hi] = mesh_bounds(m, offset);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    if (glm::dot(glm::vec3(plane), c) + plane.w >= 0.0f) return true;
  }
  return false;
}

EnvmapMask lightmapped_mask(scenes::EnvmapMask m) {
  switch (m) {
    case scenes::EnvmapMask::texture: return EnvmapMask::texture;
    case scenes::EnvmapMask::base_alpha: return EnvmapMask::base_alpha_inverted;
    case scenes::EnvmapMask::normal_alpha: return EnvmapMask::normal_alpha;
    default: return EnvmapMask::none;
  }
}


/// Builds a view's draws (views.hpp): what renderer.hpp promises, one function per family.
class FrameBuilder {
 public:
  FrameBuilder(FrameState& st, const ViewSpec& view, PassList& out)
      : st_(st), scene_(*st.scene), view_(view), out_(out), model_(st.settings.model), eye_(view.eye),
        far_(view.far_plane), vp_(view.view_projection), exposure_(view.exposure) {
    tonemap_ = ToneMapConstants::for_scale(exposure_);
    if (view.water_fog) {
      fog_settings_ = *view.water_fog;
      fog_ = Fog::height;
    } else if (scene_.fog.mode != scenes::FogMode::none && !st.settings.cubemap_capture) {
      fog_settings_.start = scene_.fog.start;
      fog_settings_.end = scene_.fog.end;
      fog_settings_.max_density = scene_.fog.max_density;
      fog_settings_.color = scene_.fog.color;
      fog_settings_.water_z = scene_.fog.water_z;
      fog_ = scene_.fog.mode == scenes::FogMode::height ? Fog::height : range_fog_for_model(model_);
    }
    fog_constants_ = fog_constants(fog_settings_, eye_, exposure_);
    lights_ = light_descriptions(scene_);
    model_of_mesh_.assign(scene_.meshes.size(), -1);
    for (size_t i = 0; i < scene_.models.size(); ++i)
      for (int m : scene_.models[i].meshes)
        if (m >= 0 && m < static_cast<int>(scene_.meshes.size())) model_of_mesh_[static_cast<size_t>(m)] = static_cast<int>(i);
  }

  /// Where mesh `index` is moved to at the clock's time: its model's offset (0 outside models).
  glm::vec3 offset_of(size_t index) const {
    const int model = model_of_mesh_[index];
    return model >= 0 ? st_.model_offsets[static_cast<size_t>(model)] : glm::vec3(0.0f);
  }

  /// Every mesh, the sky, the translucent meshes sorted.
  void build() {
    for (size_t i = 0; i < scene_.meshes.size(); ++i) add_mesh(i);
    if (view_.sky) add_sky();
    // Translucent draws back to front: the farthest mesh center first, ties in scene order.
    std::stable_sort(translucent_.begin(), translucent_.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (auto& [distance, pass] : translucent_) out_.translucent.push_back(std::move(pass));
  }

 private:
  void add_mesh(size_t index) {
    const scenes::Mesh* mesh = &scene_.meshes[index];
    const scenes::Material& m = mesh->material >= 0 ? scene_.materials[static_cast<size_t>(mesh->material)] : default_material_;
    if (m.family == scenes::ShaderFamily::sky) return;  // Scene::sky_texture draws the sky
    if (st_.settings.cubemap_capture && !captured(index, m)) return;
    if (m.family == scenes::ShaderFamily::water && !(view_.water && st_.water)) return;
    const glm::vec3 offset = offset_of(index);
    if (view_.keep && !touches(*mesh, offset, *view_.keep)) return;
    Pass pass;
    pass.state = state_of(m);
    // (A capture is rendered to floats too, through its Source draws' own state: render_float.)
    if (is_trivial_unlit(m, fog_, exposure_) && !st_.settings.cubemap_capture && offset == glm::vec3(0.0f)) {
      pass.geometry = geometry_of(*mesh);
      pass.trivial = UnlitVertex{mesh->positions.data(), data_or_null(mesh->colors), m.color, vp_};
      queue(m, index, std::move(pass));
      return;
    }
    if (needs_tangents(m) && mesh->tangents.empty()) mesh = &with_tangents(index);
    pass.geometry = geometry_of(*mesh);
    if (m.family == scenes::ShaderFamily::lightmapped_generic && m.envmap == scenes::EnvmapSource::nearest_sample)
      return add_reflecting_world(index, *mesh, m, offset, std::move(pass));
    const DrawTarget target = draw_target(pass, *mesh, m, offset);
    switch (m.family) {
      case scenes::ShaderFamily::lightmapped_generic: pass.source = lightmapped(*mesh, m, target, envmap_of(m, index)); break;
      case scenes::ShaderFamily::vertexlit_generic: pass.source = vertexlit(index, *mesh, m, target); break;
      case scenes::ShaderFamily::unlit_generic: pass.source = unlit(index, *mesh, m, target); break;
      case scenes::ShaderFamily::water: {
        const GpuTexture& normal_map = st_.textures[static_cast<size_t>(m.water_normal.texture)];
        std::optional<SourceDraw> draw =
            st_.water->surface_draw(index, m, normal_map, target, {tonemap_, fog_, fog_constants_, eye_});
        if (!draw) return;  // its plane is not drawn (water_passes.hpp)
        pass.source = std::move(*draw);
        break;
      }
      case scenes::ShaderFamily::sky: return;
    }
    queue(m, index, std::move(pass));
  }

  /// Where `pass` draws mesh `mesh` with material `m`: its own vertex stage; the refraction view's
  /// opaque draws write the water fog factor to alpha.
  DrawTarget draw_target(const Pass& pass, const scenes::Mesh& mesh, const scenes::Material& m, const glm::vec3& offset) {
    return DrawTarget{pass.state, pass.geometry, vertex_setup(mesh, m, offset), st_.settings.count_shading,
                      view_.water_fog && !translucent(m) && m.alpha == scenes::AlphaMode::opaque};
  }

  /// A LightmappedGeneric mesh reflecting the samples (`env_cubemap`): one draw per sample its
  /// face groups reflect (world_envmaps.hpp); none without samples, as the engine draws it.
  void add_reflecting_world(size_t index, const scenes::Mesh& mesh, const scenes::Material& m, const glm::vec3& offset,
                            Pass pass) {
    std::unique_ptr<std::vector<EnvmapFaceGroup>>& groups = st_.envmap_groups[index];
    if (!groups) groups = std::make_unique<std::vector<EnvmapFaceGroup>>(envmap_face_groups(mesh, scene_.cubemap_samples));
    if (groups->empty()) {
      pass.source = lightmapped(mesh, m, draw_target(pass, mesh, m, offset), nullptr);
      queue(m, index, std::move(pass));
      return;
    }
    for (const EnvmapFaceGroup& group : *groups) {
      Pass part;
      part.state = pass.state;
      part.geometry = Geometry::indexed(std::span<const uint32_t>(group.indices), static_cast<uint32_t>(mesh.vertex_count()));
      part.source = lightmapped(mesh, m, draw_target(part, mesh, m, offset), sample_cube(group.sample));
      queue(m, index, std::move(part));
    }
  }

  void add_sky() {
    if (scene_.sky_texture < 0) return;
    const scenes::Texture& cube = scene_.textures[static_cast<size_t>(scene_.sky_texture)];
    if (cube.shape != scenes::TextureShape::cube) return;
    if (st_.sky_faces.empty()) st_.sky_faces = cube_faces(cube);
    // Six quads around the eye, each face's texture over the part of the cube map it covers, at
    // depth 1 (behind everything drawn; only where the clear's depth is left).
    const float r = 0.5f * far_;  // inside the far plane, corners included
    auto& quads = *st_.sky_quads.emplace_back(std::make_unique<FrameState::SkyQuads>());
    const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int f = 0; f < 6; ++f)
      for (int k = 0; k < 4; ++k) {
        const glm::vec2& c = corners[k];
        quads.positions[4 * f + k] = eye_ + r * rasterizer::cube_direction(static_cast<rasterizer::CubeFace>(f), c.x, c.y);
        quads.uvs[4 * f + k] = c;
      }
    for (int f = 0; f < 6; ++f) {
      Pass pass;
      limit_to_view(pass.state);
      pass.state.rasterizer.cull = CullMode::None;
      pass.state.depth_stencil.depth_func = CompareFunc::LessEqual;
      pass.state.depth_stencil.depth_write = false;
      pass.state.blend.srgb_write = true;
      auto setup = std::make_unique<VertexSetup>();
      setup->positions = quads.positions + 4 * f;
      setup->uv0 = quads.uvs + 4 * f;
      setup->view_projection = vp_;
      setup->at_far_plane = true;
      static constexpr uint16_t kQuad[6] = {0, 1, 2, 0, 2, 3};
      pass.geometry = Geometry::indexed(std::span<const uint16_t>(kQuad), 4);
      SkyParams p;
      const GpuTexture& face = st_.sky_faces[static_cast<size_t>(f)];
      p.base = Sampler2D{0, &face.texture, drawn(face.sampler)};
      const bool hdr = cube.faces.at(0).is_hdr();
      p.input_scale = glm::vec4(hdr ? sky_input_scale(SkyFormat::rgba16f) : glm::vec3(1.0f), 1.0f);
      p.tonemap = tonemap_;
      DrawTarget target{pass.state, pass.geometry, setup.get(), st_.settings.count_shading};
      st_.vertex_setups.push_back(std::move(setup));
      pass.source = sky_draw(model_, target, p);
      out_.sky.push_back(std::move(pass));
    }
  }

  /// Keeps a draw to the pixels the view draws (ViewSpec::scissor, ViewSpec::masked). The mask's
  /// test writes nothing, so the rasterizer tests it before shading wherever it tests depth
  /// early (draw.hpp).
  void limit_to_view(PipelineState& s) const {
    s.scissor = view_.scissor;
    if (!view_.masked) return;
    s.depth_stencil.stencil_enable = true;
    s.depth_stencil.stencil_ref = kDrawnStencil;
    s.depth_stencil.front.func = CompareFunc::Equal;
  }

  PipelineState state_of(const scenes::Material& m) const {
    PipelineState s;
    limit_to_view(s);
    s.depth_stencil.depth_func = CompareFunc::Less;
    // Back faces turn clockwise on screen; in a mirrored view, counter-clockwise.
    s.rasterizer.front_counter_clockwise = !view_.mirrored;
    s.rasterizer.cull = m.double_sided ? CullMode::None : view_.mirrored ? CullMode::CCW : CullMode::CW;
    s.blend.srgb_write = !m.linear_write;
    if (m.alpha == scenes::AlphaMode::alpha_test) {
      s.alpha_test.enable = true;
      s.alpha_test.func = CompareFunc::GreaterEqual;
      s.alpha_test.ref = static_cast<uint8_t>(std::lround(std::clamp(m.alpha_cutoff, 0.0f, 1.0f) * 255.0f));
    }
    if (translucent(m)) {
      s.blend.enable = true;
      s.blend.src = BlendFactor::SrcAlpha;
      s.blend.dst = BlendFactor::InvSrcAlpha;
      s.depth_stencil.depth_write = false;
    }
    return s;
  }

  static bool translucent(const scenes::Material& m) { return m.translucent || m.alpha == scenes::AlphaMode::blend; }

  /// Whether a cube-map capture draws mesh `index` (renderer.hpp): world, not blended, not water.
  bool captured(size_t index, const scenes::Material& m) const {
    return model_of_mesh_[index] < 0 && !translucent(m) && m.family != scenes::ShaderFamily::water;
  }

  static bool needs_tangents(const scenes::Material& m) {
    if (m.family == scenes::ShaderFamily::water) return true;  // its normal map
    return m.bump.bound() && (m.family == scenes::ShaderFamily::lightmapped_generic || m.family == scenes::ShaderFamily::vertexlit_generic);
  }

  /// Mesh `index` with tangents, made once for every view.
  const scenes::Mesh& with_tangents(size_t index) {
    std::unique_ptr<scenes::Mesh>& completed = st_.completed_meshes[index];
    if (!completed) {
      const scenes::Mesh& mesh = scene_.meshes[index];
      auto copy = std::make_unique<scenes::Mesh>(mesh);
      try {
        scenes::generate_tangents(*copy);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(scene_.name + ": mesh '" + mesh.name + "' has a bump or normal map and " + e.what());
      }
      completed = std::move(copy);
    }
    return *completed;
  }

  VertexSetup* vertex_setup(const scenes::Mesh& mesh, const scenes::Material& m, const glm::vec3& offset) {
    auto s = std::make_unique<VertexSetup>();
    s->positions = mesh.positions.data();
    if (offset != glm::vec3(0.0f)) s->offset = offset;
    s->normals = data_or_null(mesh.normals);
    s->tangents = data_or_null(mesh.tangents);
    s->uv0 = data_or_null(m.base.uv_set == 1 ? mesh.uv1 : mesh.uv0);
    s->uv1 = data_or_null(mesh.uv1);
    s->colors = data_or_null(mesh.colors);
    // Water applies its normal map's transform per pixel (adapter.hpp), to the raw uv0.
    if (m.family != scenes::ShaderFamily::water) s->base_transform = scenes::UvTransform::of(m.base);
    s->view_projection = vp_;
    s->proj_z_row = view_.proj_z_row;
    s->fog_c16 = vertex_fog_constant(fog_settings_);
    st_.vertex_setups.push_back(std::move(s));
    return st_.vertex_setups.back().get();
  }

  Sampler2D sampler2d(int slot, const scenes::TextureRef& ref) const {
    const GpuTexture& t = ref.bound() ? st_.textures[static_cast<size_t>(ref.texture)] : st_.white;
    return Sampler2D{slot, &t.texture, drawn(t.sampler)};
  }

  /// A sampler as the frame's draws read with it (as_drawn: FrameSettings::texture_lod_bias and
  /// FrameSettings::sampling).
  rasterizer::Sampler drawn(const rasterizer::Sampler& s) const {
    return as_drawn(s, st_.settings.texture_lod_bias, st_.settings.sampling);
  }

  /// Scene texture `t` if it is a cube, else null.
  const GpuTexture* cube_at(int t) const {
    if (t < 0 || scene_.textures[static_cast<size_t>(t)].shape != scenes::TextureShape::cube) return nullptr;
    return &st_.textures[static_cast<size_t>(t)];
  }

  /// The cube of cube-map sample `s`: its baked cube, or the sky while it has none or while the
  /// frame captures the samples' cubes (docs/fidelity.md#world-env-maps-vbsp).
  const GpuTexture* sample_cube(int s) const {
    const int baked = scene_.cubemap_samples[static_cast<size_t>(s)].texture;
    return baked >= 0 && !st_.settings.cubemap_capture ? cube_at(baked) : cube_at(scene_.sky_texture);
  }

  /// The cube a mesh reflects, or null for none: with `env_cubemap`, the sample nearest the mesh's
  /// centre, else the sky (world meshes reflect per face group: add_reflecting_world).
  const GpuTexture* envmap_of(const scenes::Material& m, size_t index) const {
    switch (m.envmap) {
      case scenes::EnvmapSource::none: return nullptr;
      case scenes::EnvmapSource::texture: return cube_at(m.envmap_texture.texture);
      case scenes::EnvmapSource::nearest_sample: {
        const glm::vec3 c = mesh_center(scene_.meshes[index], offset_of(index));
        int best = -1;
        for (size_t i = 0; i < scene_.cubemap_samples.size(); ++i)
          if (best < 0 || glm::distance(scene_.cubemap_samples[i].position, c) <
                              glm::distance(scene_.cubemap_samples[size_t(best)].position, c))
            best = int(i);
        return best >= 0 ? sample_cube(best) : cube_at(scene_.sky_texture);
      }
    }
    return nullptr;
  }

  /// A LightmappedGeneric draw reflecting `env` (none: null).
  SourceDraw lightmapped(const scenes::Mesh& mesh, const scenes::Material& m, const DrawTarget& target, const GpuTexture* env) {
    if (!st_.lightmaps)
      throw std::invalid_argument(scene_.name + ": mesh '" + mesh.name +
                                  "' is LightmappedGeneric and the scene has no baked lightmaps (luxel bake)");
    if (mesh.uv1.empty())
      throw std::invalid_argument(scene_.name + ": mesh '" + mesh.name + "' is LightmappedGeneric and has no lightmap coordinates (uv1)");
    LightmappedMaterial lm;
    lm.bump = m.bump.bound();
    lm.envmap = env != nullptr;
    lm.mask = lightmapped_mask(m.envmap_mask);
    lm.base_translucent = m.base.bound() && st_.textures[static_cast<size_t>(m.base.texture)].translucent;
    if (lm.mask == EnvmapMask::normal_alpha && !lm.bump) lm.mask = EnvmapMask::none;
    lm.envmap_contrast = m.envmap_contrast;
    lm.envmap_saturation = m.envmap_saturation;
    lm.fresnel_reflection = m.fresnel_reflection;
    lm.selfillum_tint_not_one = m.self_illum && m.self_illum_tint != glm::vec3(1.0f);
    LightmappedCombo combo = choose_lightmapped_combo(lm);
    combo.fog = fog_;
    LightmappedGenericParams p;
    p.base = sampler2d(0, m.base);
    p.lightmap = Sampler2D{1, &st_.lightmaps->texture, drawn(st_.lightmaps->sampler)};
    if (env) p.envmap = SamplerCube{2, &env->texture, drawn(env->sampler)};
    p.bump = sampler2d(4, m.bump);
    p.envmap_mask = sampler2d(5, m.envmap_mask_texture);
    p.tint_lightmap_scale = glm::vec4(glm::vec3(m.color) * lightmap_scale_factor(LightmapFormat::hdr_float16), m.color.a);
    p.vertex_alpha.x = m.color.a;
    p.envmap_tint = glm::vec4(m.envmap_tint, 0.0f);
    p.envmap_contrast_saturation = glm::vec4(m.envmap_contrast, m.envmap_saturation, 0.0f, 0.0f);
    p.fresnel = fresnel_constant(m.fresnel_reflection);
    p.tonemap = tonemap_;
    p.fog = fog_constants_;
    return lightmapped_draw(combo, model_, target, p, st_.page, eye_);
  }

  SourceDraw vertexlit(size_t index, const scenes::Mesh& mesh, const scenes::Material& m, const DrawTarget& target) {
    // A model's lighting is its averaged one (renderer.hpp); a vertex-lit mesh outside models
    // does not move, and is lit as it is now.
    const int model = model_of_mesh_[index];
    const glm::vec3 centroid = model >= 0 ? st_.model_states[static_cast<size_t>(model)].centroid : mesh_center(mesh, glm::vec3(0.0f));
    // The SDK helper's choice of shader and combo (vertexlit_dispatch.hpp): Phong only in the
    // skin shader; the averaged shares rank the local lights the path takes.
    const GpuTexture* env = envmap_of(m, index);
    const VertexLitMaterial vm = generic_material(m, mesh, env);
    const FrameSettings::DispatchCards& cards = st_.settings.dispatch_cards;
    const VertexLitPath path = vertexlit_path(vm, cards.model_shader.value_or(model_));
    const bool half_lambert = vertexlit_half_lambert(vm, path);
    const int local_lights = vertexlit_max_lights(path, cards.light_count.value_or(model_), st_.settings.local_lights);
    const ModelLighting lighting =
        model >= 0 ? light_model(lights_, centroid, m, half_lambert, st_.model_lighting[static_cast<size_t>(model)], local_lights)
                   : light_model(lights_, centroid, m, half_lambert,
                                 lighting_at(scene_, lights_, centroid, st_.settings.ambient, st_.settings.local_lights),
                                 local_lights);
    if (path == VertexLitPath::plain) return vertexlit_per_vertex(m, vm, env, lighting, half_lambert, target);
    const VertexLitCombo wanted =
        vertexlit_combo(vm, path, lighting.kept, model_, {st_.settings.pixel_attenuation, fog_});
    const std::optional<VertexLitCombo> combo = fitting_vertexlit_combo(wanted, model_);
    if (!combo)
      throw std::invalid_argument(scene_.name + ": material '" + m.name + "': no VertexLitGeneric combo " + wanted.name() +
                                  " fits " + std::string(shading::caps(model_).name));
    VertexLitParams p;
    p.base = sampler2d(0, m.base);
    // The skin shader's full path reads a normal map, a flat one when the material has none.
    p.bump = m.bump.bound() ? sampler2d(3, m.bump) : Sampler2D{3, &st_.flat_normal.texture, drawn(st_.flat_normal.sampler)};
    p.phong_exponent = sampler2d(7, m.phong_exponent_texture);
    p.ambient = lighting.cube;
    p.lights = lighting.lights;
    p.eye_position = glm::vec4(eye_, 1.0f);
    p.modulation = m.color;
    const bool exponent_texture = m.phong_exponent_texture.bound();
    p.phong_tint_boost = glm::vec4(skin_specular_tint(m.phong_tint, m.phong_albedo_tint, exponent_texture), m.phong_boost);
    const SkinExponentConstants exponent =
        skin_exponent_constants(m.phong_exponent, m.phong_exponent_factor, path == VertexLitPath::skin && skin_fast_path(vm));
    p.phong_params = glm::vec4(exponent.exponent, std::max(m.rim_exponent, 1.0f), m.rim_boost, m.rim_mask ? 1.0f : 0.0f);
    p.shader_controls = glm::vec4(m.base_map_alpha_phong_mask ? 1.0f : 0.0f, exponent.texture_scale, 0.0f,
                                  m.invert_phong_mask ? 1.0f : 0.0f);
    p.fresnel_ranges = encode_fresnel_ranges(m.phong_fresnel_ranges.x, m.phong_fresnel_ranges.y, m.phong_fresnel_ranges.z);
    if (env) p.envmap = SamplerCube{8, &env->texture, drawn(env->sampler)};
    p.envmap_tint = glm::vec4(m.envmap_tint, skin_envmap_mask_control(vm));
    p.envmap_fresnel.x = m.envmap_fresnel;
    p.envmap_contrast = glm::vec4(m.envmap_contrast);
    p.envmap_saturation = glm::vec4(m.envmap_saturation);
    p.tonemap = tonemap_;
    p.fog = fog_constants_;
    if (combo->normalization_cube) {
      if (!st_.normalization_cube) st_.normalization_cube = GpuTexture{normalization_cube_map(), normalization_cube_sampler()};
      p.normalization_cube.texture = &st_.normalization_cube->texture;
      p.normalization_cube.state = drawn(st_.normalization_cube->sampler);
    }
    target.vertex->lights = lighting.lights;
    return vertexlit_draw(*combo, model_, target, p);
  }

  /// VertexLitGeneric without a bump map (vertexlit_and_unlit_generic_vs20 / _ps2x with
  /// DIFFUSELIGHTING): the vertex shader lights each vertex with the ambient cube and the kept
  /// lights, the pixel shader multiplies the albedo by the interpolated result and adds the env
  /// map `env` (none: null).
  SourceDraw vertexlit_per_vertex(const scenes::Material& m, const VertexLitMaterial& vm, const GpuTexture* env,
                                  const ModelLighting& lighting, bool half_lambert, const DrawTarget& target) {
    VertexLitVsCombo vs;
    vs.lights = lighting.kept > 0 ? 2 : 0;
    vs.half_lambert = half_lambert || vs.lights == 0;
    target.vertex->vertex_lighting = vertex_lighting_fn(vs);
    if (!target.vertex->vertex_lighting)
      throw std::logic_error("no VertexLitGeneric vertex shader combo " + vs.name());
    target.vertex->vertex_lighting_params.ambient = lighting.cube;
    target.vertex->vertex_lighting_params.lights = lighting.lights;
    return unlit_draw(generic_combo(vm, true, fog_), model_, target, generic_params(m, env), eye_);
  }

  /// What chooses a VertexLitGeneric or UnlitGeneric material's shader (vertexlit_dispatch.hpp),
  /// with the env map `env` it reflects (none: null).
  VertexLitMaterial generic_material(const scenes::Material& m, const scenes::Mesh& mesh, const GpuTexture* env) const {
    VertexLitMaterial vm = vertexlit_material(m);
    vm.envmap = env != nullptr;
    vm.base_translucent = m.base.bound() && st_.textures[static_cast<size_t>(m.base.texture)].translucent;
    vm.vertex_color = !mesh.colors.empty();
    return vm;
  }

  UnlitGenericParams generic_params(const scenes::Material& m, const GpuTexture* env) const {
    UnlitGenericParams p;
    p.base = sampler2d(0, m.base);
    if (env) p.envmap = SamplerCube{1, &env->texture, drawn(env->sampler)};
    p.envmap_mask = sampler2d(4, m.envmap_mask_texture);
    p.envmap_tint = glm::vec4(m.envmap_tint, 0.0f);
    p.modulation = m.color;
    p.envmap_contrast = glm::vec4(m.envmap_contrast);
    p.envmap_saturation = glm::vec4(m.envmap_saturation);
    p.tonemap = tonemap_;
    p.fog = fog_constants_;
    return p;
  }

  SourceDraw unlit(size_t index, const scenes::Mesh& mesh, const scenes::Material& m, const DrawTarget& target) {
    const GpuTexture* env = envmap_of(m, index);
    return unlit_draw(generic_combo(generic_material(m, mesh, env), false, fog_), model_, target, generic_params(m, env), eye_);
  }

  void queue(const scenes::Material& m, size_t index, Pass pass) {
    if (translucent(m)) {
      translucent_.emplace_back(glm::distance(mesh_center(scene_.meshes[index], offset_of(index)), eye_), std::move(pass));
    } else {
      out_.opaque.push_back(std::move(pass));
    }
  }

  FrameState& st_;
  const scenes::Scene& scene_;
  const ViewSpec& view_;
  PassList& out_;
  shading::ShaderModel model_;
  glm::vec3 eye_;
  float far_;
  glm::mat4 vp_;
  float exposure_ = 1.0f;
  ToneMapConstants tonemap_;
  FogSettings fog_settings_;
  Fog fog_ = Fog::none;
  FogConstants fog_constants_;
  std::vector<LightDesc> lights_;
  std::vector<int> model_of_mesh_;
  const scenes::Material default_material_;
  std::vector<std::pair<float, Pass>> translucent_;
};

}  // namespace

void build_view(FrameState& st, const ViewSpec& view, PassList& out) { FrameBuilder(st, view, out).build(); }

}  // namespace luxel::frame
