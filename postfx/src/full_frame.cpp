// The frame's one copy for the post passes (full_frame.hpp).

#include "luxel/postfx/full_frame.hpp"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>

namespace luxel::postfx {

namespace {
void fit(std::optional<rasterizer::Texture>& texture, int width, int height) {
  if (!texture || texture->width() != width || texture->height() != height)
    texture = rasterizer::Texture::create_2d(width, height, rasterizer::TextureFormat::RGBA8, 1);
}
}  // namespace

void FullFrameTexture::update(const rasterizer::Image& frame) {
  if (frame.width <= 0 || frame.height <= 0 || frame.rgba.size() != size_t(frame.width) * frame.height * 4)
    throw std::invalid_argument("full-frame copy: the frame's pixels do not match its size");
  fit(texture_, frame.width, frame.height);
  texture_->upload(0, std::span<const uint8_t>(frame.rgba));
}

void FullFrameTexture::resolve(rasterizer::Context& ctx, const rasterizer::ColorTarget& frame, rasterizer::ResolveAlpha alpha) {
  fit(texture_, frame.width(), frame.height());
  rasterizer::resolve_into(ctx, frame, *texture_, alpha);
}

void check_frame_copy(const rasterizer::Texture& frame, const char* pass) {
  if (frame.kind() != rasterizer::TextureKind::Texture2D || frame.mip_levels() != 1 ||
      frame.format() != rasterizer::TextureFormat::RGBA8)
    throw std::invalid_argument(std::string(pass) + ": the frame's copy is not an RGBA8 2D texture of one level");
}

void read_into(const rasterizer::Texture& texture, rasterizer::Image& image) {
  const auto bytes = texture.level_bytes(0);
  if (image.width != texture.width() || image.height != texture.height())
    image = rasterizer::Image(texture.width(), texture.height());
  std::copy(bytes.begin(), bytes.end(), image.rgba.begin());
}

const rasterizer::Texture& FullFrameTexture::texture() const {
  if (!texture_) throw std::logic_error("full-frame copy: read before any frame was copied in");
  return *texture_;
}

}  // namespace luxel::postfx
