// W4 `source`: not ported yet. The workload reports itself skipped, so that scripts/bench prints
// the comparison as missing rather than a number that does not mean what it says.

#include "workload_source.hpp"

namespace luxel::llvmpipe {

std::unique_ptr<Workload> make_source(const SourceOptions&, int, int) {
  throw Skipped("W4 is not ported to this program yet");
}

}  // namespace luxel::llvmpipe
