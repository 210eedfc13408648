// The copies of a Texture's levels that sampling reads in place of them: a volume's trilinear
// cells and a cube map's bordered copy, made again from the levels by every upload (and, for a
// cube map, by mip generation).

#include "luxel/rasterizer/texture.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace luxel::rasterizer {

// --- The volumes' trilinear cells ------------------------------------------------------------

void Texture::refresh_cells() {
  if (cell_words_.empty()) return;
  const int w = width_, h = height_, d = depth_;
  const auto texel = [&](int i, int j, int k) {
    return words_[(static_cast<size_t>(std::clamp(k, 0, d - 1)) * h + std::clamp(j, 0, h - 1)) * w + std::clamp(i, 0, w - 1)];
  };
  uint32_t* cell = cell_words_.data();
  for (int k = -1; k <= d; ++k)
    for (int j = -1; j < h; ++j)
      for (int i = -1; i < w; ++i)
        for (int corner = 0; corner < 4; ++corner) *cell++ = texel(i + (corner & 1), j + (corner >> 1), k);
}

// --- The cube maps' sampling copy -------------------------------------------------------------

namespace {

/// Where a texel one step past an edge of a face is read: on face `face`, at column `i` and row
/// `j` given as codes: kFirst (0), kLast (n - 1), kAlong (the texel's position along the edge),
/// kAlongFlipped (n - 1 - that). Derived from the face bases in texture.hpp by folding the
/// overhanging texel onto the neighbouring face (it agrees entry by entry with llvmpipe's
/// lp_build_cube_new_coords); texture_reference.cpp reaches the same texels by ray casting, and
/// the tests hold the two together.
enum EdgeCode : uint8_t { kFirst, kLast, kAlong, kAlongFlipped };
struct EdgeTarget {
  uint8_t face;
  EdgeCode i, j;
};
// [face][edge], edges: 0 = left (i < 0), 1 = right (i >= n), 2 = top (j < 0), 3 = bottom (j >= n).
constexpr EdgeTarget kCubeEdges[6][4] = {
    {{4, kLast, kAlong}, {5, kFirst, kAlong}, {2, kLast, kAlongFlipped}, {3, kLast, kAlong}},            // +X
    {{5, kLast, kAlong}, {4, kFirst, kAlong}, {2, kFirst, kAlong}, {3, kFirst, kAlongFlipped}},          // -X
    {{1, kAlong, kFirst}, {0, kAlongFlipped, kFirst}, {5, kAlongFlipped, kFirst}, {4, kAlong, kFirst}},  // +Y
    {{1, kAlongFlipped, kLast}, {0, kAlong, kLast}, {4, kAlong, kLast}, {5, kAlongFlipped, kLast}},      // -Y
    {{1, kLast, kAlong}, {0, kFirst, kAlong}, {2, kAlong, kLast}, {3, kAlong, kFirst}},                  // +Z
    {{0, kLast, kAlong}, {1, kFirst, kAlong}, {2, kAlongFlipped, kFirst}, {3, kAlongFlipped, kLast}},    // -Z
};

int edge_coordinate(EdgeCode code, int along, int n) {
  switch (code) {
    case kFirst: return 0;
    case kLast: return n - 1;
    case kAlong: return along;
    case kAlongFlipped: return n - 1 - along;
  }
  return 0;
}

}  // namespace

void Texture::refresh_cube_copy(int level, int changed_face) {
  if (kind_ != TextureKind::Cube) return;
  const int n = width(level), stride = n + 2, w = words_per_texel_;
  auto texel = [&](int face, int i, int j) { return words_.data() + face * face_words_ + level_offset_[level] + (j * n + i) * w; };
  for (int face = 0; face < 6; ++face) {
    uint32_t* copy = cube_words_.data() + face * cube_face_words_ + cube_level_offset_[level];
    if (changed_face < 0 || face == changed_face)
      for (int j = 0; j < n; ++j) std::memcpy(copy + ((j + 1) * stride + 1) * w, texel(face, 0, j), size_t(n) * w * 4);
    // The border, of every face (any may show the changed one); its corners stay 0, as the
    // filter computes the texels past a corner.
    for (int edge = 0; edge < 4; ++edge) {
      const EdgeTarget& to = kCubeEdges[face][edge];
      for (int along = 0; along < n; ++along) {
        const int x = edge == 0 ? -1 : edge == 1 ? n : along, y = edge == 2 ? -1 : edge == 3 ? n : along;
        std::memcpy(copy + ((y + 1) * stride + x + 1) * w,
                    texel(to.face, edge_coordinate(to.i, along, n), edge_coordinate(to.j, along, n)), size_t(w) * 4);
      }
    }
  }
}

}  // namespace luxel::rasterizer
