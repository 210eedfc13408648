#pragma once
// Private: the vertex stage of the Source frame. One functor type per varying count: it writes,
// per vertex, the attributes a pixel shader's combo lists (shading/source/adapter.hpp), in that
// order, so that every combo with the same number of varyings shares one compiled front end.
// VertexLitGeneric without a bump map is lit here, by the lane-language vertex shader's lighting
// (shading/source/vertexlit_vertex_shader.hpp), the code `luxel cost` counts.

#include "luxel/rasterizer/draw.hpp"
#include "luxel/scenes/scene.hpp"
#include "luxel/shading/source/adapter.hpp"
#include "luxel/shading/source/vertexlit_vertex_shader.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <array>
#include <optional>

namespace luxel::frame {

/// What the vertex stage reads and how: a mesh's streams, the transforms, the constants of the
/// per-vertex terms. Lives in the renderer's state for as long as its draws.
struct VertexSetup {
  const glm::vec3* positions = nullptr;
  std::optional<glm::vec3> offset;      ///< a moving model's translation (scenes/paths.hpp), added to the positions
  const glm::vec3* normals = nullptr;   ///< or null: +Z
  const glm::vec4* tangents = nullptr;  ///< or null: +X, w = 1
  const glm::vec2* uv0 = nullptr;       ///< or null: (0, 0)
  const glm::vec2* uv1 = nullptr;       ///< or null: (0, 0)
  const glm::vec4* colors = nullptr;    ///< or null: white
  scenes::UvTransform base_transform;   ///< the material's base-texture transform
  glm::mat4 view_projection{1.0f};
  /// Set when the view's near plane is oblique (views.hpp): proj_z is this row times the
  /// position, the view's ordinary projected depth, rather than the clip-space z.
  std::optional<glm::vec4> proj_z_row;
  shading::source::AttributeList attributes;
  std::array<shading::source::LocalLight, 4> lights{};  ///< for the per-vertex attenuation attributes
  /// For the lighting attributes: the vertex shader's lighting of its combo, and its constants
  /// (the ambient cube and the lights; the transforms are the ones above).
  shading::source::VertexLightingFn vertex_lighting = nullptr;
  shading::source::VertexLitVsParams vertex_lighting_params;
  glm::vec4 fog_c16{1.0f, 1.0f, 1.0f, 0.0f};            ///< vertex_fog_constant(): visibility 1
  bool at_far_plane = false;  ///< depth 1 everywhere (the sky, as Source draws it with MinZ = MaxZ = 1)
};

template <int N>
struct SourceVertex {
  static constexpr int kVaryings = N;
  const VertexSetup* setup;

  const void* input(uint32_t i) const { return setup->positions + i; }

  void operator()(uint32_t i, rasterizer::VertexOutput<N>& out) const {
    using shading::source::Attribute;
    const VertexSetup& s = *setup;
    const glm::vec3 p = s.offset ? s.positions[i] + *s.offset : s.positions[i];
    glm::vec4 clip = s.view_projection * glm::vec4(p, 1.0f);
    const float proj_z = s.proj_z_row ? glm::dot(*s.proj_z_row, glm::vec4(p, 1.0f)) : clip.z;
    if (s.at_far_plane) clip.z = clip.w;
    out.position = clip;
    const glm::vec3 n = s.normals ? s.normals[i] : glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec4 t = s.tangents ? s.tangents[i] : glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    const glm::vec2 uv = s.base_transform(s.uv0 ? s.uv0[i] : glm::vec2(0.0f));
    const glm::vec2 lightmap_uv = s.uv1 ? s.uv1[i] : glm::vec2(0.0f);
    const glm::vec4 color = s.colors ? s.colors[i] : glm::vec4(1.0f);
    glm::vec3 binormal(0.0f);
    if (s.tangents) binormal = t.w * glm::cross(n, glm::vec3(t));
    const glm::vec3 lighting = s.vertex_lighting ? s.vertex_lighting(p, n, s.vertex_lighting_params) : glm::vec3(0.0f);
    auto value = [&](Attribute a) -> float {
      switch (a) {
        case Attribute::world_x: return p.x;
        case Attribute::world_y: return p.y;
        case Attribute::world_z: return p.z;
        case Attribute::proj_z: return proj_z;
        case Attribute::normal_x: return n.x;
        case Attribute::normal_y: return n.y;
        case Attribute::normal_z: return n.z;
        case Attribute::tangent_x: return t.x;
        case Attribute::tangent_y: return t.y;
        case Attribute::tangent_z: return t.z;
        case Attribute::binormal_x: return s.tangents ? binormal.x : 0.0f;
        case Attribute::binormal_y: return s.tangents ? binormal.y : 1.0f;
        case Attribute::binormal_z: return s.tangents ? binormal.z : 0.0f;
        case Attribute::base_u: return uv.x;
        case Attribute::base_v: return uv.y;
        case Attribute::lightmap_u: return lightmap_uv.x;
        case Attribute::lightmap_v: return lightmap_uv.y;
        case Attribute::color_r: return color.r;
        case Attribute::color_g: return color.g;
        case Attribute::color_b: return color.b;
        case Attribute::color_a: return color.a;
        case Attribute::attenuation_0: return shading::source::vertex_light_attenuation(p, s.lights[0]);
        case Attribute::attenuation_1: return shading::source::vertex_light_attenuation(p, s.lights[1]);
        case Attribute::attenuation_2: return shading::source::vertex_light_attenuation(p, s.lights[2]);
        case Attribute::attenuation_3: return shading::source::vertex_light_attenuation(p, s.lights[3]);
        case Attribute::light_r: return lighting.r;
        case Attribute::light_g: return lighting.g;
        case Attribute::light_b: return lighting.b;
        case Attribute::fog_visibility: return shading::source::vertex_fog<float>(proj_z, s.fog_c16);
      }
      return 0.0f;
    };
    for (int k = 0; k < 4 * N; ++k) {
      const float v = k < s.attributes.count ? value(s.attributes.items[static_cast<size_t>(k)]) : 0.0f;
      out.varyings[static_cast<size_t>(k / 4)][k % 4] = v;
    }
  }
};

}  // namespace luxel::frame
