#pragma once
// Image files in and out, through OpenImageIO (PNG, JPEG, TIFF, OpenEXR, Radiance HDR, TGA, PPM...,
// the format named by the file's extension, or in memory by its signature (PNG or JPEG, what glTF
// allows), on reading; by its extension on writing). A file whose contents are not its
// extension's format is refused, not tried as every other format in turn.
//
// Reading gives a PixelImage (scene.hpp): 4 channels, top row first, straight (unassociated)
// alpha; missing channels are filled in (grey replicated to rgb, alpha 1). Files whose pixels are
// 8-bit integers stay 8-bit (`rgba8`); float and half files (EXR, HDR, float TIFF) become
// `rgba32f`, unchanged; other integer depths (16-bit PNG) are rounded to 8 bits by OpenImageIO.
// Bytes are returned as stored: whether they are sRGB is for the texture using them to say.
//
// Every failure throws std::runtime_error whose what() is one line "NAME: problem", NAME being the
// path (or the name given for bytes in memory). Images larger than kMaxImageSide on a side, or
// whose pixels would take more than the memory limit (memory_limit.hpp) as read and as kept, are
// refused before their pixels are allocated (the latter with MemoryLimitError). While an image is
// read, the process's stderr is closed: the libraries under OpenImageIO print complaints of their
// own there (libpng a "libpng error: ..." line for every damaged PNG), which the error carries.

#include "luxel/scenes/memory_limit.hpp"
#include "luxel/scenes/scene.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace luxel::scenes {

/// The largest width or height read_image accepts (16384^2 RGBA floats are already 4 GiB).
inline constexpr int kMaxImageSide = 16384;

/// Reads an image file.
PixelImage read_image(const std::string& path, uint64_t memory_limit = kDefaultMemoryLimit);

/// Reads an image file held in memory (a glTF buffer view or data URI); `name` is used in messages.
PixelImage read_image(std::span<const uint8_t> bytes, const std::string& name, uint64_t memory_limit = kDefaultMemoryLimit);

/// Writes an image; the format comes from the extension. 8-bit images are written as 8-bit, float
/// images as float where the format holds floats (EXR, HDR) and converted (clamped) where not.
void write_image(const PixelImage& image, const std::string& path);

/// Writes width x height RGBA8 pixels (row-major, top row first), e.g. a rasterizer::Image.
void write_image(int width, int height, std::span<const uint8_t> rgba8, const std::string& path);

/// The image encoded as an 8-bit RGBA PNG in memory (glTF export embeds textures this way).
/// Float images are refused: PNG cannot hold them.
std::vector<uint8_t> encode_png(const PixelImage& image, const std::string& name);

}  // namespace luxel::scenes
