#pragma once
// W4 `source`: luxel's opaque pass with its Source shaders ported to GLSL, drawn from a glTF file
// luxel exported and baked (bench/README.md, "The peer and its workloads").

#include "workload.hpp"

#include <memory>
#include <string>

namespace luxel::llvmpipe {

struct SourceOptions {
  std::string path;       ///< the glTF file; its bake is beside it (PATH without extension + .bake)
  int camera = 0;         ///< the glTF camera drawn from
  float exposure = 1.0f;  ///< the tone-map scale S
};

/// Throws Skipped when the input is missing or W4 cannot draw it.
std::unique_ptr<Workload> make_source(const SourceOptions& options, int width, int height);

}  // namespace luxel::llvmpipe
