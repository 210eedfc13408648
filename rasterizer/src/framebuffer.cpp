#include "luxel/rasterizer/framebuffer.hpp"

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/detail/command_queue.hpp"
#include "luxel/rasterizer/msaa.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>

namespace luxel::rasterizer {

namespace detail {
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

ColorTarget::ColorTarget(int width, int height, int samples)
    : layout_(width, height, samples), texels_(layout_.element_count()) {
  std::fill_n(texels_.data(), texels_.size(), 0u);
}

DepthStencilTarget::DepthStencilTarget(int width, int height, int samples)
    : layout_(width, height, samples), depth_(layout_.element_count()), stencil_(layout_.element_count()) {
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

glm::vec4 unpack_rgba8(uint32_t rgba) {
  return glm::vec4(rgba & 255, (rgba >> 8) & 255, (rgba >> 16) & 255, rgba >> 24) / 255.0f;
}

namespace {

/// Makes the pending frame use `layout`, flushing a frame of another tiling first.
detail::CommandQueue& queue_for(Context& ctx, const SurfaceLayout& layout) {
  if (!ctx.queue().accepts(layout)) ctx.flush();
  ctx.queue().set_layout(layout);
  return ctx.queue();
}

class ClearColorCommand final : public detail::Command {
 public:
  ClearColorCommand(ColorTarget& target, uint32_t value) : target_(target), value_(value) {}
  void execute(int tile, detail::TileCounters&) override {
    std::fill_n(target_.tile(tile), target_.layout().elements_per_tile(), value_);
  }

 private:
  ColorTarget& target_;
  uint32_t value_;
};

class ClearDepthStencilCommand final : public detail::Command {
 public:
  ClearDepthStencilCommand(DepthStencilTarget& target, float depth, uint8_t stencil)
      : target_(target), depth_(depth), stencil_(stencil) {}
  void execute(int tile, detail::TileCounters&) override {
    const size_t n = target_.layout().elements_per_tile();
    std::fill_n(target_.depth_tile(tile), n, depth_);
    std::fill_n(target_.stencil_tile(tile), n, stencil_);
  }

 private:
  DepthStencilTarget& target_;
  float depth_;
  uint8_t stencil_;
};

/// Box filter of one tile's samples into the image (a plain copy for one sample).
class ResolveCommand final : public detail::Command {
 public:
  ResolveCommand(const ColorTarget& target, Image& image) : target_(target), image_(image) {}
  void execute(int tile, detail::TileCounters&) override {
    const SurfaceLayout& L = target_.layout();
    const int samples = L.samples;
    const int x0 = (tile % L.tiles_x) * kTileSize, y0 = (tile / L.tiles_x) * kTileSize;
    const uint32_t* texels = target_.tile(tile);
    for (int y = y0; y < std::min(L.height, y0 + kTileSize); ++y) {
      for (int x = x0; x < std::min(L.width, x0 + kTileSize); ++x) {
        const int offset = pixel_offset_in_tile(x - x0, y - y0);
        uint32_t sum[4] = {0, 0, 0, 0};
        for (int s = 0; s < samples; ++s) {
          const uint32_t v = texels[s * kTilePixels + offset];
          for (int c = 0; c < 4; ++c) sum[c] += (v >> (8 * c)) & 255;
        }
        uint8_t* out = image_.pixel(x, y);
        for (int c = 0; c < 4; ++c) out[c] = static_cast<uint8_t>((sum[c] + samples / 2) / samples);
      }
    }
  }

 private:
  const ColorTarget& target_;
  Image& image_;
};

}  // namespace

void clear_color(Context& ctx, ColorTarget& target, glm::vec4 color) {
  queue_for(ctx, target.layout()).push(std::make_unique<ClearColorCommand>(target, pack_rgba8(color)));
}

void clear_depth_stencil(Context& ctx, DepthStencilTarget& target, float depth, uint8_t stencil) {
  const float d = std::clamp(std::isnan(depth) ? 0.0f : depth, 0.0f, 1.0f);
  queue_for(ctx, target.layout()).push(std::make_unique<ClearDepthStencilCommand>(target, d, stencil));
}

void resolve_into(Context& ctx, const ColorTarget& target, Image& image) {
  if (image.width != target.width() || image.height != target.height()) image = Image(target.width(), target.height());
  queue_for(ctx, target.layout()).push(std::make_unique<ResolveCommand>(target, image));
  ctx.flush();
}

Image resolve(Context& ctx, const ColorTarget& target) {
  Image image(target.width(), target.height());
  resolve_into(ctx, target, image);
  return image;
}

}  // namespace luxel::rasterizer
