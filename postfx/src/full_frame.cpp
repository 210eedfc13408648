// The frame's one copy for the post passes (full_frame.hpp).

#include "luxel/postfx/full_frame.hpp"

#include <span>
#include <stdexcept>

namespace luxel::postfx {

void FullFrameTexture::update(const rasterizer::Image& frame) {
  if (frame.width <= 0 || frame.height <= 0 || frame.rgba.size() != size_t(frame.width) * frame.height * 4)
    throw std::invalid_argument("full-frame copy: the frame's pixels do not match its size");
  if (!texture_ || texture_->width() != frame.width || texture_->height() != frame.height)
    texture_ = rasterizer::Texture::create_2d(frame.width, frame.height, rasterizer::TextureFormat::RGBA8, 1);
  texture_->upload(0, std::span<const uint8_t>(frame.rgba));
}

const rasterizer::Texture& FullFrameTexture::texture() const {
  if (!texture_) throw std::logic_error("full-frame copy: read before any frame was copied in");
  return *texture_;
}

}  // namespace luxel::postfx
