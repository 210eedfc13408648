#pragma once
// W1 `fill`: overdraw 8 with trivial shading (bench/README.md, "The peer and its workloads").

#include "workload.hpp"

#include <memory>

namespace luxel::llvmpipe {

std::unique_ptr<Workload> make_fill();

}  // namespace luxel::llvmpipe
