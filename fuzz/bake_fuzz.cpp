// libFuzzer target: the bake index (inputs.hpp, read_bake_input); three mutations in four edit it
// as JSON. LUXEL_FUZZ_SEED=DIR writes the real index (hash as @HASH@) to DIR and exits.

#include "inputs.hpp"
#include "json_mutator.hpp"

#include <cstdlib>

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* dir = std::getenv("LUXEL_FUZZ_SEED")) {
    luxel::fuzz::write_bake_seed(dir);
    std::exit(0);
  }
  return 0;
}

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned seed) {
  if (seed % 4 != 0)
    if (size_t n = luxel::fuzz::mutate_json(data, size, max_size, seed)) return n;
  return LLVMFuzzerMutate(data, size, max_size);
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  luxel::fuzz::read_bake_input({data, size});
  return 0;
}
