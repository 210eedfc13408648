#pragma once
// What the benchmarks print about the machine they ran on (every table in bench/README.md names
// the CPU and the instruction set it was measured with).

#include "luxel/rasterizer/cpu_model.hpp"
#include "luxel/rasterizer/simd.hpp"

#include <string>

namespace luxel::bench {

/// One line for stderr: the CPU, the lanes' instruction set and width.
inline std::string machine_line() {
  return "cpu=\"" + rasterizer::cpu_model() + "\" isa=" + rasterizer::simd::kIsaName + " lanes=" + std::to_string(rasterizer::simd::kLanes);
}

}  // namespace luxel::bench
