// The CPU check that runs before anything else in a program linked with the rasterizer
// (isa_guard.hpp). This file alone is compiled for baseline x86-64 (rasterizer/CMakeLists.txt),
// and it calls nothing compiled for more: only libc and the compiler's CPU detection.
#include "luxel/rasterizer/isa_guard.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace luxel::rasterizer {

bool cpu_has_extension(const char* name) {
  __builtin_cpu_init();
  // __builtin_cpu_supports takes a literal: one test per name kBuildIsaExtensions may hold.
#define LUXEL_CPU_HAS(literal) \
  if (std::strcmp(name, literal) == 0) return __builtin_cpu_supports(literal)
  LUXEL_CPU_HAS("sse4.2");
  LUXEL_CPU_HAS("popcnt");
  LUXEL_CPU_HAS("avx");
  LUXEL_CPU_HAS("avx2");
  LUXEL_CPU_HAS("fma");
  LUXEL_CPU_HAS("bmi");
  LUXEL_CPU_HAS("bmi2");
  LUXEL_CPU_HAS("avx512f");
  LUXEL_CPU_HAS("avx512vl");
  LUXEL_CPU_HAS("avx512bw");
  LUXEL_CPU_HAS("avx512dq");
  LUXEL_CPU_HAS("avx512cd");
  LUXEL_CPU_HAS("avx512vbmi");
  LUXEL_CPU_HAS("avx512vbmi2");
  LUXEL_CPU_HAS("avx512ifma");
  LUXEL_CPU_HAS("avx512vnni");
  LUXEL_CPU_HAS("avx512bitalg");
  LUXEL_CPU_HAS("avx512vpopcntdq");
  LUXEL_CPU_HAS("avx512bf16");
  LUXEL_CPU_HAS("gfni");
  LUXEL_CPU_HAS("vpclmulqdq");
#if defined(__clang__)
  // Clang 14 knows neither name: take the build machine's word for them (AVX-512 machines that
  // lack these lack avx512f-family extensions tested above).
  if (std::strcmp(name, "f16c") == 0 || std::strcmp(name, "avx512fp16") == 0) return true;
#else
  LUXEL_CPU_HAS("f16c");
  LUXEL_CPU_HAS("avx512fp16");
#endif
#undef LUXEL_CPU_HAS
  return false;
}

int missing_isa_extensions(bool (*cpu_has)(const char* name), char* out, std::size_t size) {
  int missing = 0;
  std::size_t length = 0;
  auto append = [&](const char* text) {
    for (; *text && length + 1 < size; ++text) out[length++] = *text;
  };
  for (const char* const* e = kBuildIsaExtensions; *e; ++e) {
    if (cpu_has(*e)) continue;
    if (missing++ > 0) append(", ");
    append(*e);
  }
  if (size > 0) out[length] = '\0';
  return missing;
}

namespace {

// LUXEL_CPU_LACKS=a,b treats the CPU as lacking those extensions: how the tests see the guard
// stop a program on a CPU they do not have.
bool cpu_has_unless_told_otherwise(const char* name) {
  if (const char* lacks = std::getenv("LUXEL_CPU_LACKS")) {
    const std::size_t n = std::strlen(name);
    for (const char* p = lacks; *p;) {
      const char* end = std::strchr(p, ',');
      const std::size_t len = end ? static_cast<std::size_t>(end - p) : std::strlen(p);
      if (len == n && std::strncmp(p, name, n) == 0) return false;
      p = end ? end + 1 : p + len;
    }
  }
  return cpu_has_extension(name);
}

void write_all(const char* text) {
  for (std::size_t left = std::strlen(text); left > 0;) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

// Priority 101: before every C++ static initializer, which may already use the extensions.
[[gnu::constructor(101)]] void stop_on_a_cpu_without_the_build_isa() {
  char missing[512];
  if (missing_isa_extensions(cpu_has_unless_told_otherwise, missing, sizeof missing) == 0) return;
  write_all(program_invocation_short_name);
  write_all(": this build of luxel uses ");
  write_all(missing);
  write_all(", which this CPU lacks (LUXEL_ARCH=" LUXEL_ARCH_NAME
            " targets the machine that built it): build it here, or with -DLUXEL_ARCH=x86-64-v3 for any AVX2 CPU\n");
  std::_Exit(1);
}

}  // namespace
}  // namespace luxel::rasterizer

// What the rasterizer's link interface names (-Wl,--undefined) so that every program takes this
// file from the static library, although nothing calls into it.
extern "C" const int luxel_isa_guard = 1;
