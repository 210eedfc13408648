#pragma once
// Private to the texture module: the filters of the SIMD sampling path (texture_sample_impl.hpp),
// one level of one kind of texture each: 2D, volume (from its texels, or from its trilinear
// cells) and cube maps (the projection of directions onto faces, then the filter).
//
// Cube maps are read from their bordered copy (Texture), where a footprint straddling a face's
// edge finds the texels across it in the border; only texels past a corner are computed here.

#include "texture_addressing.hpp"

namespace luxel::rasterizer::texture_sampling {

// --- 2D and volume ----------------------------------------------------------------------------

template <class Format>
LUXEL_INLINE TexelOf<Format> filter_2d(const Context<Format>& ctx, const Level& g, Filter filter, const Float& u, const Float& v) {
  const Sampler& s = ctx.sampler;
  if (filter == Filter::Point) {
    IntMask out_x = simd::no_lanes(), out_y = simd::no_lanes();
    const Int i = point_axis(u, g.width, g.fwidth, s.u, out_x);
    const Int j = point_axis(v, g.height, g.fheight, s.v, out_y);
    const Int index = word_index<Format>(g.offset, row_start(j, g.width) + i);
    if (ctx.prefetch_words_below != 0) prefetch_below(ctx.storage.words, index, ctx.prefetch_words_below);
    TexelOf<Format> t = fetch(ctx, index);
    if (ctx.any_border) apply_border(ctx, out_x | out_y, t);
    return t;
  }
  const LinearAxis x = linear_axis<Format>(u, g.width, g.fwidth, s.u);
  const LinearAxis y = linear_axis<Format>(v, g.height, g.fheight, s.v);
  const Int row0 = row_start(y.i0, g.width), row1 = row_start(y.i1, g.width);
  if (ctx.prefetch_words_below != 0) {
    prefetch_windows_below(ctx.storage.words, word_index<Format>(g.offset, row0 + x.i0), word_index<Format>(g.offset, row1 + x.i0),
                           ctx.prefetch_words_below);
  }
  const auto texel = [&](const Int& row, const Int& column) LUXEL_INLINE_LAMBDA {
    return fetch(ctx, word_index<Format>(g.offset, row + column));
  };
  TexelOf<Format> t00 = texel(row0, x.i0);
  if constexpr (Format::kNonNegative) {
    // A post pass's blur taps along one axis and samples the other at texel centers, where the
    // weight is 0 wherever the coordinate's float rounding is exact: then the lerp along that axis
    // returns its first texel to the bit (fma(0, b - a, a) = a for finite b - a and a >= +0, and
    // the first lerps' results lie between their texels), so its second texels need not be read.
    if (ctx.skips_zero_weights && !ctx.any_border) {
      if (xsimd::all(y.weight == Float(0.0f))) return blend<Format>(t00, texel(row0, x.i1), x.weight);
      if (xsimd::all(x.weight == Float(0.0f))) return blend<Format>(t00, texel(row1, x.i0), y.weight);
    }
  }
  TexelOf<Format> t10 = texel(row0, x.i1);
  TexelOf<Format> t01 = texel(row1, x.i0);
  TexelOf<Format> t11 = texel(row1, x.i1);
  if (ctx.any_border) {
    apply_border(ctx, x.outside0 | y.outside0, t00);
    apply_border(ctx, x.outside1 | y.outside0, t10);
    apply_border(ctx, x.outside0 | y.outside1, t01);
    apply_border(ctx, x.outside1 | y.outside1, t11);
  }
  return blend<Format>(blend<Format>(t00, t10, x.weight), blend<Format>(t01, t11, x.weight), y.weight);
}

/// A trilinear footprint under Clamp read from the volume's cells (Texture::cell_words_): the
/// texels and weights filter_volume's own footprint reads, and its lerps in its order, so the same
/// result to the bit, from two loads per lane instead of eight gathers.
template <class Format>
LUXEL_INLINE TexelOf<Format> filter_volume_cells(const Context<Format>& ctx, const Level& g, const Float& u, const Float& v,
                                                 const Float& w) {
  // A footprint's start clamped to [-1, n - 1] names the cell of the two texels Clamp reads, plus
  // one: cells start at -1.
  const auto cell_axis = [](const Float& c, const Int& n, const Float& fn, Float& weight) {
    return xsimd::min(xsimd::max(footprint_start<Format>(c, fn, weight), Int(-1)), n - Int(1)) + Int(1);
  };
  Float wx, wy, wz;
  const Int i = cell_axis(u, g.width, g.fwidth, wx), j = cell_axis(v, g.height, g.fheight, wy);
  const Int k = cell_axis(w, g.depth, g.fdepth, wz);
  const Int one(1);
  const Int square = (k * (g.height + one) + j) * (g.width + one) + i;
  Int words[8];
  const int32_t first = square.get(0);
  if (xsimd::all(square == Int(first))) {
    // Every lane's footprint in one cell (a flat patch of the frame, where neighbouring pixels'
    // colors differ by less than a LUT texel): its eight words read once for all lanes, the
    // same words the gathers would bring each.
    const int32_t* cell = ctx.cells + 4 * first;
    for (int c = 0; c < 4; ++c) {
      words[c] = Int(cell[c]);
      words[c + 4] = Int(cell[ctx.cell_slice_words + c]);
    }
  } else {
    simd::gather_two_fours(ctx.cells, square << 2, ctx.cell_slice_words, words);
  }
  TexelOf<Format> t[8];
  for (int c = 0; c < 8; ++c) t[c] = Format::decode(words[c]);
  return blend<Format>(blend<Format>(blend<Format>(t[0], t[1], wx), blend<Format>(t[2], t[3], wx), wy), blend<Format>(blend<Format>(t[4], t[5], wx), blend<Format>(t[6], t[7], wx), wy), wz);
}

template <class Format>
LUXEL_INLINE TexelOf<Format> filter_volume(const Context<Format>& ctx, const Level& g, Filter filter, const Float& u,
                                           const Float& v, const Float& w) {
  const Sampler& s = ctx.sampler;
  const Int slice = g.width * g.height;
  if (filter == Filter::Point) {
    IntMask out_x = simd::no_lanes(), out_y = simd::no_lanes(), out_z = simd::no_lanes();
    const Int i = point_axis(u, g.width, g.fwidth, s.u, out_x);
    const Int j = point_axis(v, g.height, g.fheight, s.v, out_y);
    const Int k = point_axis(w, g.depth, g.fdepth, s.w, out_z);
    TexelOf<Format> t = fetch(ctx, word_index<Format>(g.offset, k * slice + row_start(j, g.width) + i));
    if (ctx.any_border) apply_border(ctx, out_x | out_y | out_z, t);
    return t;
  }
  if constexpr (Format::kWords == 1) {
    if (ctx.cells) return filter_volume_cells<Format>(ctx, g, u, v, w);
  }
  const LinearAxis x = linear_axis<Format>(u, g.width, g.fwidth, s.u);
  const LinearAxis y = linear_axis<Format>(v, g.height, g.fheight, s.v);
  const LinearAxis z = linear_axis<Format>(w, g.depth, g.fdepth, s.w);
  auto filter_slice = [&](const Int& k, const IntMask& out_z) LUXEL_INLINE_LAMBDA {
    const Int plane = k * slice;
    const Int row0 = plane + row_start(y.i0, g.width), row1 = plane + row_start(y.i1, g.width);
    TexelOf<Format> t00 = fetch(ctx, word_index<Format>(g.offset, row0 + x.i0));
    TexelOf<Format> t10 = fetch(ctx, word_index<Format>(g.offset, row0 + x.i1));
    TexelOf<Format> t01 = fetch(ctx, word_index<Format>(g.offset, row1 + x.i0));
    TexelOf<Format> t11 = fetch(ctx, word_index<Format>(g.offset, row1 + x.i1));
    if (ctx.any_border) {
      apply_border(ctx, x.outside0 | y.outside0 | out_z, t00);
      apply_border(ctx, x.outside1 | y.outside0 | out_z, t10);
      apply_border(ctx, x.outside0 | y.outside1 | out_z, t01);
      apply_border(ctx, x.outside1 | y.outside1 | out_z, t11);
    }
    return blend<Format>(blend<Format>(t00, t10, x.weight), blend<Format>(t01, t11, x.weight), y.weight);
  };
  return blend<Format>(filter_slice(z.i0, z.outside0), filter_slice(z.i1, z.outside1), z.weight);
}

// --- Cube maps --------------------------------------------------------------------------------

/// Per-lane face, u, v of cube directions (see texture.hpp for the rules).
struct CubeCoords {
  Int face;
  Float u, v;
};

LUXEL_INLINE CubeCoords project_to_faces(const TexCoord& d) {
  const Float ax = xsimd::abs(d.x), ay = xsimd::abs(d.y), az = xsimd::abs(d.z);
  const FloatMask on_z = (az >= ax) & (az >= ay);
  const FloatMask on_y = (!on_z) & (ay >= ax);
  const Float ma = xsimd::select(on_z, d.z, xsimd::select(on_y, d.y, d.x));
  const FloatMask negative = ma < Float(0.0f);
  // (sc, tc): +X (-z, -y), -X (z, -y), +Y (x, z), -Y (x, -z), +Z (x, -y), -Z (-x, -y).
  const Float sign = xsimd::select(negative, Float(-1.0f), Float(1.0f));
  const Float sc = xsimd::select(on_z, sign * d.x, xsimd::select(on_y, d.x, -(sign * d.z)));
  const Float tc = xsimd::select(on_y, sign * d.z, -d.y);
  const Float m = xsimd::abs(ma);
  Float s = sc / m, t = tc / m;
  const Float zero(0.0f), one(1.0f), half(0.5f);
  // NaN -> the face's center; clamped, as a NaN component can make |ma| not the largest.
  s = xsimd::min(xsimd::max(xsimd::select(xsimd::isnan(s), zero, s), -one), one);
  t = xsimd::min(xsimd::max(xsimd::select(xsimd::isnan(t), zero, t), -one), one);
  CubeCoords c;
  const Int axis = xsimd::select(int_mask(on_z), Int(2), xsimd::select(int_mask(on_y), Int(1), Int(0)));
  c.face = axis + axis + xsimd::select(int_mask(negative), Int(1), Int(0));
  c.u = (s + one) * half;
  c.v = (t + one) * half;
  return c;
}

template <class Format>
LUXEL_INLINE TexelOf<Format> filter_cube(const Context<Format>& ctx, const Level& g, Filter filter, const CubeCoords& c) {
  // The sampling copy (Texture): face levels n texels wide are stored n + 2 wide, texel (i, j) of
  // the face at (i + 1, j + 1), bordered by the texels across its edges. g.offset is the level's
  // offset in that copy.
  const Int face_offset = c.face * Int(ctx.storage.face_words) + g.offset;
  const Int one(1), stride = g.width + Int(2), last = g.width - one;
  if (filter == Filter::Point) {
    const Int i = xsimd::min(to_int(xsimd::floor(c.u * g.fwidth)), last) + one;
    const Int j = xsimd::min(to_int(xsimd::floor(c.v * g.fwidth)), last) + one;
    return Format::fetch(ctx.storage.words, word_index<Format>(face_offset, row_start(j, stride) + i));
  }
  // u and v lie in [0, 1] (project_to_faces), so i0 and j0 lie in [-1, n - 1]: within the border.
  Float wx, wy;
  const Int i0 = footprint_start<Format>(c.u, g.fwidth, wx), j0 = footprint_start<Format>(c.v, g.fwidth, wy);
  // Slots 0..3: texels (i0, j0), (i1, j0), (i0, j1), (i1, j1).
  const Int row0 = row_start(j0 + one, stride) + i0 + one, row1 = row0 + stride;
  const Int index[4] = {word_index<Format>(face_offset, row0), word_index<Format>(face_offset, row0 + one),
                        word_index<Format>(face_offset, row1), word_index<Format>(face_offset, row1 + one)};
  TexelOf<Format> t[4];
  for (int k = 0; k < 4; ++k) t[k] = Format::fetch(ctx.storage.words, index[k]);
  // A texel past a cube corner (past two edges) is the mean of the footprint's other three.
  const Int zero(0);
  const IntMask before_i = i0 < zero, after_i = i0 >= last, before_j = j0 < zero, after_j = j0 >= last;
  const IntMask corner[4] = {before_i & before_j, after_i & before_j, before_i & after_j, after_i & after_j};
  if (xsimd::any(corner[0] | corner[1] | corner[2] | corner[3])) {
    TexelOf<Format> fixed[4];
    for (int k = 0; k < 4; ++k) fixed[k] = corner_mean<Format>(t[k ^ 1], t[k ^ 2], t[k ^ 3]);
    for (int k = 0; k < 4; ++k) t[k] = select(float_mask(corner[k]), fixed[k], t[k]);
  }
  return blend<Format>(blend<Format>(t[0], t[1], wx), blend<Format>(t[2], t[3], wx), wy);
}

}  // namespace luxel::rasterizer::texture_sampling
