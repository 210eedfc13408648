#pragma once
// Ambient cubes on the irradiance-volume grid (docs/fidelity.md#irradiance-volume-and-lights).
//
// Grid: the scene's IrradianceVolume: `counts` samples per axis from `min` at `spacing` (counts
// derived as floor((max - min) / spacing) + 1 when the volume gives none; spacing from the
// settings' default when it gives none). A grid point on a face of the volume's box is moved
// 1 inch inward on that axis: volumes are drawn to the floor and walls, and a sample exactly on
// a surface would see through it.
//
// Each sample fires `cube_samples` rays over the sphere (n x n strata, random.hpp) and, as vrad's
// ComputeAmbientFromSphericalSamples, sets face j (D3D order +X, -X, +Y, -Y, +Z, -Z) to
//   C_j = sum_i L_i c_ij / sum_i c_ij,  c_ij = max(0, dir_i . axis_j),
// the irradiance / pi of a surface facing axis j (the lightmaps' unit; a uniform sky of radiance
// L gives C_j = L exactly). L_i: a miss sees the sky (as lightmaps.hpp), a hit on the front of a
// lightmapped surface albedo x its final flat map + its emissive, on another diffuse surface
// albedo x the direct light there + its emissive, on an emitter its emissive.
// Default mode: that is all (the engine lights models with the scene's lights itself). All-light
// mode (`cubes_all_light`) adds each light's color x falloff x max(0, axis_j . L), unoccluded.
//
// Samples inside solid geometry: a sample more than 25 % of whose rays hit back faces is inside
// something (or under a one-sided floor); it takes the cube of the nearest valid sample in grid
// steps (a breadth-first fill from all valid samples at once over the 6-neighbourhood, in index
// order, so ties go the same way every time), like vrad's solid leaves that point to the nearest
// leaf with samples. `valid` says which were computed. With no valid sample at all the cubes are
// black and the bake warns.

#include "luxel/scenes/scene.hpp"

#include <vector>

namespace luxel::bake {

struct AmbientCubes {
  scenes::IrradianceVolume volume;  ///< grid and cubes, ready to attach to the scene
  std::vector<char> valid;          ///< per sample: computed (1) or copied from a neighbour (0)
};

/// Cubes at arbitrary points (bake.hpp's ambient_cubes_at), each computed as a grid sample is,
/// without the fill from neighbours.
struct PointCubes {
  std::vector<scenes::AmbientCube> cubes;
  std::vector<char> valid;  ///< 0: more than 25 % of the point's rays hit back faces (inside something)
};

}  // namespace luxel::bake
