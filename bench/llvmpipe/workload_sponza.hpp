#pragma once
// W3 `sponza`: a glTF file with a trilinear base texture, an ambient cube and two point lights.
// luxel draws it in bench/workloads/sponza.cpp; this draws the same scene with OpenGL.

#include "workload.hpp"

#include "sponza.hpp"  // luxel's W3 (bench/workloads): the scene loader, camera and lighting

#include <memory>
#include <string>

namespace luxel::llvmpipe {

/// Throws Skipped when `path` names no file.
std::unique_ptr<Workload> make_sponza(const std::string& path, const bench::SponzaView& view, int width, int height);

}  // namespace luxel::llvmpipe
