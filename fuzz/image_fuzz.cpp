// libFuzzer target: image import (inputs.hpp, read_image_input). LUXEL_FUZZ_SEED=DIR writes the
// seeds of the formats luxel writes to DIR and exits (scripts/fuzz).

#include "inputs.hpp"

#include <cstdlib>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* dir = std::getenv("LUXEL_FUZZ_SEED")) {
    luxel::fuzz::write_image_seeds(dir);
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  luxel::fuzz::read_image_input({data, size});
  return 0;
}
