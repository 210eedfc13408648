#pragma once
// Which cube-map sample each face of a world mesh reflects, as vbsp assigns the
// literal `env_cubemap` of LightmappedGeneric (docs/fidelity.md#world-env-maps-vbsp). vbsp
// works per brush side; a luxel mesh has no brush sides, so its triangles are grouped by the plane
// they lie on. Per group: the centre is the mean of the group's vertices; the sample is the
// nearest one in front of the plane (dot(normalize(sample - centre), normal) >= 0), else the
// nearest overall, ties to the lower index. With no samples nothing is assigned, and the engine
// draws the material without its env map.

#include "luxel/scenes/scene.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace luxel::frame {

/// The triangles of a mesh that reflect one sample.
struct EnvmapFaceGroup {
  int sample = -1;                ///< index into Scene::cubemap_samples
  std::vector<uint32_t> indices;  ///< three vertex indices per triangle, in the mesh's order
};

/// vbsp's choice for a face group centred at `centre` on a plane of unit `normal`: the index of
/// the nearest sample in front of the plane, else of the nearest overall; -1 when there is none.
int envmap_sample_for(const glm::vec3& centre, const glm::vec3& normal, std::span<const scenes::CubemapSample> samples);

/// The mesh's triangles grouped by the sample their plane's group reflects, in order of the
/// samples' first use; empty when there are no samples. Degenerate triangles (no plane) go with
/// the sample nearest their own centre.
std::vector<EnvmapFaceGroup> envmap_face_groups(const scenes::Mesh& mesh, std::span<const scenes::CubemapSample> samples);

}  // namespace luxel::frame
