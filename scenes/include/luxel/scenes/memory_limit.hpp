#pragma once
// The memory limit: one number of bytes beyond which luxel refuses a piece of work instead of
// allocating it.
//
// Each reader and builder of large data estimates what a request needs from its sizes alone,
// before the allocations it counts, and throws MemoryLimitError when that is beyond the limit:
//  - an image file (image_io.hpp): the pixels its header claims, as read and as kept;
//  - a glTF file (gltf.hpp): the file and its buffers, its images, and the flattened scene's
//    vertices and triangle corners as a Scene holds them;
//  - a frame (frame/renderer.hpp): the scene's meshes and textures, the textures' uploaded copies
//    with their mips, the render targets at their samples and the images resolved from them;
//  - a bake (bake/settings.hpp, BakeSettings::max_memory_bytes): the lightmap atlas and the
//    bake's working set per luxel.
// The estimates count the large arrays, not the code, the libraries' caches or the threads'
// stacks: the limit bounds what a scene, an image or a size asks of memory, it is not a cap on
// the process's resident size.
//
// The default is a fixed 4 GiB rather than a share of the machine's memory, so that a request is
// accepted or refused alike on every machine (luxel's outputs never depend on the machine it runs
// on). It is above what every built-in scene, every test asset and an 8192 x 8192 frame at 4
// samples need (about 3.3 GiB), and within what an 8 GB machine can give. `luxel` takes the limit
// from --memory-limit SIZE, else from the environment variable LUXEL_MEMORY_LIMIT, else the
// default; the libraries take it from their options (GltfImportOptions::memory_limit,
// FrameSettings::memory_limit, BakeSettings::max_memory_bytes, read_image's argument).

#include "luxel/scenes/scene.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace luxel::scenes {

inline constexpr uint64_t kDefaultMemoryLimit = uint64_t{4} << 30;
/// The environment variable `luxel` reads the limit from when --memory-limit is not given.
inline constexpr const char* kMemoryLimitVariable = "LUXEL_MEMORY_LIMIT";

/// A request beyond the limit. what() is one line: "NAME: needs about 9.1 GiB (WHAT), beyond the
/// memory limit of 4 GiB (raise it with --memory-limit or LUXEL_MEMORY_LIMIT)".
struct MemoryLimitError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Throws MemoryLimitError naming `name` (the file or scene) when `needed` bytes are beyond
/// `limit`; `what` says what they are ("10000000 triangles, 5000000 vertices").
void check_memory(const std::string& name, uint64_t needed, const std::string& what, uint64_t limit);

/// A size in bytes as people read it: "100 bytes", "512 KiB", "9.1 GiB" (powers of 1024, one
/// decimal below 10 units).
std::string format_bytes(uint64_t bytes);

/// A size as `--memory-limit` and LUXEL_MEMORY_LIMIT take it: bytes ("1073741824"), or a number
/// followed by K, M, G or T, with or without "iB" or "B" ("512M", "1.5G", "8GiB"), powers of 1024.
/// Throws std::invalid_argument "'TEXT' is not a size (...)" for anything else, 0 included, and
/// for sizes beyond 2^63 bytes.
uint64_t parse_memory_size(const std::string& text);

/// LUXEL_MEMORY_LIMIT parsed, or kDefaultMemoryLimit when it is unset or empty. Throws
/// std::invalid_argument "LUXEL_MEMORY_LIMIT: 'TEXT' is not a size (...)" when it is set badly.
uint64_t memory_limit_from_environment();

/// The bytes an image of this size takes once read (PixelImage: 4 channels, 1 or 4 bytes each).
uint64_t image_bytes(uint64_t width, uint64_t height, bool hdr);

/// The bytes a scene's meshes and textures hold: what rendering or baking it keeps in memory
/// besides its own arrays.
uint64_t scene_bytes(const Scene& scene);

}  // namespace luxel::scenes
