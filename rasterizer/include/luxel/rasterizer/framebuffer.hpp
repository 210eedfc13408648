#pragma once
// Render targets: RGBA8 color with 1/2/4/8 samples, RGBA32F color with one, and 32-bit float
// depth + 8-bit stencil with 1/2/4/8, tiled.
//
// Storage is tiled so that everything one thread touches while shading a tile is contiguous:
// the surface is cut into kTileSize² tiles (row-major); a tile holds its samples plane after
// plane (sample 0 of all its pixels, then sample 1...); inside a plane pixels are ordered by SIMD
// stamp (row-major stamps of simd::kStampWidth x 2 pixels), inside a stamp in lane order
// (see simd.hpp). Surfaces are padded to whole tiles; padding is never written by draws.
//
// RGBA8 color is packed as one uint32 per sample: r | g << 8 | b << 16 | a << 24. An RGBA32F
// tile holds four planes of floats, r, g, b and a, each ordered as a sample plane.
//
// Tile memory (FastPath::TileMemory), as on tile-based GPUs: a frame (the commands between two
// flushes, see Context) that clears a target whole before anything else uses it, and discards it
// (discard()) before the flush, needs its samples only while each tile runs. Such a target's
// tiles then live in the running thread's own tile memory, reused tile after tile, so they stay
// in the core's cache: the clear, the draws and the resolve never touch the target's memory,
// which a 4x MSAA frame otherwise reads and writes back whole every frame. The bytes are the
// same either way; after discard() a target must be cleared whole (clear_color,
// clear_depth_stencil or load_image, without a region) before any other use, in every build
// and with the fast path on or off.

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/rasterizer/limits.hpp"
#include "luxel/rasterizer/simd.hpp"
#include "luxel/rasterizer/state.hpp"

#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace luxel::rasterizer {

class Texture;  // texture.hpp

/// Where pixel (x, y), relative to its tile's origin, sits inside one sample plane of the tile.
constexpr int pixel_offset_in_tile(int x, int y) {
  const int stamp = (y / simd::kStampHeight) * (kTileSize / simd::kStampWidth) + x / simd::kStampWidth;
  const int lx = x % simd::kStampWidth;
  const int lane = (lx / 2) * 4 + (lx & 1) + 2 * (y & 1);
  return stamp * simd::kLanes + lane;
}
static_assert(kTileSize % simd::kStampWidth == 0 && kTileSize % simd::kStampHeight == 0);

/// The tiling shared by all targets of one size and sample count.
struct SurfaceLayout {
  int width = 0, height = 0, samples = 1;
  int tiles_x = 0, tiles_y = 0;

  SurfaceLayout() = default;
  /// Throws std::invalid_argument for sizes outside [1, kMaxTargetSize] or a bad sample count.
  SurfaceLayout(int width, int height, int samples);

  int tile_count() const { return tiles_x * tiles_y; }
  size_t elements_per_tile() const { return static_cast<size_t>(kTilePixels) * samples; }
  size_t element_count() const { return elements_per_tile() * tile_count(); }
  /// Index of pixel (x, y), sample s.
  size_t index(int x, int y, int s) const {
    const int tile = (y / kTileSize) * tiles_x + x / kTileSize;
    return tile * elements_per_tile() + static_cast<size_t>(s) * kTilePixels +
           pixel_offset_in_tile(x % kTileSize, y % kTileSize);
  }
  bool operator==(const SurfaceLayout&) const = default;
};

namespace detail {
inline constexpr size_t kNoTileMemory = ~size_t(0);

/// What the frame being recorded does with a target, and what the last one left of it.
struct FrameUse {
  FrameUse() = default;
  /// A moved target takes its discard() along, not the frame's bookkeeping (a flush ran first,
  /// see PendingUse); being listed belongs to the object, which a context's lists name.
  FrameUse(const FrameUse& other) : discard(other.discard), discarded(other.discarded) {}
  FrameUse& operator=(const FrameUse& other) {
    discard = other.discard, discarded = other.discarded;
    recorded = starts_cleared = false;
    tile_memory_offset = kNoTileMemory;
    return *this;
  }
  bool listed = false;          ///< in the context's lists: a command or discard() in this frame
  bool recorded = false;        ///< a command of this frame uses it
  bool starts_cleared = false;  ///< its first command clears all of it
  bool discard = false;         ///< discard() since its last whole clear in this frame
  bool discarded = false;       ///< a finished frame discarded it; not cleared since
  size_t tile_memory_offset = kNoTileMemory;  ///< where it sits in tile memory, while a flush runs
  bool in_tile_memory() const { return tile_memory_offset != kNoTileMemory; }
  /// Throws std::logic_error if the target's samples were discarded: `what` names the use.
  void check_kept(const char* what) const;
};

/// The frame use of a target, for the context's flush.
struct FrameUseAccess {
  template <class Target>
  static FrameUse& of(const Target& target) { return target.use_; }
};

struct FreeAligned {
  void operator()(void* p) const;
};
void* allocate_aligned(size_t bytes);
}  // namespace detail

/// A 64-byte aligned array that is never copied by accident.
template <class T>
class SurfaceBuffer {
 public:
  SurfaceBuffer() = default;
  explicit SurfaceBuffer(size_t count)
      : data_(static_cast<T*>(detail::allocate_aligned(count * sizeof(T)))), count_(count) {}
  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  size_t size() const { return count_; }
  T& operator[](size_t i) { return data_.get()[i]; }
  const T& operator[](size_t i) const { return data_.get()[i]; }

 private:
  std::unique_ptr<T, detail::FreeAligned> data_;
  size_t count_ = 0;
};

/// What a color target's samples hold.
enum class ColorFormat : uint8_t {
  /// 8 bits per channel, each clamped to [0, 1] and rounded (NaN writes 0): the frame and
  /// post-processing targets. Any sample count, blending, sRGB writes.
  rgba8,
  /// A 32-bit float per channel, exactly as the pixel functor or the clear gave it: no clamp
  /// and no rounding, so values beyond [0, 1], negative ones and NaN come back bit for bit
  /// (Direct3D 9's D3DFMT_A32B32G32R32F). For linear HDR frames read back as floats, as a cube-map
  /// capture's. One sample, no blending and no sRGB writes (DX9-generation GPUs blended no
  /// 32-bit float target either): a target with more samples, or a draw into it with either, throws
  /// std::invalid_argument. Read it with the float resolve_into below; it has no sample().
  rgba32f,
};

/// A color target. Movable; destroying or moving one that a context's pending frame refers to
/// flushes that context first (see Context, "The deferred frame").
class ColorTarget {
 public:
  /// Throws std::invalid_argument for a bad size or sample count (SurfaceLayout), or an rgba32f
  /// target of more than one sample.
  ColorTarget(int width, int height, int samples = 1, ColorFormat format = ColorFormat::rgba8);
  ColorTarget(ColorTarget&&) = default;
  ColorTarget& operator=(ColorTarget&&) = default;
  ~ColorTarget() { pending_.release(); }

  const SurfaceLayout& layout() const { return layout_; }
  int width() const { return layout_.width; }
  int height() const { return layout_.height; }
  int samples() const { return layout_.samples; }
  ColorFormat format() const { return format_; }
  /// Tile t's samples as 32-bit words (an rgba32f tile's floats, see the top of this file), for
  /// the commands a flush runs, and valid only on the thread that runs them during that flush: in
  /// that thread's tile memory when the frame keeps the target there, else in the target's own
  /// memory (allocated by the flush, allocate_memory).
  uint32_t* tile(int t) { return const_cast<uint32_t*>(std::as_const(*this).tile(t)); }
  const uint32_t* tile(int t) const;
  /// Bytes of one tile's samples.
  size_t tile_bytes() const { return tile_words() * sizeof(uint32_t); }
  /// An rgba8 target's samples, read and written after a flush; std::logic_error after discard()
  /// until the next whole clear, or for an rgba32f target. The first access may allocate the
  /// target's memory (allocate_memory): not from two threads at once then.
  uint32_t sample(int x, int y, int s) const {
    check_rgba8("read");
    allocate_memory();
    return texels_[layout_.index(x, y, s)];
  }
  void set_sample(int x, int y, int s, uint32_t rgba) {
    check_rgba8("written");
    allocate_memory();
    texels_[layout_.index(x, y, s)] = rgba;
  }
  /// The target's own memory, every sample 0, is allocated when first needed: a target that
  /// only ever lives in tile memory never has it.
  void allocate_memory() const;

 private:
  friend class Context;
  friend struct detail::FrameUseAccess;
  /// Words of one sample: an rgba32f pixel holds four.
  int words_per_sample() const { return format_ == ColorFormat::rgba32f ? 4 : 1; }
  size_t tile_words() const { return layout_.elements_per_tile() * words_per_sample(); }
  /// Throws std::logic_error unless sample() may access the samples: `what` names the access.
  void check_rgba8(const char* what) const;

  detail::PendingUse pending_;  // first: see PendingUse
  SurfaceLayout layout_;
  ColorFormat format_ = ColorFormat::rgba8;
  mutable SurfaceBuffer<uint32_t> texels_;
  mutable detail::FrameUse use_;  // kept by the context whose frame uses the target
};

/// Float depth in [0, 1] and an 8-bit stencil value per sample. Movable, with the same rule as
/// ColorTarget for pending frames.
class DepthStencilTarget {
 public:
  DepthStencilTarget(int width, int height, int samples = 1);
  DepthStencilTarget(DepthStencilTarget&&) = default;
  DepthStencilTarget& operator=(DepthStencilTarget&&) = default;
  ~DepthStencilTarget() { pending_.release(); }

  const SurfaceLayout& layout() const { return layout_; }
  int width() const { return layout_.width; }
  int height() const { return layout_.height; }
  int samples() const { return layout_.samples; }
  /// Tile t's depth and stencil samples, for the commands a flush runs, and valid only on the
  /// thread that runs them during that flush: in that thread's tile memory when the frame keeps
  /// the target there (depth, then stencil), else in the target's own memory (allocated by the
  /// flush, allocate_memory).
  float* depth_tile(int t);
  uint8_t* stencil_tile(int t);
  /// Bytes of one tile's samples, both planes.
  size_t tile_bytes() const { return layout_.elements_per_tile() * (sizeof(float) + sizeof(uint8_t)); }
  /// Read after a flush; std::logic_error after discard() until the next whole clear. The first
  /// read may allocate the target's memory (allocate_memory): not from two threads at once then.
  float depth(int x, int y, int s) const {
    use_.check_kept("read");
    allocate_memory();
    return depth_[layout_.index(x, y, s)];
  }
  uint8_t stencil(int x, int y, int s) const {
    use_.check_kept("read");
    allocate_memory();
    return stencil_[layout_.index(x, y, s)];
  }
  /// The target's own memory, depth 1 and stencil 0 in every sample, is allocated when first
  /// needed: a target that only ever lives in tile memory never has it.
  void allocate_memory() const;

 private:
  friend class Context;
  friend struct detail::FrameUseAccess;
  detail::PendingUse pending_;  // first: see PendingUse
  SurfaceLayout layout_;
  mutable SurfaceBuffer<float> depth_;
  mutable SurfaceBuffer<uint8_t> stencil_;
  mutable detail::FrameUse use_;  // kept by the context whose frame uses the target
};

/// What a draw renders into. Either target may be absent; present targets must share size and
/// sample count.
struct Framebuffer {
  ColorTarget* color = nullptr;
  DepthStencilTarget* depth_stencil = nullptr;
};

/// Packs a color with round-to-nearest after clamping to [0, 1] (NaN becomes 0), as an rgba8
/// target holds it.
uint32_t pack_rgba8(glm::vec4 color);
/// Inline: vertex functors unpack per-vertex colors with it.
inline glm::vec4 unpack_rgba8(uint32_t rgba) {
  return glm::vec4(rgba & 255, (rgba >> 8) & 255, (rgba >> 16) & 255, rgba >> 24) / 255.0f;
}

/// Records a clear of every sample (runs at the next flush, like draws) to `color`, packed as
/// pack_rgba8 does, or as it is into an rgba32f target. With an enabled `region` (pixels
/// [x0, x1) x [y0, y1)), only the tiles that hold some of it are cleared: what a view scissored
/// to the region needs, the rest of the target left as it was.
void clear_color(Context& ctx, ColorTarget& target, glm::vec4 color, const Scissor& region = {});
void clear_depth_stencil(Context& ctx, DepthStencilTarget& target, float depth, uint8_t stencil, const Scissor& region = {});
/// Depth alone (D3DCLEAR_ZBUFFER without D3DCLEAR_STENCIL): stencil keeps its values.
void clear_depth(Context& ctx, DepthStencilTarget& target, float depth, const Scissor& region = {});

/// Declares the target's samples undefined from here on (Vulkan's load op DONT_CARE): recorded
/// like a whole clear, without the fill, so a frame that also discards the target keeps it in
/// tile memory. Only for a frame in which nothing reads the samples before writing them: draws
/// with the depth and stencil tests off (the luminance histogram's counting draw), or a draw that
/// writes every sample without blending (a post pass's rectangle over the whole target). What
/// such a read returns is undefined, and may differ from one run or thread count to the next.
void invalidate(Context& ctx, ColorTarget& target);
void invalidate(Context& ctx, DepthStencilTarget& target);

/// Declares that the target's samples are not needed after the frame being recorded
/// (glInvalidateFramebuffer, Vulkan's store op DONT_CARE). Record it before the frame's last use,
/// a resolve, which flushes and so ends the frame; in that frame only a resolve may follow it (a
/// draw throws std::logic_error). A frame that cleared the target whole first then keeps it in
/// tile memory (FastPath::TileMemory, above). Once the frame has ended, the target must be
/// cleared whole before any other use: drawing into it, resolving it or reading its samples first
/// throws std::logic_error. A whole clear recorded after discard() in the same frame starts new
/// samples, which are kept.
void discard(Context& ctx, ColorTarget& target);
void discard(Context& ctx, DepthStencilTarget& target);

/// Loads an image into every sample of a target of the same size (the reverse of a one-sample
/// resolve): how a finished frame held as an Image comes back as a target that post-processing
/// passes draw onto. Recorded like a clear; the image must stay alive until the next flush.
/// Throws std::invalid_argument when the sizes differ or the target is rgba32f.
void load_image(Context& ctx, const Image& image, ColorTarget& target);

/// What a resolve writes to the image's alpha.
enum class ResolveAlpha {
  samples,  ///< the mean of the samples' alpha, as for the color channels
  opaque,   ///< 255: an image to be shown, whose target's alpha held the shaders' own values
};

/// Box-filter resolve of an rgba8 target: each channel of each pixel is the rounded mean of its
/// samples' 8-bit values (a plain copy out of the tiled layout for one sample). Flushes the
/// context. The resolves into an image or a texture throw std::invalid_argument for an rgba32f
/// target, which has its own below.
Image resolve(Context& ctx, const ColorTarget& target, ResolveAlpha alpha = ResolveAlpha::samples);
/// The same into an existing image (reallocated only when its size differs). With an enabled
/// `region`, only the tiles that hold some of it are resolved; the image keeps its other pixels.
void resolve_into(Context& ctx, const ColorTarget& target, Image& image, ResolveAlpha alpha = ResolveAlpha::samples,
                  const Scissor& region = {});
/// The same into level 0 of `texture`, a 2D RGBA8 (or RGBA8_sRGB: the bytes as they are) texture
/// of one level and the target's size, in place: the render target that is also a texture, or
/// D3D9's StretchRect of a multisampled surface into one, with no copy through an image. Its
/// opaque() follows. Throws std::invalid_argument for any other texture.
void resolve_into(Context& ctx, const ColorTarget& target, Texture& texture, ResolveAlpha alpha = ResolveAlpha::samples,
                  const Scissor& region = {});
/// An rgba32f target's pixels as floats, bit for bit, into `pixels` (resized to width x height,
/// row-major, top row first). A resolve like the others: it may follow discard() in the frame,
/// and flushes the context. Throws std::invalid_argument for an rgba8 target.
void resolve_into(Context& ctx, const ColorTarget& target, std::vector<glm::vec4>& pixels);

}  // namespace luxel::rasterizer
