#pragma once
// What a build of luxel asks of the CPU, and the guard that stops a binary on a CPU without it.
//
// The default build (LUXEL_ARCH=native) compiles for the machine that builds it: AVX-512 where it
// has it (16 lanes), AVX2 where not. Such a binary copied to an older CPU would die of SIGILL at
// its first such instruction; instead, every program linked with the rasterizer checks the CPU
// before anything else runs (a constructor compiled for baseline x86-64) and, if an extension the
// build uses is missing, prints one line naming it and exits with status 1.

#include <cstddef>

namespace luxel::rasterizer {

/// The instruction-set extensions this build's code may use (the compiler's target macros of
/// LUXEL_ARCH), by the names `__builtin_cpu_supports` knows, ending in nullptr.
extern const char* const kBuildIsaExtensions[];

/// Whether this CPU has the extension `name` (one of kBuildIsaExtensions' names).
bool cpu_has_extension(const char* name);

/// Writes the extensions of kBuildIsaExtensions that `cpu_has` denies into `out`, separated by
/// ", " and NUL-terminated (truncated to `size`); returns how many there are.
int missing_isa_extensions(bool (*cpu_has)(const char* name), char* out, std::size_t size);

}  // namespace luxel::rasterizer
