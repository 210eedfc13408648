#include "luxel/scenes/image_io.hpp"

#include "one_line.hpp"

#include "luxel/scenes/memory_limit.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace luxel::scenes {

namespace {

/// Closes stderr (fd 2) while it lives: the libraries under OpenImageIO print complaints of their
/// own there. libpng prints "libpng error: ..." for every damaged PNG (OpenImageIO 2.4's error
/// handler records the message and returns, and libpng's default handler then prints it), a second
/// line beside the one error luxel throws, which holds that message already. Process-wide, so
/// counted: the first reader to start closes it, the last to finish opens it again; whatever
/// another thread prints meanwhile is lost (luxel reads images while loading, not while drawing).
class QuietStderr {
 public:
  QuietStderr() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (depth_++ > 0) return;
    std::fflush(stderr);
    saved_ = dup(STDERR_FILENO);
    const int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null >= 0) dup2(null, STDERR_FILENO);
    if (null >= 0) close(null);
  }
  ~QuietStderr() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (--depth_ > 0) return;
    std::fflush(stderr);
    if (saved_ >= 0) {
      dup2(saved_, STDERR_FILENO);
      close(saved_);
    }
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  static inline std::mutex mutex_;
  static inline int depth_ = 0;
  static inline int saved_ = -1;
};

/// OpenImageIO's messages can span lines; ours are one line.
[[noreturn]] void fail(const std::string& name, const std::string& what) {
  const std::string line = one_line(what);
  throw std::runtime_error(name + ": " + (line.empty() ? "unknown OpenImageIO error" : line));
}

bool is_float(OIIO::TypeDesc t) {
  return t.basetype == OIIO::TypeDesc::FLOAT || t.basetype == OIIO::TypeDesc::HALF ||
         t.basetype == OIIO::TypeDesc::DOUBLE;
}

/// 4 channels from n (1 to 4): grey replicated, alpha `one` where the file has none. RGBA rows are
/// returned as they are; the others are expanded by one loop per layout, no choice per pixel.
template <class T>
std::vector<T> expand_to_rgba(std::vector<T> raw, size_t pixels, int n, T one) {
  if (n == 4) return raw;
  std::vector<T> out(pixels * 4);
  T* q = out.data();
  const T* p = raw.data();
  switch (n) {
    case 1:
      for (size_t i = 0; i < pixels; ++i, q += 4) q[0] = q[1] = q[2] = p[i], q[3] = one;
      break;
    case 2:
      for (size_t i = 0; i < pixels; ++i, q += 4, p += 2) q[0] = q[1] = q[2] = p[0], q[3] = p[1];
      break;
    default:
      for (size_t i = 0; i < pixels; ++i, q += 4, p += 3) q[0] = p[0], q[1] = p[1], q[2] = p[2], q[3] = one;
      break;
  }
  return out;
}

/// The first `n` channels of every row, read in bands into `raw`, which grows with what was
/// decoded: a small file whose header claims a large image fails on its first band instead of
/// having the whole image allocated (and zeroed) first. A band is about 256 KB of kept channels
/// (at least a row). The rows are read in the file's own format (TypeDesc::UNKNOWN) and, where
/// that is not `type`, converted here with OpenImageIO's own conversion (convert_pixel_values):
/// its converting read allocates, on every call, a buffer for as many rows as fit in tens of
/// megabytes (64 MB in its current source), whatever the rows asked, which made a narrow, tall
/// image read a band at a time cost seconds under AddressSanitizer. Files with a
/// format per channel (some EXRs) take the converting read. False on a read error.
template <class T>
bool read_rows(OIIO::ImageInput& in, int n, OIIO::TypeDesc type, std::vector<T>& raw) {
  const OIIO::ImageSpec& spec = in.spec();
  const size_t row = static_cast<size_t>(spec.width) * static_cast<size_t>(n);
  const bool uniform = spec.channelformats.empty();
  const bool convert = uniform && spec.format != type;
  const size_t stored_row = convert ? row * spec.format.size() : 0;
  const int band_rows = static_cast<int>(std::clamp<size_t>((size_t{256} << 10) / std::max(row * sizeof(T), stored_row), 1,
                                                            static_cast<size_t>(spec.height)));
  std::vector<std::byte> stored;
  for (int y = spec.y; y < spec.y + spec.height; y += band_rows) {
    const int end = std::min(y + band_rows, spec.y + spec.height);
    const size_t at = raw.size(), values = row * static_cast<size_t>(end - y);
    raw.resize(at + values);
    if (!convert) {
      if (!in.read_scanlines(0, 0, y, end, 0, 0, n, uniform ? OIIO::TypeDesc::UNKNOWN : type, raw.data() + at)) return false;
      continue;
    }
    stored.resize(stored_row * static_cast<size_t>(end - y));
    if (!in.read_scanlines(0, 0, y, end, 0, 0, n, OIIO::TypeDesc::UNKNOWN, stored.data())) return false;
    if (!OIIO::convert_pixel_values(spec.format, stored.data(), type, raw.data() + at, static_cast<int>(values))) {
      in.errorfmt("cannot convert pixels stored as {}", spec.format);
      return false;
    }
  }
  return true;
}

PixelImage read_opened(OIIO::ImageInput& in, const std::string& name, uint64_t memory_limit) {
  const OIIO::ImageSpec& spec = in.spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    fail(name, "the image has no pixels");
  if (spec.width > kMaxImageSide || spec.height > kMaxImageSide)
    fail(name, std::to_string(spec.width) + "x" + std::to_string(spec.height) + " is larger than " +
                   std::to_string(kMaxImageSide) + " on a side");
  // Only the channels kept are read, so a file claiming thousands of channels allocates four.
  const int n = std::min(spec.nchannels, 4);
  const size_t pixels = static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height);
  // The channels as read and the RGBA image made of them are held together for a moment.
  const bool hdr = is_float(spec.format);
  check_memory(name, pixels * uint64_t(n) * (hdr ? 4 : 1) + image_bytes(uint64_t(spec.width), uint64_t(spec.height), hdr),
               "a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + (hdr ? " float" : " 8-bit") + " image",
               memory_limit);
  PixelImage image;
  image.width = spec.width;
  image.height = spec.height;
  if (hdr) {
    std::vector<float> raw;
    if (!read_rows(in, n, OIIO::TypeDesc::FLOAT, raw)) fail(name, in.geterror());
    image.rgba32f = expand_to_rgba(std::move(raw), pixels, n, 1.0f);
  } else {
    std::vector<uint8_t> raw;
    if (!read_rows(in, n, OIIO::TypeDesc::UINT8, raw)) fail(name, in.geterror());
    image.rgba8 = expand_to_rgba(std::move(raw), pixels, n, uint8_t{255});
  }
  return image;
}

/// Straight alpha in and out: without it OIIO's PNG reader premultiplies and its writer divides
/// color by alpha, losing it where alpha is 0.
OIIO::ImageSpec straight_alpha_config() {
  // A file is read by the reader its extension (or, in memory, its signature) names, never by
  // every format OpenImageIO has in turn: a damaged PNG would otherwise also be tried as a camera
  // raw, a DICOM..., each failing its own way, at the cost of milliseconds and megabytes each.
  static const bool once = OIIO::attribute("try_all_readers", 0);
  (void)once;
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  return config;
}

/// The spec of a written image. PNGs are deflated at zlib level 2, not libpng's default 6: a
/// 1280x720 frame then takes a third of the time to write for files a few percent larger
/// (bench/README.md, "Why the code is as it is"), which a sequence of frames pays per frame.
OIIO::ImageSpec output_spec(int width, int height, int channels, OIIO::TypeDesc type) {
  OIIO::ImageSpec spec(width, height, channels, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  spec.attribute("png:compressionLevel", 2);
  return spec;
}

void write_pixels(int width, int height, OIIO::TypeDesc type, const void* pixels, const std::string& path) {
  if (width <= 0 || height <= 0) fail(path, "cannot write an empty image");
  auto out = OIIO::ImageOutput::create(path);
  if (!out) fail(path, "cannot write this file type (" + OIIO::geterror() + ")");
  // Formats without alpha (Radiance .hdr, JPEG) take the rgb of each rgba pixel.
  const int channels = out->supports("alpha") ? 4 : 3;
  if (!out->open(path, output_spec(width, height, channels, type))) fail(path, out->geterror());
  if (!out->write_image(type, pixels, OIIO::stride_t(4 * type.size()))) fail(path, out->geterror());
  if (!out->close()) fail(path, out->geterror());
}

void check_layout(const PixelImage& image, const std::string& name) {
  const size_t texels = static_cast<size_t>(std::max(image.width, 0)) * static_cast<size_t>(std::max(image.height, 0)) * 4;
  if (image.width <= 0 || image.height <= 0) fail(name, "cannot write an empty image");
  if (image.rgba8.empty() == image.rgba32f.empty()) fail(name, "the image must hold either 8-bit or float texels");
  if ((image.is_hdr() ? image.rgba32f.size() : image.rgba8.size()) != texels)
    fail(name, "the image holds the wrong number of texels for its size");
}

}  // namespace

PixelImage read_image(const std::string& path, uint64_t memory_limit) {
  const QuietStderr quiet;
  const OIIO::ImageSpec config = straight_alpha_config();
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) fail(path, OIIO::geterror());
  return read_opened(*in, path, memory_limit);
}

PixelImage read_image(std::span<const uint8_t> bytes, const std::string& name, uint64_t memory_limit) {
  // In memory there is no extension to pick a reader by: tell the formats glTF allows by their
  // signatures.
  static const uint8_t kPng[] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  const char* as = nullptr;
  if (bytes.size() >= 8 && std::equal(kPng, kPng + 8, bytes.begin())) as = "memory.png";
  else if (bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff) as = "memory.jpg";
  if (!as) fail(name, "not a PNG or JPEG image");
  const QuietStderr quiet;
  OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
  // OIIO 2.4 ignores open()'s ioproxy argument when a config is given: pass it in the config.
  OIIO::ImageSpec config = straight_alpha_config();
  OIIO::Filesystem::IOProxy* proxy = &reader;
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  auto in = OIIO::ImageInput::open(as, &config);
  if (!in) fail(name, OIIO::geterror());
  return read_opened(*in, name, memory_limit);
}

void write_image(const PixelImage& image, const std::string& path) {
  check_layout(image, path);
  if (image.is_hdr()) write_pixels(image.width, image.height, OIIO::TypeDesc::FLOAT, image.rgba32f.data(), path);
  else write_pixels(image.width, image.height, OIIO::TypeDesc::UINT8, image.rgba8.data(), path);
}

void write_image(int width, int height, std::span<const uint8_t> rgba8, const std::string& path) {
  if (width > 0 && height > 0 && rgba8.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 4)
    fail(path, "the image holds the wrong number of bytes for its size");
  write_pixels(width, height, OIIO::TypeDesc::UINT8, rgba8.data(), path);
}

std::vector<uint8_t> encode_png(const PixelImage& image, const std::string& name) {
  check_layout(image, name);
  if (image.is_hdr()) fail(name, "a float image cannot be stored as PNG");
  std::vector<uint8_t> bytes;
  OIIO::Filesystem::IOVecOutput writer(bytes);
  auto out = OIIO::ImageOutput::create("memory.png");
  if (!out || !out->set_ioproxy(&writer)) fail(name, OIIO::geterror());
  if (!out->open("memory.png", output_spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8))) fail(name, out->geterror());
  if (!out->write_image(OIIO::TypeDesc::UINT8, image.rgba8.data())) fail(name, out->geterror());
  if (!out->close()) fail(name, out->geterror());
  return bytes;
}

}  // namespace luxel::scenes
