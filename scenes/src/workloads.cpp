#include "luxel/scenes/workloads.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace luxel::scenes {

FillWorkload make_fill_workload() {
  FillWorkload w;
  for (int j = 0; j <= FillWorkload::kQuadsY; ++j) {
    for (int i = 0; i <= FillWorkload::kQuadsX; ++i) {
      w.vertices.push_back({{-1.0f + 2.0f * i / FillWorkload::kQuadsX, -1.0f + 2.0f * j / FillWorkload::kQuadsY},
                            {float(i) / FillWorkload::kQuadsX, float(j) / FillWorkload::kQuadsY}});
    }
  }
  const int row = FillWorkload::kQuadsX + 1;
  for (int j = 0; j < FillWorkload::kQuadsY; ++j) {
    for (int i = 0; i < FillWorkload::kQuadsX; ++i) {
      const uint16_t v00 = uint16_t(j * row + i), v10 = uint16_t(v00 + 1);
      const uint16_t v01 = uint16_t(v00 + row), v11 = uint16_t(v01 + 1);
      w.indices.insert(w.indices.end(), {v00, v10, v11, v00, v11, v01});
    }
  }
  w.layer_color = {{{.90f, .20f, .20f}, {.20f, .90f, .20f}, {.20f, .20f, .90f}, {.90f, .90f, .20f},
                    {.90f, .20f, .90f}, {.20f, .90f, .90f}, {.60f, .60f, .60f}, {.95f, .55f, .15f}}};
  for (int k = 0; k < FillWorkload::kLayers; ++k) w.layer_ndc_z[k] = 0.875f - 0.25f * k;
  return w;
}

TrisWorkload make_tris_workload(int width, int height, int triangles) {
  TrisWorkload w;
  w.vertices.reserve(static_cast<size_t>(triangles) * 3);
  std::mt19937 rng(1);
  auto u = [&rng] { return double(rng() >> 8) / double(1u << 24); };
  const double pi = std::numbers::pi;
  for (int t = 0; t < triangles; ++t) {
    const double cx = width * u(), cy = height * u(), z = 2 * u() - 1;
    const double area = 2 + 2 * u(), theta = 2 * pi * u();
    const uint32_t r = 64 + rng() % 192, g = 64 + rng() % 192, b = 64 + rng() % 192;
    const uint32_t rgba = r | (g << 8) | (b << 16) | (255u << 24);
    const double R = std::sqrt(4 * area / (3 * std::sqrt(3.0)));
    for (int k = 0; k < 3; ++k) {
      const double a = theta + k * (2 * pi / 3);  // the peer's exact expression
      w.vertices.push_back({float(cx + R * std::cos(a)), float(cy + R * std::sin(a)), float(z), rgba});
    }
  }
  return w;
}

}  // namespace luxel::scenes
