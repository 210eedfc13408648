#pragma once
// The CPU this process runs on, in words: what every printed timing names (bench/README.md's
// tables, `luxel cost`), since a speed measured on one vendor says little about another.

#include <cpuid.h>

#include <cstdio>
#include <cstring>
#include <string>

namespace luxel::rasterizer {

/// The CPU's brand string and its vendor, family and model from CPUID (a VM's brand string can be
/// as bare as "AMD EPYC"; the family tells Zen 4 (25) from Zen 5 (26)).
inline std::string cpu_model() {
  unsigned a = 0, b = 0, c = 0, d = 0;
  char vendor[13] = {};
  __get_cpuid(0, &a, &b, &c, &d);
  std::memcpy(vendor, &b, 4);
  std::memcpy(vendor + 4, &d, 4);
  std::memcpy(vendor + 8, &c, 4);
  __get_cpuid(1, &a, &b, &c, &d);
  const unsigned base_family = (a >> 8) & 0xf, base_model = (a >> 4) & 0xf;
  const unsigned family = base_family == 0xf ? base_family + ((a >> 20) & 0xff) : base_family;
  const unsigned model = base_family == 0x6 || base_family == 0xf ? base_model | ((a >> 12) & 0xf0) : base_model;
  std::string brand;
  unsigned regs[12] = {};
  if (__get_cpuid(0x80000000, &a, &b, &c, &d) && a >= 0x80000004) {
    for (unsigned i = 0; i < 3; ++i) __get_cpuid(0x80000002 + i, &regs[4 * i], &regs[4 * i + 1], &regs[4 * i + 2], &regs[4 * i + 3]);
    brand.assign(reinterpret_cast<const char*>(regs), sizeof regs);
    brand = brand.c_str();
    while (!brand.empty() && brand.back() == ' ') brand.pop_back();
  }
  char ids[96];
  std::snprintf(ids, sizeof ids, " (%s family %u model %u)", vendor, family, model);
  return brand + ids;
}

}  // namespace luxel::rasterizer
