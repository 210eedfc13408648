// libFuzzer target: `luxel`'s arguments, one per line (inputs.hpp, read_cli_input).
// LUXEL_FUZZ_SEED=DIR writes the README's and the tests' command lines to DIR and exits (scripts/fuzz).

#include "inputs.hpp"

#include <cstdlib>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* dir = std::getenv("LUXEL_FUZZ_SEED")) {
    luxel::fuzz::write_cli_seeds(dir);
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  luxel::fuzz::read_cli_input({data, size});
  return 0;
}
