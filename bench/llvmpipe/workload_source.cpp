// W4 `source`: luxel's opaque pass drawn by llvmpipe. The scene and its bake come from luxel's
// libraries (source_inputs.hpp); the choices that make a draw (which meshes the opaque pass draws,
// each LightmappedGeneric combo, a model's ambient cube and local lights, the constants) are taken
// from luxel's code where it has them as functions: shading::source::choose_lightmapped_combo,
// the skin constants' helpers, and frame's model lighting (frame/src/model_lighting.hpp). The
// per-pixel arithmetic is the GLSL port in source_shaders.cpp.
//
// The W4 definition this follows (bench/README.md, "scripts/bench"): every mesh in scene order but
// water, sky and translucent ones; VertexLitGeneric per pixel with two local lights and
// attenuation per pixel, the skin shader's Phong and rim where the material asks; LightmappedGeneric
// reflecting the cube-map sample nearest its bounding box's center; range or height fog; the
// tone-map scale S (--exposure); the D3D9 sRGB write done in the shader into an RGBA8 target.

#include "workload_source.hpp"

#include "clip_space.hpp"
#include "gl_context.hpp"
#include "mesh_indices.hpp"
#include "source_inputs.hpp"
#include "source_shaders.hpp"
#include "source_textures.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/scenes/scene.hpp"
#include "luxel/shading/source/fog.hpp"
#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"
#include "model_lighting.hpp"  // frame's own (frame/src): the lighting luxel's renderer gives a model

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace luxel::llvmpipe {

namespace {

namespace source = shading::source;

/// Texture units, one per sampler a program may read.
enum Unit : GLint { kBase = 0, kLightmapPage, kEnvmap, kBump, kMask, kExponent };

/// One draw of the opaque pass: its mesh's buffers, its program, its textures and constants.
struct Draw {
  std::string label;  ///< mesh, family and combo, for stderr
  GLuint vertex_array = 0;
  std::vector<GLuint> buffers;
  MeshIndices indices;
  bool cull = true;
  GLuint program = 0;
  std::vector<std::pair<GLenum, GLuint>> textures;  ///< (target, name) per unit, in unit order from 0
  std::vector<std::function<void()>> uniforms;       ///< set before the draw (the programs are shared)
};

/// For the clear: luxel clears to the scene's background sRGB-encoded, as its 8-bit target stores it.
float srgb_encode(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

/// The programs, one per combo (the #define block is the key).
class ProgramCache {
 public:
  ~ProgramCache() {
    for (const auto& [defines, program] : programs_) glDeleteProgram(program);
  }
  GLuint get(const std::string& defines) {
    auto [it, added] = programs_.try_emplace(defines, 0);
    if (!added) return it->second;
    it->second = build_program(source_vertex_shader(), source_fragment_shader(defines));
    glUseProgram(it->second);
    // Every sampler to its own unit, once: the units are the same in every program.
    const std::pair<const char*, GLint> samplers[] = {{"baseTexture", kBase},   {"lightmapPage", kLightmapPage},
                                                      {"envmap", kEnvmap},      {"bumpTexture", kBump},
                                                      {"maskTexture", kMask},   {"exponentTexture", kExponent}};
    for (const auto& [name, unit] : samplers) glUniform1i(glGetUniformLocation(it->second, name), unit);
    return it->second;
  }
  size_t size() const { return programs_.size(); }

 private:
  std::map<std::string, GLuint> programs_;
};

/// Closures that set one uniform of `program` (looked up once, set at every draw).
struct UniformList {
  GLuint program;
  std::vector<std::function<void()>>& out;
  void vec4(const char* name, glm::vec4 v) {
    const GLint at = glGetUniformLocation(program, name);
    if (at >= 0) out.push_back([at, v] { glUniform4f(at, v.x, v.y, v.z, v.w); });
  }
  void vec3(const char* name, glm::vec3 v) {
    const GLint at = glGetUniformLocation(program, name);
    if (at >= 0) out.push_back([at, v] { glUniform3f(at, v.x, v.y, v.z); });
  }
  void vec2(const char* name, glm::vec2 v) {
    const GLint at = glGetUniformLocation(program, name);
    if (at >= 0) out.push_back([at, v] { glUniform2f(at, v.x, v.y); });
  }
  void scalar(const char* name, float v) {
    const GLint at = glGetUniformLocation(program, name);
    if (at >= 0) out.push_back([at, v] { glUniform1f(at, v); });
  }
  template <size_t N>
  void vec3_array(const char* name, const std::array<glm::vec3, N>& v) {
    const GLint at = glGetUniformLocation(program, name);
    if (at >= 0) out.push_back([at, v] { glUniform3fv(at, GLsizei(N), glm::value_ptr(v[0])); });
  }
  void vec4_array(const char* name, const std::vector<glm::vec4>& v) {
    const GLint at = glGetUniformLocation(program, name);
    if (at >= 0) out.push_back([at, v] { glUniform4fv(at, GLsizei(v.size()), glm::value_ptr(v[0])); });
  }
};

std::string fog_defines(source::Fog fog) {
  if (fog == source::Fog::range) return "#define FOG_RANGE\n";
  if (fog == source::Fog::height) return "#define FOG_HEIGHT\n";
  return "";
}

glm::vec3 bounds_center(const scenes::Mesh& mesh) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return 0.5f * (lo + hi);
}

/// The cube-map sample nearest `point` (the first on ties), or -1 without samples.
int nearest_sample(const scenes::Scene& scene, glm::vec3 point) {
  int best = -1;
  float best_d2 = std::numeric_limits<float>::infinity();
  for (size_t i = 0; i < scene.cubemap_samples.size(); ++i) {
    const glm::vec3 d = scene.cubemap_samples[i].position - point;
    const float d2 = glm::dot(d, d);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = int(i);
    }
  }
  return best;
}

class Source final : public Workload {
 public:
  Source(scenes::Scene scene, const SourceOptions& options, int width, int height)
      : scene_(std::move(scene)), textures_(scene_) {
    if (scene_.cameras.empty()) throw Skipped("the glTF file has no camera");
    const scenes::Camera& camera = scene_.cameras.front();
    if (camera.projection != scenes::Projection::perspective) throw Skipped("camera is not perspective (W4 draws perspective cameras only)");
    eye_ = camera.position;
    // luxel's clip space (Direct3D's): z is the projected z the pixel fog reads.
    const glm::mat4 direct3d = frame::view_projection(camera, width, height);
    view_projection_ = opengl_clip(direct3d);
    fog_z_row_ = glm::vec4(direct3d[0][2], direct3d[1][2], direct3d[2][2], direct3d[3][2]);
    exposure_ = options.exposure;
    // FrameBuilder's fog: the scene's fog controller, range fog on ps_3_0 (its pixel fog).
    source::FogSettings fog;
    if (scene_.fog.mode != scenes::FogMode::none) {
      fog.start = scene_.fog.start;
      fog.end = scene_.fog.end;
      fog.max_density = scene_.fog.max_density;
      fog.color = scene_.fog.color;
      fog.water_z = scene_.fog.water_z;
      fog_ = scene_.fog.mode == scenes::FogMode::height ? source::Fog::height : source::Fog::range;
    }
    fog_constants_ = source::fog_constants(fog, eye_, exposure_);
    clear_ = glm::vec4(srgb_encode(scene_.background.r), srgb_encode(scene_.background.g), srgb_encode(scene_.background.b), 1.0f);
    lights_ = frame::light_descriptions(scene_);

    model_of_mesh_.assign(scene_.meshes.size(), -1);
    for (size_t i = 0; i < scene_.models.size(); ++i)
      for (int m : scene_.models[i].meshes)
        if (m >= 0 && size_t(m) < scene_.meshes.size()) model_of_mesh_[size_t(m)] = int(i);

    size_t triangles = 0;
    for (size_t i = 0; i < scene_.meshes.size(); ++i) {
      const scenes::Mesh& mesh = scene_.meshes[i];
      const scenes::Material& m = mesh.material >= 0 ? scene_.materials.at(size_t(mesh.material)) : default_material_;
      // luxel's other passes: the water, the sky, the translucent meshes.
      if (m.family == scenes::ShaderFamily::water || m.family == scenes::ShaderFamily::sky || m.translucent ||
          m.alpha == scenes::AlphaMode::blend) {
        std::fprintf(stderr, "source: not drawn: '%s' (another pass of luxel's frame)\n", mesh.name.c_str());
        continue;
      }
      if (m.alpha == scenes::AlphaMode::alpha_test)
        throw Skipped("material '" + m.name + "' is alpha-tested, which W4 does not port");
      Draw d = make_geometry(mesh, m);
      switch (m.family) {
        case scenes::ShaderFamily::lightmapped_generic: lightmapped(d, mesh, m); break;
        case scenes::ShaderFamily::vertexlit_generic: vertexlit(d, i, mesh, m); break;
        default: unlit(d, mesh, m); break;
      }
      d.label = mesh.name + ": " + d.label;
      std::fprintf(stderr, "source: draw %s, %d triangles\n", d.label.c_str(), int(d.indices.count / 3));
      triangles += size_t(d.indices.count / 3);
      draws_.push_back(std::move(d));
    }
    std::fprintf(stderr, "source: %zu draws, %zu triangles, %zu programs; eye (%.1f, %.1f, %.1f), tone-map scale %g\n",
                 draws_.size(), triangles, programs_.size(), eye_.x, eye_.y, eye_.z, exposure_);
    check_gl("preparing source");
  }

  ~Source() override {
    for (const Draw& d : draws_) {
      glDeleteBuffers(GLsizei(d.buffers.size()), d.buffers.data());
      glDeleteVertexArrays(1, &d.vertex_array);
    }
  }

  glm::vec4 clear_color() const override { return clear_; }

  void draw() const override {
    depth_tested_without_blending();
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    for (const Draw& d : draws_) {
      if (d.cull)
        glEnable(GL_CULL_FACE);
      else
        glDisable(GL_CULL_FACE);
      glUseProgram(d.program);
      for (const auto& set : d.uniforms) set();
      for (size_t unit = 0; unit < d.textures.size(); ++unit) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(d.textures[unit].first, d.textures[unit].second);
      }
      glBindVertexArray(d.vertex_array);
      draw_triangles(d.indices);
    }
  }

 private:
  template <class T>
  GLuint attribute(Draw& d, GLuint location, const std::vector<T>& data, GLint components) {
    GLuint buffer = 0;
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
    d.buffers.push_back(buffer);
    return buffer;
  }

  /// The mesh's vertex streams (missing ones as luxel's vertex stage reads them: normal +Z,
  /// tangent +X with w 1, uv (0, 0), color white) and its indices.
  Draw make_geometry(const scenes::Mesh& mesh, const scenes::Material& m) {
    Draw d;
    d.cull = !m.double_sided;
    glGenVertexArrays(1, &d.vertex_array);
    glBindVertexArray(d.vertex_array);
    attribute(d, 0, mesh.positions, 3);
    if (!mesh.normals.empty()) attribute(d, 1, mesh.normals, 3);
    else glVertexAttrib3f(1, 0.0f, 0.0f, 1.0f);
    if (!mesh.tangents.empty()) attribute(d, 2, mesh.tangents, 4);
    else glVertexAttrib4f(2, 1.0f, 0.0f, 0.0f, 1.0f);
    // Every texture of the material reads the base texture's uv, transformed (luxel's vertex stage).
    const std::vector<glm::vec2>& uv_set = m.base.uv_set == 1 ? mesh.uv1 : mesh.uv0;
    if (!uv_set.empty()) {
      const scenes::UvTransform transform = scenes::UvTransform::of(m.base);
      std::vector<glm::vec2> uvs(uv_set.size());
      for (size_t i = 0; i < uvs.size(); ++i) uvs[i] = transform(uv_set[i]);
      attribute(d, 3, uvs, 2);
    } else {
      glVertexAttrib2f(3, 0.0f, 0.0f);
    }
    if (!mesh.uv1.empty()) attribute(d, 4, mesh.uv1, 2);
    else glVertexAttrib2f(4, 0.0f, 0.0f);
    if (!mesh.colors.empty()) attribute(d, 5, mesh.colors, 4);
    else glVertexAttrib4f(5, 1.0f, 1.0f, 1.0f, 1.0f);

    const MeshIndices indices = upload_indices(mesh);
    if (indices.buffer) d.buffers.push_back(indices.buffer);
    d.indices = indices;
    glBindVertexArray(0);
    return d;
  }

  /// What every program reads: the camera, the tone map, the fog.
  void common_uniforms(Draw& d) {
    UniformList u{d.program, d.uniforms};
    const GLint vp = glGetUniformLocation(d.program, "viewProjection");
    const glm::mat4 view_projection = view_projection_;
    d.uniforms.push_back([vp, view_projection] { glUniformMatrix4fv(vp, 1, GL_FALSE, glm::value_ptr(view_projection)); });
    u.vec4("fogZRow", fog_z_row_);
    u.scalar("toneScale", exposure_);
    u.vec4("fogParams", fog_constants_.params);
    u.vec3("fogColor", glm::vec3(fog_constants_.color));
    u.vec3("eyePosition", eye_);
  }

  /// The texture units in order: base, lightmap page, env map, bump, mask, exponent.
  void bind(Draw& d, GLuint base, GLuint page, GLuint envmap, GLuint bump, GLuint mask, GLuint exponent) {
    d.textures = {{GL_TEXTURE_2D, base},  {GL_TEXTURE_2D, page}, {GL_TEXTURE_CUBE_MAP, envmap},
                  {GL_TEXTURE_2D, bump}, {GL_TEXTURE_2D, mask}, {GL_TEXTURE_2D, exponent}};
  }

  /// The scene texture of the cube map `m` reads on `mesh` (the sample nearest the mesh's
  /// bounds centre, or its own cube texture); -1 for none.
  int envmap_cube(const scenes::Mesh& mesh, const scenes::Material& m) const {
    if (m.envmap == scenes::EnvmapSource::nearest_sample) {
      const int sample = nearest_sample(scene_, bounds_center(mesh));
      return sample >= 0 ? scene_.cubemap_samples[size_t(sample)].texture : -1;
    }
    return m.envmap == scenes::EnvmapSource::texture ? m.envmap_texture.texture : -1;
  }

  /// renderer.cpp's FrameBuilder::lightmapped, with the env map of the nearest sample.
  void lightmapped(Draw& d, const scenes::Mesh& mesh, const scenes::Material& m) {
    if (!scene_.lightmaps) throw Skipped("mesh '" + mesh.name + "' is LightmappedGeneric and the bake has no lightmaps");
    if (mesh.uv1.empty()) throw Skipped("mesh '" + mesh.name + "' is LightmappedGeneric and has no TEXCOORD_1");
    const int cube = envmap_cube(mesh, m);
    source::LightmappedMaterial lm;
    lm.bump = m.bump.bound();
    lm.envmap = cube >= 0;
    switch (m.envmap_mask) {
      case scenes::EnvmapMask::none: lm.mask = source::EnvmapMask::none; break;
      case scenes::EnvmapMask::texture: lm.mask = source::EnvmapMask::texture; break;
      case scenes::EnvmapMask::base_alpha: lm.mask = source::EnvmapMask::base_alpha_inverted; break;
      case scenes::EnvmapMask::normal_alpha: lm.mask = source::EnvmapMask::normal_alpha; break;
    }
    lm.base_translucent = m.base.bound() && scenes::has_translucent_texels(scene_.textures.at(size_t(m.base.texture)));
    if (lm.mask == source::EnvmapMask::normal_alpha && !lm.bump) lm.mask = source::EnvmapMask::none;
    lm.envmap_contrast = m.envmap_contrast;
    lm.envmap_saturation = m.envmap_saturation;
    lm.fresnel_reflection = m.fresnel_reflection;
    lm.selfillum_tint_not_one = m.self_illum && m.self_illum_tint != glm::vec3(1.0f);
    source::LightmappedCombo combo = source::choose_lightmapped_combo(lm);
    combo.fog = fog_;
    if (!combo.valid()) throw Skipped("mesh '" + mesh.name + "': LightmappedGeneric combo " + combo.name() + " is not a valid one");

    std::string defines = "#define LIGHTMAPPED_GENERIC\n" + fog_defines(combo.fog);
    if (combo.bump) defines += "#define BUMP\n";
    if (combo.envmap) defines += "#define ENVMAP\n";
    if (combo.mask == source::EnvmapMask::base_alpha_inverted) defines += "#define MASK_BASE_ALPHA\n";
    if (combo.mask == source::EnvmapMask::normal_alpha) defines += "#define MASK_NORMAL_ALPHA\n";
    if (combo.mask == source::EnvmapMask::texture) defines += "#define MASK_TEXTURE\n";
    if (combo.path == source::EnvmapPath::fast_contrast) defines += "#define PATH_CONTRAST1\n";
    if (combo.path == source::EnvmapPath::full) defines += "#define PATH_FULL\n";
    d.program = programs_.get(defines);
    d.label = "LightmappedGeneric " + combo.name() + (cube >= 0 ? ", cube texture " + std::to_string(cube) : "");

    source::LightmapPage page;
    const GLuint page_texture = textures_.lightmap_page(page);
    bind(d, textures_.flat(m.base), page_texture, textures_.cube(cube), textures_.flat(m.bump),
         textures_.flat(m.envmap_mask_texture), textures_.white());
    common_uniforms(d);
    UniformList u{d.program, d.uniforms};
    u.vec4("lightmapOffset", glm::vec4(page.offset[0], page.offset[1], page.offset[2], page.offset[3]));
    u.scalar("lightmapScale", page.scale);
    u.vec3("lightmapTint", glm::vec3(m.color) * source::lightmap_scale_factor(source::LightmapFormat::hdr_float16));
    u.vec3("envmapTint", m.envmap_tint);
    u.vec2("contrastSaturation", glm::vec2(m.envmap_contrast, m.envmap_saturation));
    const glm::vec4 fresnel = source::fresnel_constant(m.fresnel_reflection);
    u.vec2("fresnel", glm::vec2(fresnel.z, fresnel.w));
  }

  /// Per-pixel VertexLitGeneric with the skin shader's Phong, lit as luxel's renderer lights a
  /// model at rest in its first frame (frame/src/model_lighting.hpp).
  void vertexlit(Draw& d, size_t index, const scenes::Mesh& mesh, const scenes::Material& m) {
    const int model = model_of_mesh_[index];
    const glm::vec3 centroid = model >= 0 ? scene_.models[size_t(model)].centroid : bounds_center(mesh);
    source::VertexLitCombo combo;
    combo.lights = lights_.empty() ? 0 : 2;
    combo.bump = m.bump.bound();
    combo.phong = m.phong;
    combo.rim = m.phong && m.rim && combo.bump;
    combo.half_lambert = m.half_lambert || m.phong;
    combo.pixel_attenuation = true;
    combo.fog = fog_;
    const frame::AveragedLighting at_rest =
        frame::lighting_at(scene_, lights_, centroid, frame::AmbientSampling::nearest, 2);
    const frame::ModelLighting lighting = frame::light_model(lights_, centroid, m, combo.half_lambert, at_rest, 2);
    if (lighting.kept < combo.lights) combo.lights = lighting.kept;

    std::string defines = "#define VERTEXLIT_GENERIC\n#define LIGHTS " + std::to_string(combo.lights) + "\n" + fog_defines(combo.fog);
    if (combo.bump) defines += "#define BUMP\n";
    if (combo.phong) defines += "#define PHONG\n";
    if (combo.rim) defines += "#define RIM\n";
    if (combo.half_lambert) defines += "#define HALF_LAMBERT\n";
    d.program = programs_.get(defines);
    d.label = "VertexLitGeneric " + combo.name() + ", local lights " + std::to_string(lighting.local[0]) + " " +
              std::to_string(lighting.local[1]);

    bind(d, textures_.flat(m.base), textures_.white(), textures_.white_cube(), textures_.flat(m.bump), textures_.white(),
         textures_.flat(m.phong_exponent_texture));
    common_uniforms(d);
    UniformList u{d.program, d.uniforms};
    u.vec3_array("ambientCube", lighting.cube.color);
    std::vector<glm::vec4> color, position, spot_direction, spot_params, attenuation;
    for (int i = 0; i < 2; ++i) {
      const source::LocalLight& l = lighting.lights[size_t(i)];
      color.push_back(l.color);
      position.push_back(l.position);
      spot_direction.push_back(l.spot_direction);
      spot_params.push_back(l.spot_params);
      attenuation.push_back(l.attenuation);
    }
    u.vec4_array("lightColor", color);
    u.vec4_array("lightPosition", position);
    u.vec4_array("lightSpotDirection", spot_direction);
    u.vec4_array("lightSpotParams", spot_params);
    u.vec4_array("lightAttenuation", attenuation);
    u.vec4("modulation", m.color);
    // The skin shader's constants as luxel's renderer sets them (skin_dx9_helper.cpp's rules).
    const bool exponent_texture = m.phong_exponent_texture.bound();
    u.vec4("phongTintBoost", glm::vec4(source::skin_specular_tint(m.phong_tint, m.phong_albedo_tint, exponent_texture), m.phong_boost));
    const source::SkinExponentConstants exponent =
        source::skin_exponent_constants(m.phong_exponent, m.phong_exponent_factor, !combo.bump);
    u.vec4("phongParams", glm::vec4(exponent.exponent, std::max(m.rim_exponent, 1.0f), m.rim_boost, m.rim_mask ? 1.0f : 0.0f));
    u.vec4("shaderControls", glm::vec4(m.base_map_alpha_phong_mask ? 1.0f : 0.0f, exponent.texture_scale, 0.0f,
                                       m.invert_phong_mask ? 1.0f : 0.0f));
    u.vec4("fresnelRanges", source::encode_fresnel_ranges(m.phong_fresnel_ranges.x, m.phong_fresnel_ranges.y, m.phong_fresnel_ranges.z));
  }

  void unlit(Draw& d, const scenes::Mesh& mesh, const scenes::Material& m) {
    const int cube = envmap_cube(mesh, m);
    std::string defines = "#define UNLIT_GENERIC\n" + fog_defines(fog_);
    std::string name = "base";
    if (cube >= 0) {
      defines += "#define ENVMAP\n";
      name += "+envmap";
      if (m.envmap_mask == scenes::EnvmapMask::texture) defines += "#define MASK_TEXTURE\n", name += "+envmapmask";
      if (m.envmap_mask == scenes::EnvmapMask::base_alpha) defines += "#define MASK_BASE_ALPHA\n", name += "+basealphamask";
    }
    if (!mesh.colors.empty()) defines += "#define VERTEX_COLOR\n", name += "+vertexcolor";
    d.program = programs_.get(defines);
    d.label = "UnlitGeneric " + name + source::fog_name(fog_);
    bind(d, textures_.flat(m.base), textures_.white(), textures_.cube(cube), textures_.white(),
         textures_.flat(m.envmap_mask_texture), textures_.white());
    common_uniforms(d);
    UniformList u{d.program, d.uniforms};
    u.vec4("modulation", m.color);
    u.vec3("envmapTint", m.envmap_tint);
    u.vec2("contrastSaturation", glm::vec2(m.envmap_contrast, m.envmap_saturation));
  }

  scenes::Scene scene_;
  SourceTextures textures_;
  ProgramCache programs_;
  const scenes::Material default_material_{};
  std::vector<source::LightDesc> lights_;
  std::vector<int> model_of_mesh_;
  glm::vec3 eye_{0.0f};
  glm::mat4 view_projection_{1.0f};
  glm::vec4 fog_z_row_{0.0f};
  float exposure_ = 1.0f;
  source::Fog fog_ = source::Fog::none;
  source::FogConstants fog_constants_;
  glm::vec4 clear_{0.0f};
  std::vector<Draw> draws_;
};

}  // namespace

std::unique_ptr<Workload> make_source(const SourceOptions& options, int width, int height) {
  return std::make_unique<Source>(load_baked_scene(options.path, options.camera), options, width, height);
}

}  // namespace luxel::llvmpipe
