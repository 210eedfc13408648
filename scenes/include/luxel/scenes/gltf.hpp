#pragma once
// glTF 2.0 in and out (.gltf with side files or base64 data URIs, and .glb), through
// tinygltf 2.7 behind a validation layer of luxel's own.
//
// ## Units and axes
// glTF is in meters, +Y up; a scene is in inches, +Z up (scene.hpp). Import maps a glTF world
// point (x, y, z) to (x, -z, y) * kInchesPerMeter: the conversion is folded into every node's
// world matrix, composed in double precision. Export writes the scene's vertex values unchanged
// and puts the conversion back in one root node, "luxel:source-to-gltf", whose matrix rotates +Z up
// to +Y up and scales by 1 / kInchesPerMeter, so every glTF viewer sees meters and +Y up.
// Re-import gives identical vertex bytes: when a primitive's world matrix (the conversion
// included) is the identity to within 1e-9 per element, as it is under that root node, its
// vertices are copied bit for bit instead of transformed.
//
// ## Geometry
// - Node hierarchy (matrix or TRS) flattened to world space: positions by the matrix, normals by
//   its inverse transpose (normalized), tangents' xyz by the matrix (normalized). A mirroring
//   matrix (negative determinant) reverses each triangle's winding and negates tangent handedness,
//   so front faces and bitangents stay what the author drew.
// - Modes: TRIANGLES; TRIANGLE_STRIP and TRIANGLE_FAN converted to lists as the glTF
//   specification orders them; POINTS, LINES, LINE_LOOP and LINE_STRIP refused.
// - Indices: UNSIGNED_BYTE widened to 16 bits, UNSIGNED_SHORT and UNSIGNED_INT kept; a
//   TRIANGLES primitive without indices stays a non-indexed mesh (unless mirroring or flat
//   normals reorder it; then 0..n-1 in the smallest type that holds them).
// - Attributes: POSITION, NORMAL, TANGENT, TEXCOORD_0 (uv0), TEXCOORD_1 (uv1, lightmap UVs),
//   COLOR_0 (VEC3 gets alpha 1), with the component types the specification allows (normalized
//   unsigned bytes and shorts for TEXCOORD and COLOR), sparse accessors applied.
// - Without NORMAL, flat normals (each triangle gets its own three vertices), as the specification
//   asks, except under an unlit material (KHR_materials_unlit, UnlitGeneric), which reads none
//   (GltfImportOptions::missing_normal asks for a constant normal instead). Without TANGENT but with normals and uv0, tangents are generated (tangents.hpp).
// - Each node with a mesh becomes a Model (a VertexLitGeneric object) holding the meshes of its
//   primitives whose material is VertexLitGeneric; its centroid is the node's
//   extras.luxel.centroid (written by save_gltf) or else the mean of their world positions. Primitives with other families (LightmappedGeneric, Water, ...) are world geometry.
// - A model's path (Model::path) is the node's extras.luxel.path ([{"time", "offset"}...], offsets
//   in its parent's units, written by save_gltf), or else the translation channel of the file's
//   first animation that moves the node or its nearest animated ancestor: per key, the change of
//   that node's translation from its rest, taken to world space by its parent's matrix; LINEAR
//   exactly, STEP and CUBICSPLINE as linear between their keys' values. World geometry does not
//   move.
// - Compressed and quantized geometry: EXT_meshopt_compression buffer views and
//   KHR_draco_mesh_compression primitives are decoded into plain buffers first
//   (gltf_compression.hpp); KHR_mesh_quantization allows bytes and shorts for POSITION and
//   TEXCOORD (normalized or not) and normalized signed ones for NORMAL and TANGENT.
// - Skins, morph targets, other animations and rotation or scale channels are ignored (the bind
//   pose is drawn).
//
// ## Materials: glTF PBR -> Source
//   baseColorTexture               -> base (sRGB), its texCoord and KHR_texture_transform
//   baseColorFactor                -> color (rgb linear, a = $alpha)
//   normalTexture                  -> bump (linear; its `scale` is not read)
//   roughnessFactor r              -> phong = r < 0.9; phong_exponent = clamp(2 / r^4 - 2, 1, 150)
//                                     (the Blinn-Phong exponent of GGX alpha = r^2)
//   metallicFactor m               -> m > 0 and r < 0.5: envmap = nearest_sample,
//                                     envmap_tint = lerp(0.04, baseColor.rgb, m) * (1 - r)
//   emissiveFactor x KHR_materials_emissive_strength -> emissive
//   alphaMode MASK / BLEND, alphaCutoff -> alpha_test / blend (+ translucent), alpha_cutoff
//   doubleSided                    -> double_sided ($nocull)
//   KHR_materials_unlit            -> UnlitGeneric
//   metallicRoughnessTexture, occlusionTexture, emissiveTexture: not read (Source has no slot
//   that means the same).
// Then Source parameters in the material's extras override the mapping, so an author can set
// them in any glTF editor: extras: {"luxel": {"shader": "LightmappedGeneric", "phong": true,
// "phongexponent": 20, ...}}. The keys are the .vmt names without '$' (lower case), values
// numbers, booleans, [r, g, b] arrays, or for textures a glTF textureInfo {"index": i,
// "texCoord": n, "offset": [u, v], "scale": [u, v], "rotation": radians}:
//   shader: LightmappedGeneric | VertexLitGeneric | UnlitGeneric | Water | Sky
//   basetexture, bumpmap, detail, envmapmasktexture, phongexponenttexture, normalmap (Water): textures
//   color [3], alpha, detailscale, detailblendfactor,
//   envmap: "" | "env_cubemap" (nearest sample), envmapmask: "" | "texture" | "basealpha" | "normalalpha",
//   envmaptint [3], envmapcontrast, envmapsaturation, envmapfresnel, fresnelreflection,
//   phong, phongexponent, phongexponentfactor, phongboost, phongfresnelranges [3], phongtint [3],
//   phongalbedotint, basemapalphaphongmask, invertphongmask,
//   rimlight, rimlightexponent, rimlightboost, rimmask, halflambert, heroboost,
//   selfillum, selfillumtint [3], emissive [3],
//   alphatestreference, translucent, nocull (alpha test and blending themselves are glTF's alphaMode),
//   scroll1 [2], reflectamount, refractamount, reflecttint [3], refracttint [3],
//   fogcolor [3], fogstart, fogend, blurrefract (Water).
// Export writes every one of them, so a re-import gives the same Source material.
//
// ## The scene's own Source data: the glTF scene's extras.luxel
// Positions in Source inches, +Z up (not glTF's meters: only luxel reads them):
//   background [3], fog {mode: none|range|height, color [3], start, end, maxdensity, waterz},
//   exposure {minscale, maxscale, rate, percenttarget, percentbright, bloomscale},
//   exposurezones [{min [3], max [3], exposure {...}}],
//   cubemapsamples [{position [3], size}], colorcorrections [{lut, position [3], minfalloff,
//   maxfalloff, maxweight, fadein, fadeout, startdisabled, inputs [{time, input: enable|disable}]}],
//   colorcorrectionvolumes [{lut, min [3], max [3], fadeduration}],
//   irradiancevolume {min [3], max [3], spacing [3], counts [3]} (its
//   baked cubes are not written), camerapath [{time, camera {position, target, up [3], fov, near, far}}].
// A key a file lacks keeps the scene model's default (files written before it existed load as
// they did); an input that is neither enable nor disable is an error.
//
// ## Lights (KHR_lights_punctual)
// glTF's point and spot lights fall off as intensity / d^2, intensity in candela, d in meters;
// Source's as color / (constant + linear d + quadratic d^2), d in inches. With d_m = d_in / k
// (k = kInchesPerMeter), I / d_m^2 = I / (d_in^2 / k^2), so a light becomes
//   color = glTF color x intensity, constant = linear = 0, quadratic = 1 / k^2 (0.00064516),
// which is exact. Directional lights (lux) become color = color x intensity without falloff.
// `range` (meters) becomes Light::range (inches): Source cuts the light off there, where glTF
// recommends a smooth window towards it; that window is not modelled. Spot cone angles are kept
// (half-angles). Export inverts this; a light with constant or linear terms is matched at
// 100 inches, where its intensity is the same.
//
// ## Cameras
// All cameras placed by nodes are imported; the one asked for (the first by default) is
// Scene::cameras[0]. Without any, a camera looking at the asset's front with the whole scene in
// the frame (framing.hpp) is added, and without any light, a key and a fill directional light, so
// every asset renders to something visible.
//
// ## Errors
// Every problem throws GltfError whose what() is one line "FILE: problem". First the JSON's
// structure where luxel reads it (gltf_schema.hpp): a list that is not an array, an index of the
// wrong type or to nothing, a `scene` that names no scene is "FILE: JSON.PATH problem"; a
// wrong-typed or out-of-range optional value is a warning (GltfImportOptions::warn) naming the path
// and the value used. An extension in extensionsRequired that luxel does not read refuses the file,
// one only in extensionsUsed is a warning (docs/gltf.md lists them). Before any data is
// read, luxel checks in 64-bit arithmetic that every accessor (and sparse part) lies within its
// buffer view and buffer, the component types and types each attribute may have, byte strides,
// index values against the vertex count, the limits below, that URIs stay in the file's folder
// (no "../", no absolute paths or schemes), that images exist and decode, that positions are
// finite; then scenes::validate().
//
// ## Memory
// What a file asks for is estimated before it is allocated and refused beyond
// GltfImportOptions::memory_limit (memory_limit.hpp), a GltfError "FILE: needs about 9.1 GiB
// (...), beyond the memory limit of 4 GiB (...)": the file's bytes and tinygltf's copy of its
// buffers before they are read; each image's pixels from its header, and the images read so far
// with the buffers; then, before any vertex is read, the flattened scene: per vertex the
// attributes it will have (position, normal, tangent, uvs, color) and per triangle corner a 32-bit
// index, each twice (as read, then as kept), with the buffers and images.

#include "luxel/scenes/memory_limit.hpp"
#include "luxel/scenes/scene.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace luxel::scenes {

/// A glTF file that cannot be read: what() is one line naming the file and the problem (what it
/// quotes from the file, a name or a URI, with its control characters as spaces).
struct GltfError : std::runtime_error {
  explicit GltfError(const std::string& what);
};

/// Limits checked before anything is allocated for the data they count.
inline constexpr uint64_t kMaxGltfVertices = uint64_t{1} << 24;   ///< per accessor and primitive
inline constexpr uint64_t kMaxGltfIndices = uint64_t{1} << 26;    ///< per primitive
inline constexpr uint64_t kMaxGltfSceneVertices = uint64_t{1} << 25;  ///< summed over the flattened scene
inline constexpr uint64_t kMaxGltfSceneIndices = uint64_t{1} << 27;   ///< triangle corners, summed likewise
inline constexpr int kMaxGltfNodeDepth = 256;

struct GltfImportOptions {
  int camera = 0;                   ///< the glTF camera (index into its `cameras`) made Scene::cameras[0]
  bool default_camera = true;       ///< add a framing camera when the file has none (framing.hpp)
  float framing_aspect = 16.0f / 9.0f;  ///< the width / height of the images it frames the scene for
  bool default_lights = true;       ///< add a key and a fill light when the file has none
  bool generate_tangents = true;    ///< MikkTSpace tangents where TANGENT is missing
  /// Set: a primitive without NORMAL gets this object-space normal at every vertex, transformed by
  /// its node like any normal, instead of flat normals (the way OpenGL's constant vertex attribute
  /// reads a missing array, which the llvmpipe peer's W3 workload relies on). Unlit materials get
  /// it too.
  std::optional<glm::vec3> missing_normal = std::nullopt;
  /// The most bytes the file may ask for (above, and memory_limit.hpp).
  uint64_t memory_limit = kDefaultMemoryLimit;
  /// Where each warning goes: one line "FILE: problem; what is used instead" (a wrong-typed
  /// optional value, an extension used but not read). Unset: standard error, after
  /// "luxel: warning: ".
  std::function<void(const std::string&)> warn;
};

/// Reads a .gltf or .glb file (told apart by its first bytes). Scene::name is `path`.
Scene load_gltf(const std::string& path, const GltfImportOptions& options = {});

/// Writes the scene as .glb (when `path` ends in .glb) or as one .gltf with base64-embedded
/// buffers. Writes positions, normals, tangents, uv0, uv1, colors (float) and indices, POSITION
/// min/max, 8-bit textures as embedded PNG with their samplers, lights (KHR_lights_punctual),
/// cameras, models as nodes, every material with its Source
/// parameters in extras (see above), the scene's Source data in the glTF scene's extras.
/// Not written: float (HDR) and cube textures (glTF has no such images; a material whose env map
/// is a texture then asks for the nearest sample), so neither the sky nor baked lightmaps, cube
/// maps and ambient cubes. Meshes without vertices or triangles are left out. Throws GltfError
/// naming the file.
void save_gltf(const Scene& scene, const std::string& path);

}  // namespace luxel::scenes
