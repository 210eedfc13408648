#pragma once
// Compile-time limits of the rasterizer, in one place (as bx and llvmpipe keep theirs).
// Every number here is a named decision; the static_asserts say what depends on what.

#include <cstdint>

namespace luxel::rasterizer {

/// Vertex positions are snapped to 1/256 pixel ("16.8" fixed point, as D3D10 requires).
inline constexpr int kSubpixelBits = 8;
inline constexpr int kSubpixelsPerPixel = 1 << kSubpixelBits;

/// The screen is split into square tiles of this many pixels on a side. A tile's color, depth and
/// stencil (all samples) are contiguous and are shaded by one thread at a time.
inline constexpr int kTileSize = 64;
inline constexpr int kTilePixels = kTileSize * kTileSize;

/// Largest render target, in pixels on a side (the D3D10 texture limit).
inline constexpr int kMaxTargetSize = 8192;

/// Guard band: after the viewport transform, x and y must lie in [-kGuardBand, +kGuardBand]
/// pixels, or the triangle is clipped against the band in homogeneous space. This bounds every
/// snapped coordinate to 2^22 subpixels (2^23 with what rounding in clipping may add; setup
/// drops anything beyond), so edge-function constants fit comfortably in 64 bits (|C| < 2^49)
/// and the per-sample steps of edges shorter than a few thousand pixels fit in 32.
inline constexpr int kGuardBand = 16384;
static_assert(kGuardBand >= 2 * kMaxTargetSize, "the guard band must contain any viewport");
static_assert(kGuardBand * kSubpixelsPerPixel <= (1 << 22), "snapped coordinates must fit 23 bits");

/// Most float4 interpolants a vertex functor may hand to the pixel functor (DX9: 10 texcoords/colors).
inline constexpr int kMaxVaryings = 10;

/// Most samples per pixel.
inline constexpr int kMaxSamples = 8;


/// A draw's front end (vertex functor, clip, setup, binning) is cut into chunks of at most this
/// many triangles, run in parallel; each chunk has its own bins, and a tile replays the chunks in
/// order, so submission order is kept for any thread count. Fewer, larger chunks mean fewer bins
/// to write and replay (bench/README.md).
inline constexpr int kTrianglesPerChunk = 32768;
/// Smaller draws are cut into one chunk per thread, of at least kMinTrianglesPerChunk, so that
/// their front end, too, runs on every thread (the chunking never changes the output). More
/// chunks cost more than they balance: each has its own bins to write and replay.
inline constexpr int kMinTrianglesPerChunk = 512;
static_assert(kMinTrianglesPerChunk <= kTrianglesPerChunk);

/// A draw is recorded in parts of at most this many triangles; between two parts the deferred
/// frame flushes if its records exceed their budget (ContextOptions::max_pending_record_bytes),
/// so one part is what the records can grow beyond it.
inline constexpr uint32_t kTrianglesPerPart = uint32_t(1) << 16;
static_assert(kTrianglesPerChunk <= kTrianglesPerPart);

}  // namespace luxel::rasterizer
