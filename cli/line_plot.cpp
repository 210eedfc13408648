#include "line_plot.hpp"

#include "compare_sheet.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace luxel::cli {
namespace {

constexpr int kFontSize = 13;
constexpr int kLeft = 70, kRight = 20, kTop = 36, kBottom = 52;  ///< margins around the plot area

/// Ticks covering [lo, hi]: multiples of a step of 1, 2 or 5 x 10^k, about five of them.
std::vector<double> nice_ticks(double lo, double hi) {
  const double raw = (hi - lo) / 5.0;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * power;
    if (raw <= step) break;
  }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step) ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  return ticks;
}

std::string tick_label(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
  /// Padded by 5 % each way (a flat range by +-0.5 or 5 % of its value).
  void pad() {
    const double span = hi > lo ? hi - lo : std::max(std::abs(lo) * 0.1, 1.0);
    lo -= 0.05 * span, hi += 0.05 * span;
  }
};

}  // namespace

rasterizer::Image draw_line_plot(const LinePlot& plot) {
  if (plot.width < 200 || plot.height < 150)
    throw std::invalid_argument("plot size " + std::to_string(plot.width) + "x" + std::to_string(plot.height) + " is below 200x150");
  Range xr, yr;
  for (const PlotSeries& s : plot.series)
    for (const auto& [x, y] : s.points)
      if (std::isfinite(x) && std::isfinite(y)) xr.add(x), yr.add(y);
  if (!(xr.lo <= xr.hi)) throw std::invalid_argument("plot '" + plot.title + "' has no finite point");
  xr.pad(), yr.pad();

  OIIO::ImageBuf image(OIIO::ImageSpec(plot.width, plot.height, 4, OIIO::TypeDesc::UINT8));
  const float ground[4] = {24 / 255.0f, 24 / 255.0f, 24 / 255.0f, 1.0f}, axis[4] = {0.6f, 0.6f, 0.6f, 1.0f},
              grid[4] = {0.22f, 0.22f, 0.22f, 1.0f}, white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  OIIO::ImageBufAlgo::fill(image, ground);
  const int x0 = kLeft, x1 = plot.width - kRight, y0 = kTop, y1 = plot.height - kBottom;
  const auto px = [&](double x) { return int(std::lround(x0 + (x - xr.lo) / (xr.hi - xr.lo) * (x1 - x0))); };
  const auto py = [&](double y) { return int(std::lround(y1 - (y - yr.lo) / (yr.hi - yr.lo) * (y1 - y0))); };
  const auto text = [&](const std::string& s, int x, int y, OIIO::ImageBufAlgo::TextAlignX align, const float* color) {
    if (!OIIO::ImageBufAlgo::render_text(image, x, y, s, kFontSize, kSheetFont, {color, 4}, align,
                                         OIIO::ImageBufAlgo::TextAlignY::Baseline, 0, {}, /*nthreads=*/1))
      throw std::runtime_error(std::string(kSheetFont) + ": cannot draw text (Debian package fonts-dejavu-core): " + image.geterror());
  };
  const auto line = [&](int ax, int ay, int bx, int by, const float* color) {
    OIIO::ImageBufAlgo::render_line(image, ax, ay, bx, by, {color, 4}, false, {}, /*nthreads=*/1);
  };

  for (double t : nice_ticks(xr.lo, xr.hi)) {
    line(px(t), y0, px(t), y1, grid);
    text(tick_label(t), px(t), y1 + 16, OIIO::ImageBufAlgo::TextAlignX::Center, axis);
  }
  for (double t : nice_ticks(yr.lo, yr.hi)) {
    line(x0, py(t), x1, py(t), grid);
    text(tick_label(t), x0 - 6, py(t) + 4, OIIO::ImageBufAlgo::TextAlignX::Right, axis);
  }
  line(x0, y1, x1, y1, axis);
  line(x0, y0, x0, y1, axis);
  text(plot.title, plot.width / 2, 22, OIIO::ImageBufAlgo::TextAlignX::Center, white);
  text(plot.x_label, (x0 + x1) / 2, plot.height - 12, OIIO::ImageBufAlgo::TextAlignX::Center, axis);
  text(plot.y_label, 8, y0 - 10, OIIO::ImageBufAlgo::TextAlignX::Left, axis);

  // The legend, top right, as wide as its longest name.
  int legend_width = 0;
  for (const PlotSeries& s : plot.series) {
    const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(s.name, kFontSize, kSheetFont);
    legend_width = std::max(legend_width, box.defined() ? box.xend : 0);
  }
  const int legend_x = x1 - 8 - legend_width - 30;
  int legend_y = y0 + 16;
  for (const PlotSeries& s : plot.series) {
    const float color[4] = {s.rgb[0] / 255.0f, s.rgb[1] / 255.0f, s.rgb[2] / 255.0f, 1.0f};
    bool have = false;
    int last_x = 0, last_y = 0;
    for (const auto& [x, y] : s.points) {
      if (!(std::isfinite(x) && std::isfinite(y))) {
        have = false;
        continue;
      }
      const int cx = px(x), cy = py(y);
      if (have) line(last_x, last_y, cx, cy, color);
      else line(cx, cy, cx, cy, color);
      have = true, last_x = cx, last_y = cy;
    }
    line(legend_x, legend_y - 4, legend_x + 24, legend_y - 4, color);
    text(s.name, legend_x + 30, legend_y, OIIO::ImageBufAlgo::TextAlignX::Left, white);
    legend_y += 18;
  }

  rasterizer::Image out(plot.width, plot.height);
  image.get_pixels(OIIO::ROI(0, plot.width, 0, plot.height, 0, 1, 0, 4), OIIO::TypeDesc::UINT8, out.rgba.data());
  return out;
}

}  // namespace luxel::cli
