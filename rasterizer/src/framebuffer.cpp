#include "luxel/rasterizer/framebuffer.hpp"

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/detail/command_queue.hpp"
#include "luxel/rasterizer/msaa.hpp"
#include "luxel/rasterizer/texture.hpp"

#include "texture_internal.hpp"
#include "tile_memory.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstring>
#include <cmath>
#include <cstdlib>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>

namespace luxel::rasterizer {

namespace detail {
void FrameUse::check_kept(const char* what) const {
  if (discarded)
    throw std::logic_error(std::string("a render target was ") + what +
                           " after discard() without a whole clear first: its samples are gone");
}

void FreeAligned::operator()(void* p) const { std::free(p); }
void* allocate_aligned(size_t bytes) {
  const size_t rounded = (bytes + 63) / 64 * 64;
  void* p = std::aligned_alloc(64, std::max<size_t>(rounded, 64));
  if (!p) throw std::bad_alloc();
  return p;
}
}  // namespace detail

SurfaceLayout::SurfaceLayout(int w, int h, int s) : width(w), height(h), samples(s) {
  if (w < 1 || h < 1 || w > kMaxTargetSize || h > kMaxTargetSize)
    throw std::invalid_argument("render target size " + std::to_string(w) + "x" + std::to_string(h) +
                                " is outside 1.." + std::to_string(kMaxTargetSize));
  if (!is_valid_sample_count(s))
    throw std::invalid_argument("sample count " + std::to_string(s) + " is not 1, 2, 4 or 8");
  tiles_x = (w + kTileSize - 1) / kTileSize;
  tiles_y = (h + kTileSize - 1) / kTileSize;
}

ColorTarget::ColorTarget(int width, int height, int samples, ColorFormat format)
    : layout_(width, height, samples), format_(format) {
  if (format == ColorFormat::rgba32f && samples != 1)
    throw std::invalid_argument("an rgba32f color target has one sample, not " + std::to_string(samples) +
                                ": multisampled float targets are not supported");
}

const uint32_t* ColorTarget::tile(int t) const {
  if (use_.in_tile_memory()) return reinterpret_cast<const uint32_t*>(detail::tile_memory_base + use_.tile_memory_offset);
  return texels_.data() + t * tile_words();  // allocated by the flush (allocate_memory)
}

void ColorTarget::allocate_memory() const {
  if (texels_.size() != 0) return;
  texels_ = SurfaceBuffer<uint32_t>(layout_.element_count() * words_per_sample());
  std::fill_n(texels_.data(), texels_.size(), 0u);  // 0.0f in an rgba32f target
}

void ColorTarget::check_rgba8(const char* what) const {
  use_.check_kept(what);
  if (format_ != ColorFormat::rgba8)
    throw std::logic_error(std::string("an rgba32f color target was ") + what +
                           " as 8-bit samples: its floats are read with resolve_into");
}

DepthStencilTarget::DepthStencilTarget(int width, int height, int samples) : layout_(width, height, samples) {}

float* DepthStencilTarget::depth_tile(int t) {
  if (use_.in_tile_memory()) return reinterpret_cast<float*>(detail::tile_memory_base + use_.tile_memory_offset);
  return depth_.data() + t * layout_.elements_per_tile();  // allocated by the flush (allocate_memory)
}

uint8_t* DepthStencilTarget::stencil_tile(int t) {
  if (use_.in_tile_memory())
    return reinterpret_cast<uint8_t*>(detail::tile_memory_base + use_.tile_memory_offset) + layout_.elements_per_tile() * sizeof(float);
  return stencil_.data() + t * layout_.elements_per_tile();
}

void DepthStencilTarget::allocate_memory() const {
  if (depth_.size() != 0) return;
  depth_ = SurfaceBuffer<float>(layout_.element_count());
  stencil_ = SurfaceBuffer<uint8_t>(layout_.element_count());
  std::fill_n(depth_.data(), depth_.size(), 1.0f);
  std::fill_n(stencil_.data(), stencil_.size(), uint8_t(0));
}

uint32_t pack_rgba8(glm::vec4 c) {
  uint32_t out = 0;
  for (int i = 0; i < 4; ++i) {
    const float v = std::isnan(c[i]) ? 0.0f : std::clamp(c[i], 0.0f, 1.0f);
    out |= static_cast<uint32_t>(std::nearbyint(v * 255.0f)) << (8 * i);
  }
  return out;
}

namespace {

/// Whether tile `tile` holds some of `region` (every tile does when the region is off).
bool tile_holds(const SurfaceLayout& L, int tile, const Scissor& region) {
  if (!region.enable) return true;
  const int x0 = (tile % L.tiles_x) * kTileSize, y0 = (tile / L.tiles_x) * kTileSize;
  return x0 < region.x1 && region.x0 < x0 + kTileSize && y0 < region.y1 && region.y0 < y0 + kTileSize;
}

/// Makes the pending frame use `layout`, flushing a frame of another tiling first.
detail::CommandQueue& queue_for(Context& ctx, const SurfaceLayout& layout) {
  if (!ctx.queue().accepts(layout)) ctx.flush_within_frame();
  ctx.queue().set_layout(layout);
  return ctx.queue();
}

class ClearColorCommand final : public detail::Command {
 public:
  ClearColorCommand(ColorTarget& target, glm::vec4 color, const Scissor& region)
      : target_(target), region_(region) {
    if (target.format() == ColorFormat::rgba8) {
      plane_words_ = target.layout().elements_per_tile();  // one plane of every sample
      planes_ = 1;
      words_[0] = pack_rgba8(color);
    } else {
      plane_words_ = kTilePixels;  // a plane per channel, the float's bits as they are
      planes_ = 4;
      for (int c = 0; c < 4; ++c) words_[c] = std::bit_cast<uint32_t>(color[c]);
    }
  }
  void execute(int tile, detail::ThreadCounters&) override {
    if (!tile_holds(target_.layout(), tile, region_)) return;
    uint32_t* texels = target_.tile(tile);
    for (int p = 0; p < planes_; ++p) simd::fill_u32(texels + p * plane_words_, words_[p], plane_words_);
  }

 private:
  ColorTarget& target_;
  Scissor region_;
  size_t plane_words_ = 0;
  int planes_ = 0;
  uint32_t words_[4] = {};
};

/// Clears depth, and stencil unless it is left out.
class ClearDepthStencilCommand final : public detail::Command {
 public:
  ClearDepthStencilCommand(DepthStencilTarget& target, float depth, std::optional<uint8_t> stencil, const Scissor& region)
      : target_(target), depth_(depth), stencil_(stencil), region_(region) {}
  void execute(int tile, detail::ThreadCounters&) override {
    if (!tile_holds(target_.layout(), tile, region_)) return;
    const size_t n = target_.layout().elements_per_tile();
    simd::fill_u32(reinterpret_cast<uint32_t*>(target_.depth_tile(tile)), std::bit_cast<uint32_t>(depth_), n);
    if (stencil_) std::fill_n(target_.stencil_tile(tile), n, *stencil_);
  }

 private:
  DepthStencilTarget& target_;
  float depth_;
  std::optional<uint8_t> stencil_;
  Scissor region_;
};

/// Copies one tile's pixels of the image into every sample of the target.
class LoadImageCommand final : public detail::Command {
 public:
  LoadImageCommand(const Image& image, ColorTarget& target) : image_(image), target_(target) {}
  void execute(int tile, detail::ThreadCounters&) override {
    const SurfaceLayout& L = target_.layout();
    const int x0 = (tile % L.tiles_x) * kTileSize, y0 = (tile / L.tiles_x) * kTileSize;
    const int width = std::min(kTileSize, L.width - x0), height = std::min(kTileSize, L.height - y0);
    uint32_t* texels = target_.tile(tile);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        uint32_t rgba;
        std::memcpy(&rgba, image_.pixel(x0 + x, y0 + y), 4);
        const int offset = pixel_offset_in_tile(x, y);
        for (int s = 0; s < L.samples; ++s) texels[s * kTilePixels + offset] = rgba;
      }
    }
  }

 private:
  const Image& image_;
  ColorTarget& target_;
};

/// Rows of RGBA8 pixels a resolve writes: an Image's, or level 0 of a 2D texture's.
struct ResolvedPixels {
  uint8_t* first;    ///< pixel (0, 0)
  size_t row_bytes;  ///< from one row to the next
  uint8_t* pixel(int x, int y) const { return first + size_t(y) * row_bytes + size_t(x) * 4; }
};

/// Box filter of one tile's samples into the pixels (a plain copy for one sample). With
/// `below_max`, a tile that wrote an alpha below 255 sets it: whether the pixels are opaque, found
/// by the threads as they write them instead of by a pass over them afterwards.
class ResolveCommand final : public detail::Command {
 public:
  ResolveCommand(const ColorTarget& target, ResolvedPixels pixels, ResolveAlpha alpha, const Scissor& region,
                 std::atomic<bool>* below_max)
      : target_(target), pixels_(pixels), opaque_(alpha == ResolveAlpha::opaque ? int32_t(0xff000000u) : 0), region_(region),
        below_max_(below_max) {}
  void execute(int tile, detail::ThreadCounters&) override {
    using simd::Int;
    const SurfaceLayout& L = target_.layout();
    if (!tile_holds(L, tile, region_)) return;
    const int samples = L.samples;
    const int shift = std::countr_zero(static_cast<unsigned>(samples));  // samples is a power of two
    const int x0 = (tile % L.tiles_x) * kTileSize, y0 = (tile / L.tiles_x) * kTileSize;
    const int width = std::min(kTileSize, L.width - x0), height = std::min(kTileSize, L.height - y0);
    const uint32_t* texels = target_.tile(tile);
    const Int low_bytes(0x00ff00ff), half(samples / 2 * 0x00010001), opaque(opaque_);
    // A stamp's pixel: its samples' mean (one sample: the sample itself, which the sums below
    // return to the bit, for less work).
    const auto resolved = [&](const uint32_t* stamp_texels) {
      if (samples == 1) return Int::load_aligned(reinterpret_cast<const int32_t*>(stamp_texels)) | opaque;
      // Channels r, b and g, a summed in 16-bit halves of two accumulators.
      Int rb(0), ga(0);
      for (int s = 0; s < samples; ++s) {
        const Int v = Int::load_aligned(reinterpret_cast<const int32_t*>(stamp_texels + s * kTilePixels));
        rb += v & low_bytes;
        ga += xsimd::bitwise_cast<Int>(xsimd::bitwise_cast<simd::UInt>(v) >> 8) & low_bytes;
      }
      rb = xsimd::bitwise_cast<Int>(xsimd::bitwise_cast<simd::UInt>(rb + half) >> shift) & low_bytes;
      ga = xsimd::bitwise_cast<Int>(xsimd::bitwise_cast<simd::UInt>(ga + half) >> shift) & low_bytes;
      return rb | (ga << 8) | opaque;
    };
    constexpr int kStampsPerRow = kTileSize / simd::kStampWidth;
    Int written_and(-1);  // of every pixel written: alpha 255 in all of them when its top byte is
    uint32_t edge_and = ~0u;
    for (int sy = 0; sy < height; sy += simd::kStampHeight) {
      const bool whole_rows = sy + simd::kStampHeight <= height;
      uint8_t* const top = pixels_.pixel(x0, y0 + sy);
      const uint32_t* stamp = texels + (sy / simd::kStampHeight) * kStampsPerRow * simd::kLanes;
      for (int sx = 0; sx < width; sx += simd::kStampWidth, stamp += simd::kLanes) {
        const Int rows = simd::to_row_major(resolved(stamp));  // the stamp's two rows of pixels
        if (whole_rows && sx + simd::kStampWidth <= width) {
          simd::store_stamp_rows(rows, top + 4 * sx, top + pixels_.row_bytes + 4 * sx);
          written_and &= rows;
          continue;
        }
        alignas(64) uint32_t out[simd::kLanes];
        rows.store_aligned(reinterpret_cast<int32_t*>(out));
        for (int y = sy; y < std::min(sy + simd::kStampHeight, height); ++y) {
          for (int x = sx; x < std::min(sx + simd::kStampWidth, width); ++x) {
            const uint32_t pixel = out[(y - sy) * simd::kStampWidth + (x - sx)];
            std::memcpy(pixels_.pixel(x0 + x, y0 + y), &pixel, 4);
            edge_and &= pixel;
          }
        }
      }
    }
    if (below_max_) {
      alignas(64) uint32_t lanes[simd::kLanes];
      written_and.store_aligned(reinterpret_cast<int32_t*>(lanes));
      for (uint32_t lane : lanes) edge_and &= lane;
      if (edge_and >> 24 != 0xffu) below_max_->store(true, std::memory_order_relaxed);
    }
  }

 private:
  const ColorTarget& target_;
  ResolvedPixels pixels_;
  int32_t opaque_;  ///< or-ed into every pixel: alpha 255, or nothing
  Scissor region_;
  std::atomic<bool>* below_max_;
};

/// Copies one tile of an rgba32f target's planes into row-major pixels.
class FloatResolveCommand final : public detail::Command {
 public:
  FloatResolveCommand(const ColorTarget& target, glm::vec4* pixels) : target_(target), pixels_(pixels) {}
  void execute(int tile, detail::ThreadCounters&) override {
    const SurfaceLayout& L = target_.layout();
    const int x0 = (tile % L.tiles_x) * kTileSize, y0 = (tile / L.tiles_x) * kTileSize;
    const int width = std::min(kTileSize, L.width - x0), height = std::min(kTileSize, L.height - y0);
    const uint32_t* planes = target_.tile(tile);
    for (int y = 0; y < height; ++y) {
      glm::vec4* row = pixels_ + size_t(y0 + y) * size_t(L.width) + x0;
      for (int x = 0; x < width; ++x) {
        const int offset = pixel_offset_in_tile(x, y);
        for (int c = 0; c < 4; ++c) row[x][c] = std::bit_cast<float>(planes[c * kTilePixels + offset]);
      }
    }
  }

 private:
  const ColorTarget& target_;
  glm::vec4* pixels_;
};

}  // namespace

void clear_color(Context& ctx, ColorTarget& target, glm::vec4 color, const Scissor& region) {
  detail::CommandQueue& queue = queue_for(ctx, target.layout());
  // After queue_for, whose flush would forget it.
  ctx.refer(target, region.enable ? Context::Access::use : Context::Access::whole_clear);
  queue.push(std::make_unique<ClearColorCommand>(target, color, region));
}

namespace {
void record_depth_clear(Context& ctx, DepthStencilTarget& target, float depth, std::optional<uint8_t> stencil,
                        const Scissor& region) {
  const float d = std::clamp(std::isnan(depth) ? 0.0f : depth, 0.0f, 1.0f);
  detail::CommandQueue& queue = queue_for(ctx, target.layout());
  ctx.refer(target, stencil && !region.enable ? Context::Access::whole_clear : Context::Access::use);
  queue.push(std::make_unique<ClearDepthStencilCommand>(target, d, stencil, region));
}
}  // namespace

void clear_depth_stencil(Context& ctx, DepthStencilTarget& target, float depth, uint8_t stencil, const Scissor& region) {
  record_depth_clear(ctx, target, depth, stencil, region);
}

void clear_depth(Context& ctx, DepthStencilTarget& target, float depth, const Scissor& region) {
  record_depth_clear(ctx, target, depth, std::nullopt, region);
}

namespace {
/// A whole clear recorded without its command (invalidate()).
template <class Target>
void record_invalidate(Context& ctx, Target& target) {
  queue_for(ctx, target.layout());
  ctx.refer(target, Context::Access::whole_clear);
}
}  // namespace

void invalidate(Context& ctx, ColorTarget& target) { record_invalidate(ctx, target); }
void invalidate(Context& ctx, DepthStencilTarget& target) { record_invalidate(ctx, target); }

void load_image(Context& ctx, const Image& image, ColorTarget& target) {
  if (target.format() != ColorFormat::rgba8) throw std::invalid_argument("load_image: the target is rgba32f, not rgba8");
  if (image.width != target.width() || image.height != target.height()) {
    throw std::invalid_argument("load_image: a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                " image into a " + std::to_string(target.width()) + "x" +
                                std::to_string(target.height()) + " target");
  }
  detail::CommandQueue& queue = queue_for(ctx, target.layout());
  ctx.refer(target, Context::Access::whole_clear);
  queue.push(std::make_unique<LoadImageCommand>(image, target));
}

namespace {
/// Throws std::invalid_argument unless `target` has format `format`; `resolve` names the resolve.
void check_format(const ColorTarget& target, ColorFormat format, const char* resolve) {
  if (target.format() == format) return;
  throw std::invalid_argument(std::string("resolve_into: ") + resolve + " resolves an " +
                              (format == ColorFormat::rgba8 ? "rgba8" : "rgba32f") + " color target, not an " +
                              (target.format() == ColorFormat::rgba8 ? "rgba8" : "rgba32f") + " one");
}

void record_resolve(Context& ctx, const ColorTarget& target, ResolvedPixels pixels, ResolveAlpha alpha, const Scissor& region,
                    std::atomic<bool>* below_max = nullptr) {
  check_format(target, ColorFormat::rgba8, "an image or texture");
  detail::CommandQueue& queue = queue_for(ctx, target.layout());
  ctx.refer(target, Context::Access::resolve);  // runs another context's pending frame on it first
  queue.push(std::make_unique<ResolveCommand>(target, pixels, alpha, region, below_max));
  ctx.flush();
}
}  // namespace

void resolve_into(Context& ctx, const ColorTarget& target, Image& image, ResolveAlpha alpha, const Scissor& region) {
  if (image.width != target.width() || image.height != target.height()) image = Image(target.width(), target.height());
  record_resolve(ctx, target, {image.rgba.data(), size_t(image.width) * 4}, alpha, region);
}

void resolve_into(Context& ctx, const ColorTarget& target, Texture& texture, ResolveAlpha alpha, const Scissor& region) {
  if (texture.kind() != TextureKind::Texture2D || texture.mip_levels() != 1 ||
      (texture.format() != TextureFormat::RGBA8 && texture.format() != TextureFormat::RGBA8_sRGB) ||
      texture.width() != target.width() || texture.height() != target.height()) {
    throw std::invalid_argument("resolve_into: a " + std::to_string(target.width()) + "x" + std::to_string(target.height()) +
                                " target resolves into an RGBA8 2D texture of one level and its size");
  }
  const ResolvedPixels pixels{TextureAccess::level0(texture).data(), size_t(texture.width()) * 4};
  if (!region.enable) {
    // Every pixel written: whether the level is opaque is what the tiles found.
    std::atomic<bool> below_max{false};
    record_resolve(ctx, target, pixels, alpha, region, &below_max);
    TextureAccess::level_written(texture, alpha == ResolveAlpha::opaque || !below_max.load(std::memory_order_relaxed));
    return;
  }
  record_resolve(ctx, target, pixels, alpha, region);
  // The rows the resolve wrote: those of the tiles holding the region (see tile_holds).
  int y0 = 0, y1 = target.height();
  if (region.enable) {
    y0 = std::clamp(region.y0 / kTileSize * kTileSize, 0, y1);
    y1 = std::clamp((std::max(region.y1, region.y0) + kTileSize - 1) / kTileSize * kTileSize, y0, y1);
  }
  TextureAccess::rows_written(texture, y0, y1, alpha == ResolveAlpha::opaque);
}

void resolve_into(Context& ctx, const ColorTarget& target, std::vector<glm::vec4>& pixels) {
  check_format(target, ColorFormat::rgba32f, "a float vector");
  pixels.resize(size_t(target.width()) * size_t(target.height()));
  detail::CommandQueue& queue = queue_for(ctx, target.layout());
  ctx.refer(target, Context::Access::resolve);  // runs another context's pending frame on it first
  queue.push(std::make_unique<FloatResolveCommand>(target, pixels.data()));
  ctx.flush();
}

void discard(Context& ctx, ColorTarget& target) { ctx.discard(target); }
void discard(Context& ctx, DepthStencilTarget& target) { ctx.discard(target); }

Image resolve(Context& ctx, const ColorTarget& target, ResolveAlpha alpha) {
  Image image(target.width(), target.height());
  resolve_into(ctx, target, image, alpha);
  return image;
}

}  // namespace luxel::rasterizer
