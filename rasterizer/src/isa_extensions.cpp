// The extensions this build targets: compiled with the build's own flags, so that the compiler's
// target macros say what LUXEL_ARCH enabled. Data only: the guard (isa_guard.cpp) reads it before
// any code compiled for those extensions may run.
#include "luxel/rasterizer/isa_guard.hpp"

namespace luxel::rasterizer {

const char* const kBuildIsaExtensions[] = {
#if defined(__SSE4_2__)
    "sse4.2",
#endif
#if defined(__POPCNT__)
    "popcnt",
#endif
#if defined(__AVX__)
    "avx",
#endif
#if defined(__AVX2__)
    "avx2",
#endif
#if defined(__FMA__)
    "fma",
#endif
#if defined(__BMI__)
    "bmi",
#endif
#if defined(__BMI2__)
    "bmi2",
#endif
#if defined(__F16C__)
    "f16c",
#endif
#if defined(__AVX512F__)
    "avx512f",
#endif
#if defined(__AVX512VL__)
    "avx512vl",
#endif
#if defined(__AVX512BW__)
    "avx512bw",
#endif
#if defined(__AVX512DQ__)
    "avx512dq",
#endif
#if defined(__AVX512CD__)
    "avx512cd",
#endif
#if defined(__AVX512VBMI__)
    "avx512vbmi",
#endif
#if defined(__AVX512VBMI2__)
    "avx512vbmi2",
#endif
#if defined(__AVX512IFMA__)
    "avx512ifma",
#endif
#if defined(__AVX512VNNI__)
    "avx512vnni",
#endif
#if defined(__AVX512BITALG__)
    "avx512bitalg",
#endif
#if defined(__AVX512VPOPCNTDQ__)
    "avx512vpopcntdq",
#endif
#if defined(__AVX512BF16__)
    "avx512bf16",
#endif
#if defined(__AVX512FP16__)
    "avx512fp16",
#endif
#if defined(__GFNI__)
    "gfni",
#endif
#if defined(__VPCLMULQDQ__)
    "vpclmulqdq",
#endif
    nullptr,
};

}  // namespace luxel::rasterizer
