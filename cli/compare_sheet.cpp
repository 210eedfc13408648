#include "compare_sheet.hpp"

#include "luxel/frame/image_difference.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace luxel::cli {

namespace {

constexpr int kMargin = 8;
constexpr int kLabelHeight = 22;
constexpr int kFontSize = 14;
constexpr int kBaseline = 16;  ///< of a label, below the top of its strip
constexpr int kSwatch = 16;
constexpr std::array<uint8_t, 4> kGround = {24, 24, 24, 255};

/// Width of `text` drawn from x = 0 (its advance), through the font.
int text_width(const std::string& text) {
  const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(text, kFontSize, kSheetFont);
  if (!box.defined())
    throw std::runtime_error(std::string(kSheetFont) + ": cannot load the font (Debian package fonts-dejavu-core)");
  return box.xend;
}

class Canvas {
 public:
  Canvas(int width, int height) : image_(width, height) {
    for (size_t p = 0; p < image_.rgba.size(); p += 4) std::memcpy(&image_.rgba[p], kGround.data(), 4);
  }

  void fill(int x, int y, int w, int h, std::array<uint8_t, 3> rgb) {
    for (int j = y; j < y + h; ++j)
      for (int i = x; i < x + w; ++i) {
        uint8_t* p = image_.pixel(i, j);
        std::memcpy(p, rgb.data(), 3);
        p[3] = 255;
      }
  }

  /// `source` opaque with its top-left at (x, y).
  void paste(const rasterizer::Image& source, int x, int y) {
    for (int j = 0; j < source.height; ++j)
      for (int i = 0; i < source.width; ++i) {
        uint8_t* p = image_.pixel(x + i, y + j);
        std::memcpy(p, source.pixel(i, j), 3);
        p[3] = 255;
      }
  }

  /// White `text` with its baseline's left end at (x, y), clipped to the box [x, x + w) x [top, top + h).
  void text(const std::string& text, int x, int y, int w, int top, int h) {
    const OIIO::ImageSpec spec(image_.width, image_.height, 4, OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf view(spec, image_.rgba.data());
    const float white[4] = {1, 1, 1, 1};
    const OIIO::ROI clip(x, std::min(x + w, image_.width), top, top + h);
    if (!OIIO::ImageBufAlgo::render_text(view, x, y, text, kFontSize, kSheetFont, white, OIIO::ImageBufAlgo::TextAlignX::Left,
                                         OIIO::ImageBufAlgo::TextAlignY::Baseline, 0, clip, /*nthreads=*/1))
      throw std::runtime_error(std::string(kSheetFont) + ": cannot draw text: " + view.geterror());
  }

  rasterizer::Image take() { return std::move(image_); }

 private:
  rasterizer::Image image_;
};

int legend_width(const Legend& legend) {
  int w = text_width(legend.title) + kMargin;
  for (const auto& [label, colour] : legend.swatches) w += kSwatch + 4 + text_width(label) + kMargin;
  return w;
}

}  // namespace

Legend heat_legend() {
  Legend l{"difference in 8-bit steps:", {}};
  for (size_t i = 0; i < frame::kHeatStops.size(); ++i) {
    const std::string n = std::to_string(frame::kHeatStops[i]);
    l.swatches.emplace_back(i + 1 == frame::kHeatStops.size() ? n + "+" : n, frame::heat_colour(frame::kHeatStops[i]));
  }
  return l;
}

rasterizer::Image compose_sheet(const std::vector<std::vector<SheetCell>>& rows, const std::vector<Legend>& legends) {
  // Column widths and row heights.
  std::vector<int> column_width;
  std::vector<int> row_height;
  for (const auto& row : rows) {
    int height = 0;
    for (size_t c = 0; c < row.size(); ++c) {
      if (column_width.size() <= c) column_width.push_back(0);
      column_width[c] = std::max({column_width[c], row[c].image->width, text_width(row[c].label)});
      height = std::max(height, row[c].image->height);
    }
    row_height.push_back(kLabelHeight + height);
  }
  int width = kMargin, height = kMargin;
  for (int w : column_width) width += w + kMargin;
  for (int h : row_height) height += h + kMargin;
  for (const Legend& legend : legends) {
    width = std::max(width, legend_width(legend) + 2 * kMargin);
    height += kLabelHeight + kMargin;
  }

  Canvas canvas(width, height);
  int y = kMargin;
  for (size_t r = 0; r < rows.size(); ++r) {
    int x = kMargin;
    for (size_t c = 0; c < rows[r].size(); ++c) {
      canvas.text(rows[r][c].label, x, y + kBaseline, column_width[c], y, kLabelHeight);
      canvas.paste(*rows[r][c].image, x, y + kLabelHeight);
      x += column_width[c] + kMargin;
    }
    y += row_height[r] + kMargin;
  }
  for (const Legend& legend : legends) {
    int x = kMargin;
    canvas.text(legend.title, x, y + kBaseline, width - x, y, kLabelHeight);
    x += text_width(legend.title) + kMargin;
    for (const auto& [label, colour] : legend.swatches) {
      canvas.fill(x, y + kBaseline - kSwatch + 3, kSwatch, kSwatch, colour);
      x += kSwatch + 4;
      canvas.text(label, x, y + kBaseline, width - x, y, kLabelHeight);
      x += text_width(label) + kMargin;
    }
    y += kLabelHeight + kMargin;
  }
  return canvas.take();
}

}  // namespace luxel::cli
