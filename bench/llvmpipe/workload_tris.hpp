#pragma once
// W2 `tris`: one million small flat-colored triangles (bench/README.md, "The peer and its workloads").

#include "workload.hpp"

#include <memory>

namespace luxel::llvmpipe {

std::unique_ptr<Workload> make_tris(int width, int height);

}  // namespace luxel::llvmpipe
