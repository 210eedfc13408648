#pragma once
// Radiosity-normal-mapped lightmaps, as vrad made them (docs/fidelity.md#bake-vrad,
// #rnm-basis-and-lightmaps).
//
// What is baked. Every mesh that is world geometry (in no Model) with a LightmappedGeneric
// material gets luxels in one atlas shared by all of them, addressed by its uv1 (glTF
// convention: v = 0 is the atlas's top row). A luxel is the texel whose center lies inside one of
// the mesh's uv1 triangles (the first triangle in mesh and index order claims it); its sample
// point, normal and tangent frame are the triangle's attributes interpolated at that center.
//
// The four maps (flat, then basis 0, 1, 2, vrad's order). Each holds the light arriving at the
// luxel in the shaders' lightmap unit, irradiance / pi, i.e. the radiance a white Lambertian
// surface would show; the shader multiplies it by the albedo (HDR lightmap scale factor 1):
//   flat    (1/pi) integral over the hemisphere of L(w) max(0, n . w) dw
//   basis i (1/pi) integral over the same hemisphere of L(w) max(0, b_i . w) dw, b_i the RNM basis
//           (rnm_basis.hpp) in the luxel's tangent frame: x = tangent orthogonalized to the
//           interpolated normal n, y = w cross(n, x) (w: the tangent's handedness), z = n.
// Light only counts from above the surface (vrad zeroes a bump map where the flat normal faces
// away). The lights of the scene (Light, scene.hpp) are deltas: they add color x falloff x
// max(0, n . L) to the flat map and color x falloff x max(0, b_i . L) to map i, when no occluding
// surface lies between. Falloff: 1 / (constant + linear d + quadratic d^2) with d in inches (at
// least 1 inch), zero beyond `range` when it is set; spots multiply by
// sat((cos a - cos outer) / (cos inner - cos outer))^exponent inside the outer cone and, as vrad
// does, by cos a (a: the angle to the spot's axis). Directional lights do not fall off.
//
// Sky, emissive surfaces and bounced light are gathered with `samples` rays per luxel and bounce
// over the hemisphere (uniform directions, n x n strata jittered by random.hpp), and weighted
// with self-normalized weights (the estimate sum L w / sum w times the weight's exact integral):
// the same rule vrad uses for ambient cubes. A uniform sky is then exact in the flat map (white
// furnace), and anything else converges as 1/sqrt(samples).
// The sky's light in the basis maps follows vrad instead (GatherSampleAmbientSkySSE in
// utils/vrad/lightmap.cpp "scales out the missing parts of the hemisphere of this bump basis
// vector"): basis map i gets (sum over rays with n . w > 0 and b_i . w > 0 of L max(0, b_i . w)
// / their count) / (sum over rays with n . w > 0 of n . w / their count), the mean of b_i's
// cosine over the directions both see, over the mean of n's over n's hemisphere. A uniform sky L
// then gives each basis map pi (1 + cos b) / (2 (pi - b)) L = 1.1333 L (b = 54.74 degrees, the
// lune both hemispheres share has area 2 (pi - b)), not the clipped integral's 0.7887 L: under
// an open sky, a bumped surface with a flat normal is 13 % brighter than its flat map, as in the
// engine. Bounced light and emitters keep the exact rule, as vrad's patch transfers do.
//   bounce 0: the lights (delta), plus rays that miss everything (sky texture, else the scene's
//             background) and rays that hit the front of an emissive surface (its `emissive`);
//   bounce k: rays that hit the front of a lightmapped surface see albedo x that surface's flat
//             map of bounce k-1 (nearest luxel); of another diffuse surface (models), at bounce 1
//             only, albedo x the direct light of the lights there. Back faces are black.
// Stopping rule (luxel's; vrad's threshold is absolute, docs/fidelity.md#bake-vrad): after
// bounce k >= 1, stop if the light it added (luminance x luxel area, summed over the atlas) is less
// than `stop_fraction` of all light so far, or at `max_bounces`.
//
// Albedo is vrad's "reflectivity": the material's color times its base texture's mean (decoded
// from sRGB when the texture is sRGB), clamped to [0, 1].
//
// Supersampling: where a luxel's direct light differs from a covered neighbour's by more than
// `supersample_threshold` x the larger, its direct light is recomputed as the mean of
// supersample x supersample points over its footprint on its triangle's plane.
//
// Borders: luxels no triangle covers but a covered luxel touches (8-neighbourhood) take the mean
// of those neighbours, twice over (two rings), so that bilinear filtering anywhere inside a chart
// reads written luxels only; `coverage` says which luxels are what.
//
// Encoding: the maps are rounded to IEEE half (what is stored, storage.hpp), values above 65504
// clamped to it.

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace luxel::bake {

/// What a texel of the atlas is.
enum class LuxelCoverage : uint8_t {
  empty = 0,    ///< no triangle, no neighbour: never read by bilinear filtering of a chart
  covered = 1,  ///< a luxel: its center lies in a uv1 triangle
  border = 2,   ///< filled from its covered neighbours (dilation)
};

/// The four lightmaps of one atlas, width x height, row-major, top row first.
struct LightmapAtlas {
  int width = 0, height = 0;
  std::array<std::vector<glm::vec3>, 4> maps;  ///< flat, basis 0, basis 1, basis 2
  std::vector<LuxelCoverage> coverage;
  const glm::vec3& flat(int x, int y) const { return maps[0][size_t(y) * size_t(width) + size_t(x)]; }
  const glm::vec3& basis(int i, int x, int y) const { return maps[size_t(i) + 1][size_t(y) * size_t(width) + size_t(x)]; }
};

}  // namespace luxel::bake
