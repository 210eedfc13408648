#pragma once
// The scene model: everything a frame draws, as plain data. A scene is read from a file
// (gltf.hpp), built in code (builtin.hpp) or baked into (the optional Lightmaps and
// IrradianceVolume parts); it never renders itself, and it knows nothing about tiles or shaders.
//
// Units and axes are Source's: inches, right-handed, +Z up. glTF's meters with +Y up map by
//   source = (x, -z, y) * kInchesPerMeter
// on import, and back on export (gltf.hpp documents the whole mapping). Colors are linear unless
// a texture says otherwise; light colors are linear HDR.

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace luxel::scenes {

/// Source's unit is the inch; glTF's is the meter.
inline constexpr float kInchesPerMeter = 39.37007874f;

// --- Textures ------------------------------------------------------------------------------------

/// How the bytes of an image encode color. Base and detail textures are sRGB; normal maps, masks,
/// exponent textures, lightmaps and HDR images are linear.
enum class ColorSpace : uint8_t { srgb, linear };

/// A plain image, row-major, top row first, 4 channels (missing channels: alpha 1, grey replicated).
/// Either 8-bit (`rgba8`) or 32-bit float (`rgba32f`, HDR skies and probes), never both.
struct PixelImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba8;    ///< width * height * 4 bytes, or empty
  std::vector<float> rgba32f;    ///< width * height * 4 floats, or empty
  bool is_hdr() const { return !rgba32f.empty(); }
};

/// What shape a texture is. A cube map holds six square faces in D3D order (+X, -X, +Y, -Y, +Z,
/// -Z), each a PixelImage of the same size.
enum class TextureShape : uint8_t { flat, cube };

enum class Wrap : uint8_t { repeat, mirror, clamp };
enum class Filter : uint8_t { nearest, linear };

/// A texture as the frame will upload it once: images plus sampler state. Mips are made by the
/// frame (the rasterizer generates them); a scene stores level 0 only.
struct Texture {
  std::string name;                 ///< for messages and `luxel info` (the file name, or a built-in name)
  TextureShape shape = TextureShape::flat;
  ColorSpace color_space = ColorSpace::srgb;
  std::vector<PixelImage> faces;    ///< 1 (flat) or 6 (cube)
  Wrap wrap_u = Wrap::repeat, wrap_v = Wrap::repeat;
  Filter mag = Filter::linear, min = Filter::linear;
  bool mipmaps = true;              ///< trilinear; false: the base level only
};

/// A material's reference to a texture, with the UV set it reads and KHR_texture_transform:
/// uv' = offset + R (scale * uv), R = [cos r, sin r; -sin r, cos r] (the extension's matrix).
struct TextureRef {
  int texture = -1;                 ///< index into Scene::textures; -1 = none
  int uv_set = 0;                   ///< 0 or 1
  glm::vec2 offset{0.0f}, scale{1.0f};
  float rotation = 0.0f;            ///< radians, r above
  bool bound() const { return texture >= 0; }
};

/// A TextureRef's transform with its sine and cosine taken once, for applying it per vertex.
struct UvTransform {
  glm::vec2 offset{0.0f}, scale{1.0f};
  float cos_r = 1.0f, sin_r = 0.0f;
  static UvTransform of(const TextureRef& ref);
  glm::vec2 operator()(glm::vec2 uv) const {
    const glm::vec2 s = uv * scale;
    return offset + glm::vec2(cos_r * s.x + sin_r * s.y, cos_r * s.y - sin_r * s.x);
  }
};

// --- Materials -----------------------------------------------------------------------------------

/// The Source shader families a material can be drawn with.
enum class ShaderFamily : uint8_t { lightmapped_generic, vertexlit_generic, unlit_generic, water, sky };

enum class AlphaMode : uint8_t { opaque, alpha_test, blend };

/// Where an env map comes from: none, a texture of the material's own, or the nearest
/// CubemapSample (Source's `env_cubemap`).
enum class EnvmapSource : uint8_t { none, texture, nearest_sample };

/// What masks env-map specular (as the .vmt flags): nothing, a texture of its own, the base
/// texture's alpha or the normal map's alpha.
enum class EnvmapMask : uint8_t { none, texture, base_alpha, normal_alpha };

/// A Source material: a shader family and its .vmt parameters. Parameters a family does not read
/// are ignored by it (and reported by `luxel info`).
struct Material {
  std::string name;
  ShaderFamily family = ShaderFamily::vertexlit_generic;

  TextureRef base;                  ///< $basetexture (sRGB); alpha: opacity or a mask, per flags
  glm::vec4 color{1.0f};            ///< $color (linear rgb) and $alpha
  TextureRef bump;                  ///< $bumpmap (linear, tangent space, +Y up: OpenGL/glTF convention)
  TextureRef detail;                ///< $detail
  float detail_scale = 4.0f;        ///< $detailscale
  float detail_blend = 1.0f;        ///< $detailblendfactor

  EnvmapSource envmap = EnvmapSource::none;
  TextureRef envmap_texture;        ///< when envmap == texture: a cube
  EnvmapMask envmap_mask = EnvmapMask::none;
  TextureRef envmap_mask_texture;   ///< when envmap_mask == texture
  glm::vec3 envmap_tint{1.0f};      ///< $envmaptint
  float envmap_contrast = 0.0f;     ///< $envmapcontrast
  float envmap_saturation = 1.0f;   ///< $envmapsaturation
  float envmap_fresnel = 0.0f;      ///< $envmapfresnel (the skin shader: how much the Phong Fresnel ranges scale the env map)
  float fresnel_reflection = 1.0f;  ///< $fresnelreflection (LightmappedGeneric)

  bool phong = false;               ///< $phong (VertexLitGeneric)
  /// $phongexponent; 0 or less: unset (the exponent texture's, else 150; docs/fidelity.md#phong-defaults)
  float phong_exponent = 0.0f;
  float phong_boost = 1.0f;         ///< $phongboost
  glm::vec3 phong_fresnel_ranges{0.0f, 0.5f, 1.0f};  ///< $phongfresnelranges
  /// $phongexponentfactor; not 0: the exponent is 1 + factor x the exponent texture's r
  float phong_exponent_factor = 0.0f;
  /// $phongtint; all zero: none (white, or the albedo tint with $phongalbedotint)
  glm::vec3 phong_tint{1.0f};
  bool phong_albedo_tint = false;   ///< $phongalbedotint: with no tint, tint by the albedo where the exponent texture's g says
  TextureRef phong_exponent_texture;  ///< $phongexponenttexture: r = exponent, g = albedo tint mask
  bool invert_phong_mask = false;   ///< $invertphongmask: the skin shader's env map masked by 1 - its mask
  bool base_map_alpha_phong_mask = false;  ///< $basemapalphaphongmask (else the normal map's alpha)
  bool rim = false;                 ///< $rimlight
  float rim_exponent = 4.0f;        ///< $rimlightexponent
  float rim_boost = 1.0f;           ///< $rimlightboost
  bool rim_mask = false;            ///< $rimmask: the exponent texture's alpha masks rim
  bool half_lambert = false;        ///< $halflambert
  float hero_boost = 1.0f;          ///< ambient boost of the hero model (Episode 1's AmbientBoost)

  bool self_illum = false;          ///< $selfillum: the base alpha scales self-illumination
  glm::vec3 self_illum_tint{1.0f};  ///< $selfillumtint
  glm::vec3 emissive{0.0f};         ///< linear HDR emission (glTF emissive x emissive_strength)

  AlphaMode alpha = AlphaMode::opaque;
  float alpha_cutoff = 0.5f;        ///< $alphatestreference
  bool translucent = false;         ///< $translucent (drawn after opaque, back to front)
  bool double_sided = false;        ///< $nocull
  bool linear_write = false;        ///< $linearwrite (UnlitGeneric): the result is written to the 8-bit
                                    ///< target as it is, not sRGB-encoded (the peer workloads' output)

  // Water.
  TextureRef water_normal;          ///< $normalmap
  glm::vec2 water_scroll{0.0f};     ///< $scroll1 (uv per second); nonzero = the multitexture combo
  bool water_blur_refract = false;  ///< $blurrefract: the refraction blurred (25 taps), ps_2_b and up
  float reflect_amount = 0.8f, refract_amount = 0.0f;
  glm::vec3 reflect_tint{1.0f}, refract_tint{1.0f};
  glm::vec3 water_fog_color{0.0f};
  float water_fog_start = 0.0f, water_fog_end = 500.0f;  ///< inches below the surface
};

// --- Geometry ------------------------------------------------------------------------------------

/// 16- or 32-bit triangle-list indices (three per triangle, counter-clockwise seen from the front).
/// Empty: the mesh is not indexed, every three consecutive vertices are one triangle.
using Indices = std::variant<std::vector<uint16_t>, std::vector<uint32_t>>;

/// One triangle list with one material. Per-vertex arrays are either empty or as long as
/// `positions`. Positions and normals are in world space (the node hierarchy is flattened on import).
struct Mesh {
  std::string name;
  int material = -1;                ///< index into Scene::materials (-1: the default material)
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;   ///< unit
  std::vector<glm::vec4> tangents;  ///< xyz unit, w = +-1 handedness: bitangent = w * cross(n, t)
  std::vector<glm::vec2> uv0;       ///< texture coordinates (glTF convention: v down the image)
  std::vector<glm::vec2> uv1;       ///< lightmap coordinates
  std::vector<glm::vec4> colors;    ///< linear rgba
  Indices indices;

  size_t vertex_count() const { return positions.size(); }
  size_t index_count() const;        ///< 0 when not indexed
  bool indexed() const { return index_count() != 0; }
  size_t triangle_count() const { return (indexed() ? index_count() : vertex_count()) / 3; }
  /// The vertex of triangle corner i (i < 3 triangle_count()): indices[i], or i when not indexed.
  uint32_t vertex_of_corner(size_t i) const;
};

/// A key of a model's path: at `time` seconds the model is moved by `offset` (paths.hpp).
struct ModelKey {
  float time = 0.0f;
  glm::vec3 offset{0.0f};           ///< inches, added to its meshes' positions and its centroid
};

/// A VertexLitGeneric object: lighting (ambient cube, two most significant lights) is chosen per
/// model from its centroid, so a model keeps its identity after flattening.
struct Model {
  std::string name;
  std::vector<int> meshes;          ///< indices into Scene::meshes
  glm::vec3 centroid{0.0f};         ///< world space, where its lighting is sampled
  std::vector<ModelKey> path;       ///< empty: the model stays where its meshes are
};

// --- Lights, camera, environment ----------------------------------------------------------------

enum class LightType : uint8_t { point, spot, directional };

/// A Source light. Intensity at distance d (inches) is color / (constant + linear d + quadratic d^2);
/// directional lights do not fall off. Spots fade between the inner and outer cone (smoothstep-free
/// Source falloff with `spot_exponent`).
struct Light {
  std::string name;
  LightType type = LightType::point;
  glm::vec3 position{0.0f};         ///< point, spot
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  ///< spot, directional: where the light travels (unit)
  glm::vec3 color{1.0f};            ///< linear HDR
  float constant = 0.0f, linear = 0.0f, quadratic = 1.0f;
  float inner_cone = 0.0f, outer_cone = 0.7853982f;  ///< half-angles, radians
  float spot_exponent = 1.0f;
  float range = 0.0f;               ///< beyond it the light is off; 0 = unlimited
};

enum class Projection : uint8_t { perspective, orthographic };

/// A camera looking from `position` at `target`. `up` is world +Z unless the camera rolls.
struct Camera {
  std::string name;
  Projection projection = Projection::perspective;
  glm::vec3 position{0.0f};
  glm::vec3 target{1.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 0.0f, 1.0f};
  float vertical_fov = 1.0f;        ///< perspective: radians
  float ortho_height = 2.0f;        ///< orthographic: the height of the view volume, inches
  float aspect = 0.0f;              ///< width / height; 0 = the image's
  float near_plane = 4.0f, far_plane = 16384.0f;  ///< inches
};

/// A key of the camera path: the camera at `time` seconds; in between, position and target are
/// interpolated (Catmull-Rom through the keys).
struct CameraKey {
  float time = 0.0f;
  Camera camera;
};

/// A cube-map sample point (Source's env_cubemap): surfaces whose material asks for the nearest
/// sample use the one closest to the surface's model or face.
struct CubemapSample {
  glm::vec3 position{0.0f};
  int size = 64;                    ///< face size in texels when baked
  int texture = -1;                 ///< a baked or loaded cube (Scene::textures), or -1 until baked
};

/// Six linear HDR colors in D3D face order (+X, -X, +Y, -Y, +Z, -Z).
using AmbientCube = std::array<glm::vec3, 6>;

/// An irradiance volume: ambient cubes on a regular grid, the models' indirect light.
struct IrradianceVolume {
  glm::vec3 min{0.0f}, max{0.0f};   ///< world bounds
  glm::vec3 spacing{128.0f};        ///< inches between samples
  glm::ivec3 counts{0};             ///< samples per axis (baked: cubes.size() = product)
  std::vector<AmbientCube> cubes;   ///< x fastest, then y, then z; empty until baked
};

/// An input a map's logic sends a color-correction node at a time on the scene's clock (Source's
/// Enable and Disable inputs of color_correction).
struct ColorCorrectionInput {
  enum class Kind : uint8_t { enable, disable };
  float time = 0.0f;                ///< seconds
  Kind kind = Kind::enable;
};

/// A color-correction node (Source's color_correction entity): a 3D LUT weighted by the eye's
/// distance, faded in and out by the inputs it is sent (the frame's rules: frame/renderer.hpp).
struct ColorCorrection {
  std::string lut;                  ///< file name (.cube, .3dl...) or "builtin:NAME"
  glm::vec3 position{0.0f};
  float min_falloff = 0.0f, max_falloff = 0.0f;  ///< inches, >= 0 or -1 (none); equal = global
  float max_weight = 1.0f;          ///< maxweight: the weight it holds while enabled
  float fade_in = 0.0f;             ///< fadeInDuration: seconds from 0 to max_weight on Enable; 0 jumps
  float fade_out = 0.0f;            ///< fadeOutDuration: seconds from max_weight to 0 on Disable; 0 jumps
  bool start_disabled = false;      ///< StartDisabled: weight 0 until enabled
  std::vector<ColorCorrectionInput> inputs;  ///< times in order (equal times: in list order)
};

/// A color-correction volume (Source's color_correction_volume, a trigger): its LUT ramps up
/// while the eye is inside the box and down after it leaves (the frame's rules: frame/renderer.hpp).
struct ColorCorrectionVolume {
  std::string lut;                  ///< as ColorCorrection::lut
  glm::vec3 min{0.0f}, max{0.0f};   ///< world bounds, inches (inclusive)
  float fade_duration = 10.0f;      ///< fadeDuration, seconds (the FGD's default); 0 jumps
};

enum class FogMode : uint8_t { none, range, height };

/// Fog (Source's env_fog_controller, and height fog under water).
struct Fog {
  FogMode mode = FogMode::none;
  glm::vec3 color{0.5f};            ///< linear
  float start = 0.0f, end = 4096.0f;  ///< inches from the eye
  float max_density = 1.0f;
  float water_z = 0.0f;             ///< height fog: world z of the water plane
};

/// The auto-exposure controller (Source's env_tonemap_controller). min == max fixes the exposure.
/// Scene::exposure holds everywhere outside the scene's exposure zones.
struct Exposure {
  float min_scale = 0.5f, max_scale = 2.0f;
  float rate = 1.0f;                ///< adaptation per second
  float percent_target = 60.0f;     ///< the histogram percentile aimed at
  float percent_bright = 2.0f;
  float bloom_scale = 1.0f;
};

/// A box where other exposure controls hold while the camera is inside it: what a level designer
/// does in Source with a trigger that sends env_tonemap_controller new values on entering
/// (SetAutoExposureMin/Max, SetTonemapRate, SetBloomScale) and the defaults back on leaving.
/// The scale does not jump: auto exposure carries on towards the new range at the new rate.
struct ExposureZone {
  glm::vec3 min{0.0f}, max{0.0f};   ///< world bounds, inches
  Exposure exposure;
};

/// Baked radiosity normal mapping: the flat (un-bumped) lightmap and three directional lightmaps,
/// each one atlas of the same size, addressed by the meshes' uv1. Attached by `luxel bake`
/// (bake/), or loaded; absent until then. Values are linear HDR in the shaders' lightmap unit: a
/// white Lambertian surface shows the value as its radiance (irradiance / pi), so
/// diffuse = albedo x lightmap (docs/fidelity.md#lightmappedgeneric; HDR: lightmap scale factor 1).
struct Lightmaps {
  int width = 0, height = 0;
  int flat = -1;                            ///< Scene::textures: irradiance / pi about the surface normal
  std::array<int, 3> textures{-1, -1, -1};  ///< Scene::textures, linear HDR, one per basis direction
};

/// Everything one frame draws.
struct Scene {
  std::string name;                 ///< "builtin:courtyard", or the file it was read from
  std::vector<Texture> textures;
  std::vector<Material> materials;
  std::vector<Mesh> meshes;
  std::vector<Model> models;        ///< meshes not in any model are world geometry
  std::vector<Light> lights;
  std::vector<Camera> cameras;      ///< the first is the default
  std::vector<CameraKey> camera_path;
  std::vector<CubemapSample> cubemap_samples;
  std::optional<IrradianceVolume> irradiance_volume;
  std::vector<ColorCorrection> color_corrections;
  std::vector<ColorCorrectionVolume> color_correction_volumes;
  Fog fog;
  Exposure exposure;
  std::vector<ExposureZone> exposure_zones;  ///< the last zone holding the camera wins
  int sky_texture = -1;             ///< an HDR cube (Scene::textures) drawn behind everything, or -1
  glm::vec3 background{0.0f};       ///< linear, where there is no sky
  /// Inches per lightmap luxel (Source's "lightmapscale"; vbsp's DEFAULT_LUXEL_SIZE is 16): the
  /// density the uv1 charts were laid out for, and the baker's for charts it makes itself.
  float lightmap_luxel_size = 16.0f;
  std::optional<Lightmaps> lightmaps;
};

/// Whether the box from `min` to `max` holds `p`, bounds inclusive (exposure zones, color-correction
/// volumes).
bool box_holds(glm::vec3 min, glm::vec3 max, glm::vec3 p);

/// The exposure controls at `position`: the last of Scene::exposure_zones whose box holds it
/// (bounds inclusive), else Scene::exposure.
const Exposure& exposure_at(const Scene& scene, glm::vec3 position);

struct Bounds {
  glm::vec3 min{0.0f}, max{0.0f};
  bool empty = true;
  glm::vec3 center() const { return 0.5f * (min + max); }
  glm::vec3 size() const { return max - min; }
};

/// The box around every mesh position.
Bounds bounds_of(const Scene& scene);

/// Per mesh: 1 when a Model lists it (world geometry is 0). Indices out of range are left out
/// (validate() refuses them).
std::vector<char> meshes_in_models(const Scene& scene);

/// Whether a texel of `texture` has alpha below 1: what the SDK's helpers ask of a base texture
/// (ITexture::IsTranslucent, the VTF's alpha flags) before they keep $basealphaenvmapmask.
bool has_translucent_texels(const Texture& texture);

/// Checks what the frame relies on: indices within their vertex counts, array lengths, material
/// and texture references in range, finite positions, finite material numbers and texture
/// transforms (a shader computes with each), a finite background and fog, texture images the size
/// they claim, unit handedness, exposure controls and color-correction nodes and volumes with
/// finite values that are not negative (a falloff may be -1), a LUT name, input times in order,
/// ordered boxes, no LightmappedGeneric material asking for a combo the SDK never compiles
/// ($bumpmap with $basealphaenvmapmask over a base texture with alpha), and no bumped
/// VertexLitGeneric material whose env map the SDK deletes (masked by $basealphaenvmapmask or
/// $envmapmask).
/// Throws std::invalid_argument naming the scene and the first problem.
void validate(const Scene& scene);

}  // namespace luxel::scenes
