#pragma once
// Binning's fast path, inlined into setup (triangle_setup.cpp): a set-up triangle's record written
// into the stream of the one tile it touches. The rest of binning is binning.cpp.

#include "front_end.hpp"

#include "luxel/rasterizer/detail/triangle_setup.hpp"
#include "luxel/rasterizer/simd.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace luxel::rasterizer::detail {

/// The parts of a record after its header, but for a small flat-shaded triangle (binning.cpp).
[[gnu::noinline]] void write_record_rest(const DrawConstants& dc, const TriangleLanes& tri, const SetupLanes& setup,
                                         int l, std::byte* record);

/// Writes a triangle's record into every tile it touches (binning.cpp).
[[gnu::noinline]] void bin_to_tiles(const DrawConstants& dc, const TriangleLanes& tri, const SetupLanes& setup, int l,
                                    ChunkBins& bins);

/// Writes triangle l's record at `record` from setup's rows: a record line was just allocated
/// and is not in the cache, so nothing may be read from it, and a wider load of values just
/// stored narrower (a struct built on the stack, copied) cannot be forwarded from the store
/// buffer and waits for every older store to reach the cache.
LUXEL_INLINE void write_record(const DrawConstants& dc, const TriangleLanes& tri, const SetupLanes& setup, int l,
                               std::byte* record) {
  std::memcpy(record, setup.header[l], sizeof(TriangleSetup));
  constexpr int kSmallFlat = TriangleSetup::kSmall | TriangleSetup::kFlat;
  if ((setup.header[l][7] >> 8 & kSmallFlat) != kSmallFlat) {
    write_record_rest(dc, tri, setup, l, record);
    return;
  }
  std::memcpy(record + sizeof(TriangleSetup), setup.small_edges[l], sizeof(SmallEdges));
  std::byte* tail = record + TriangleSetup::varyings_offset(true);
  for (int i = 0; i < dc.varyings; ++i) std::memcpy(tail + 16 * i, tri.data[0][l] + 4 * (1 + i), 16);
}

/// Room for a record of `bytes` at the end of `tile`'s stream.
LUXEL_INLINE std::byte* append_to_tile(ChunkBins& bins, int tile, size_t bytes) {
  RecordStream& records = bins.tile_records[tile];
  if (records.empty()) bins.touched_tiles.push_back(static_cast<uint32_t>(tile));
  return records.append(bytes);
}

/// The bytes of triangle l's record.
LUXEL_INLINE size_t record_bytes(const SetupLanes& setup, int l) { return 16 * size_t(setup.header[l][7] & 0xff); }

/// Appends triangle l's record to `tile`'s stream.
LUXEL_INLINE void emit_record(const DrawConstants& dc, const TriangleLanes& tri, const SetupLanes& setup, int l,
                              int tile, ChunkBins& bins) {
  write_record(dc, tri, setup, l, append_to_tile(bins, tile, record_bytes(setup, l)));
}

}  // namespace luxel::rasterizer::detail
