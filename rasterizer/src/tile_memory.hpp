#pragma once
// The running thread's tile memory during a flush (FastPath::TileMemory, framebuffer.hpp): set by
// Context::run_frame before the thread runs a tile's commands, read by the targets' tile accessors
// (ColorTarget::tile, DepthStencilTarget::depth_tile and stencil_tile). Private to the rasterizer:
// a thread_local is the library's own state, not a part of the framebuffer's interface.

#include <cstddef>

namespace luxel::rasterizer::detail {

inline thread_local std::byte* tile_memory_base = nullptr;

}  // namespace luxel::rasterizer::detail
