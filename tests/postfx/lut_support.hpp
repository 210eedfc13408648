#pragma once
// Helpers for the color-correction tests: LUT files written by the tests themselves (a known
// function on a lattice, as .cube or as CLF with an interpolation attribute), and the trilinear and
// tetrahedral interpolation of such a lattice in double, written from their definitions.

#include "luxel/postfx/lut.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace luxel::postfx::test {

/// A smooth, non-multilinear function of the color, different per channel, partly outside [0, 1]
/// (as real LUTs are), so interpolating its lattice differs from the function itself.
inline glm::dvec3 analytic_grade(glm::dvec3 c) {
  return {0.85 * c.x * c.x + 0.2 * c.y * c.z - 0.02, 0.5 * c.y + 0.35 * std::sin(2.5 * c.z) * c.x + 0.1,
          std::sqrt(0.2 + 0.8 * c.z) * (0.7 + 0.3 * c.y) - 0.4 * c.x * c.y};
}

/// A lattice of n points per axis, values stored as the float the file holds. at(r, g, b).
struct Lattice {
  int n = 0;
  std::vector<glm::vec3> values;  ///< index r + n g + n^2 b
  glm::dvec3 at(int r, int g, int b) const { return glm::dvec3(values[size_t((b * n + g) * n + r)]); }
};

/// The engine's LUT (its 8-bit entries, red fastest) as a lattice.
inline Lattice lut_lattice(const Lut& lut) {
  Lattice l{kLutSize, std::vector<glm::vec3>(lut.entries.size())};
  for (size_t i = 0; i < lut.entries.size(); ++i) l.values[i] = glm::vec3(lut.entries[i][0], lut.entries[i][1], lut.entries[i][2]);
  return l;
}

inline Lattice analytic_lattice(int n) {
  Lattice l{n, std::vector<glm::vec3>(size_t(n) * n * n)};
  for (int b = 0; b < n; ++b)
    for (int g = 0; g < n; ++g)
      for (int r = 0; r < n; ++r)
        l.values[size_t((b * n + g) * n + r)] = glm::vec3(analytic_grade(glm::dvec3(r, g, b) / double(n - 1)));
  return l;
}

/// Writes the lattice as a .cube (red fastest), every float in full.
inline void write_cube_file(const Lattice& l, const std::string& path) {
  std::ofstream out(path);
  out << "TITLE \"luxel test\"\nLUT_3D_SIZE " << l.n << "\n";
  char line[96];
  for (const glm::vec3& v : l.values) {
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", v.x, v.y, v.z);
    out << line;
  }
}

/// Writes the lattice as a Common LUT Format file asking for `interpolation` ("trilinear" or
/// "tetrahedral"); CLF orders its array with blue fastest.
inline void write_clf_file(const Lattice& l, const std::string& path, const std::string& interpolation) {
  std::ofstream out(path);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<ProcessList id=\"luxel\" compCLFversion=\"3\">\n"
      << "  <LUT3D id=\"lut\" inBitDepth=\"32f\" outBitDepth=\"32f\" interpolation=\"" << interpolation << "\">\n"
      << "    <Array dim=\"" << l.n << " " << l.n << " " << l.n << " 3\">\n";
  char line[96];
  for (int r = 0; r < l.n; ++r)
    for (int g = 0; g < l.n; ++g)
      for (int b = 0; b < l.n; ++b) {
        const glm::dvec3 v = l.at(r, g, b);
        std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", v.x, v.y, v.z);
        out << line;
      }
  out << "    </Array>\n  </LUT3D>\n</ProcessList>\n";
}

/// The cell of c in [0, 1] on an n-point axis and the fraction inside it.
inline void locate(double c, int n, int& i0, double& f) {
  const double x = std::clamp(c, 0.0, 1.0) * (n - 1);
  i0 = std::min(static_cast<int>(x), n - 2);
  f = x - i0;
}

inline glm::dvec3 trilinear(const Lattice& l, glm::dvec3 c) {
  int i[3];
  double f[3];
  for (int a = 0; a < 3; ++a) locate(c[a], l.n, i[a], f[a]);
  glm::dvec3 sum(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    const int dr = corner & 1, dg = (corner >> 1) & 1, db = corner >> 2;
    const double w = (dr ? f[0] : 1 - f[0]) * (dg ? f[1] : 1 - f[1]) * (db ? f[2] : 1 - f[2]);
    sum += w * l.at(i[0] + dr, i[1] + dg, i[2] + db);
  }
  return sum;
}

/// An 8-bit lattice (values 0 to 255) read as the hardware rules read an 8-bit volume under Clamp
/// (rasterizer/texture.hpp, "Sampling rules"): each position in 16.8 fixed point, rounded to
/// nearest; each blend of two values (along r, then g, then b) rounded to an integer.
inline glm::dvec3 hardware_trilinear(const Lattice& l, glm::dvec3 c) {
  int i[3], w[3];
  for (int a = 0; a < 3; ++a) {
    const long fixed = std::lround(std::nearbyint(std::clamp(c[a], 0.0, 1.0) * (l.n - 1) * 256.0));
    i[a] = static_cast<int>(fixed >> 8);
    w[a] = static_cast<int>(fixed & 255);
  }
  auto blend = [](double a, double b, int weight) { return a + std::floor(weight * (b - a) / 256.0 + 0.5); };
  auto texel = [&](int dr, int dg, int db) {
    return l.at(std::min(i[0] + dr, l.n - 1), std::min(i[1] + dg, l.n - 1), std::min(i[2] + db, l.n - 1));
  };
  glm::dvec3 out;
  for (int ch = 0; ch < 3; ++ch) {
    auto row = [&](int dg, int db) { return blend(texel(0, dg, db)[ch], texel(1, dg, db)[ch], w[0]); };
    auto slice = [&](int db) { return blend(row(0, db), row(1, db), w[1]); };
    out[ch] = blend(slice(0), slice(1), w[2]);
  }
  return out;
}

/// Tetrahedral: the cell's tetrahedron that holds the point is the one walking from corner 000 to
/// 111 along the axes in order of decreasing fraction; the weights are the fractions' differences.
inline glm::dvec3 tetrahedral(const Lattice& l, glm::dvec3 c) {
  int i[3];
  double f[3];
  for (int a = 0; a < 3; ++a) locate(c[a], l.n, i[a], f[a]);
  std::array<int, 3> axes = {0, 1, 2};
  std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return f[a] > f[b]; });
  int step[3] = {0, 0, 0};
  glm::dvec3 sum = (1.0 - f[axes[0]]) * l.at(i[0], i[1], i[2]);
  for (int k = 0; k < 3; ++k) {
    step[axes[k]] = 1;
    const double w = f[axes[k]] - (k < 2 ? f[axes[k + 1]] : 0.0);
    sum += w * l.at(i[0] + step[0], i[1] + step[1], i[2] + step[2]);
  }
  return sum;
}

}  // namespace luxel::postfx::test
