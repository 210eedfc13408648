#include "line_plot.hpp"

#include "compare_sheet.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace luxel::cli {
namespace {

constexpr int kFontSize = 13;
constexpr int kLeft = 70, kRight = 20, kTop = 36, kBottom = 52;  ///< margins around the plot area
constexpr int kLabelGap = 14;    ///< from a marker to its label
constexpr int kLineHeight = 14;  ///< between labels stacked in a column

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

/// Ticks on a log axis covering [lo, hi] (exponents of ten): the decades, and 2 and 5 times them
/// when fewer than two decades fall inside.
std::vector<double> log_ticks(double lo, double hi) {
  std::vector<double> ticks;
  for (double k = std::ceil(lo); k <= hi; k += 1.0) ticks.push_back(k);
  if (ticks.size() >= 2) return ticks;
  ticks.clear();
  for (double k = std::floor(lo); k <= hi; k += 1.0)
    for (double m : {1.0, 2.0, 5.0})
      if (const double t = k + std::log10(m); t >= lo && t <= hi) ticks.push_back(t);
  return ticks;
}

int text_width(const std::string& s) {
  const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(s, kFontSize, kSheetFont);
  return box.defined() ? box.xend : 0;
}

/// A point's label: its point's pixel, the baseline it is written at, its text and color.
struct PlacedLabel {
  int cx, cy, baseline;
  std::string text;
  std::array<float, 4> color;
};

/// Labels of points in one column (the same pixel x) would overprint: from the top down, each is
/// moved down until it is a line below the one above it.
void spread_labels(std::vector<PlacedLabel>& labels) {
  std::stable_sort(labels.begin(), labels.end(), [](const PlacedLabel& a, const PlacedLabel& b) {
    return a.cx != b.cx ? a.cx < b.cx : a.cy < b.cy;
  });
  for (size_t i = 1; i < labels.size(); ++i)
    if (labels[i].cx == labels[i - 1].cx) labels[i].baseline = std::max(labels[i].baseline, labels[i - 1].baseline + kLineHeight);
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
  // On a log axis the plot works in log10(y) throughout: range, ticks, placement.
  const auto plotted_y = [&](double y) {
    return plot.log_y ? (y > 0.0 ? std::log10(y) : std::numeric_limits<double>::quiet_NaN()) : y;
  };
  Range xr, yr;
  int label_width = 0;
  for (const PlotSeries& s : plot.series) {
    if (!s.labels.empty() && s.labels.size() != s.points.size())
      throw std::invalid_argument("plot '" + plot.title + "': series '" + s.name + "' has " + std::to_string(s.labels.size()) +
                                  " labels for " + std::to_string(s.points.size()) + " points");
    for (const auto& [x, y] : s.points)
      if (std::isfinite(x) && std::isfinite(plotted_y(y))) xr.add(x), yr.add(plotted_y(y));
    for (const std::string& l : s.labels) label_width = std::max(label_width, text_width(l));
  }
  if (!(xr.lo <= xr.hi)) throw std::invalid_argument("plot '" + plot.title + "' has no finite point");
  xr.pad(), yr.pad();

  OIIO::ImageBuf image(OIIO::ImageSpec(plot.width, plot.height, 4, OIIO::TypeDesc::UINT8));
  const float ground[4] = {24 / 255.0f, 24 / 255.0f, 24 / 255.0f, 1.0f}, axis[4] = {0.6f, 0.6f, 0.6f, 1.0f},
              grid[4] = {0.22f, 0.22f, 0.22f, 1.0f}, white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  OIIO::ImageBufAlgo::fill(image, ground);
  // Labels beside the rightmost points need room: the plot area ends their width earlier.
  const int x0 = kLeft, x1 = plot.width - kRight - (label_width > 0 ? label_width + kLabelGap : 0), y0 = kTop,
            y1 = plot.height - kBottom;
  if (x1 - x0 < 50) throw std::invalid_argument("plot '" + plot.title + "': its labels leave no room for the plot");
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
  const auto marker = [&](int cx, int cy, const float* color) {
    OIIO::ImageBufAlgo::fill(image, {color, 4}, OIIO::ROI(cx - 3, cx + 4, cy - 3, cy + 4), /*nthreads=*/1);
  };

  for (double t : nice_ticks(xr.lo, xr.hi)) {
    line(px(t), y0, px(t), y1, grid);
    text(tick_label(t), px(t), y1 + 16, OIIO::ImageBufAlgo::TextAlignX::Center, axis);
  }
  for (double t : plot.log_y ? log_ticks(yr.lo, yr.hi) : nice_ticks(yr.lo, yr.hi)) {
    line(x0, py(t), x1, py(t), grid);
    text(tick_label(plot.log_y ? std::pow(10.0, t) : t), x0 - 6, py(t) + 4, OIIO::ImageBufAlgo::TextAlignX::Right, axis);
  }
  line(x0, y1, x1, y1, axis);
  line(x0, y0, x0, y1, axis);
  text(plot.title, plot.width / 2, 22, OIIO::ImageBufAlgo::TextAlignX::Center, white);
  text(plot.x_label, (x0 + x1) / 2, plot.height - 12, OIIO::ImageBufAlgo::TextAlignX::Center, axis);
  text(plot.y_label, 8, y0 - 10, OIIO::ImageBufAlgo::TextAlignX::Left, axis);

  // The series; labels are placed after all markers are known.
  std::vector<PlacedLabel> labels;
  std::vector<std::pair<int, int>> drawn;  // every point's pixel, for the legend to avoid
  for (const PlotSeries& s : plot.series) {
    const float color[4] = {s.rgb[0] / 255.0f, s.rgb[1] / 255.0f, s.rgb[2] / 255.0f, 1.0f};
    bool have = false;
    int last_x = 0, last_y = 0;
    for (size_t i = 0; i < s.points.size(); ++i) {
      const double x = s.points[i].first, y = plotted_y(s.points[i].second);
      if (!(std::isfinite(x) && std::isfinite(y))) {
        have = false;
        continue;
      }
      const int cx = px(x), cy = py(y);
      if (s.style == PlotStyle::markers) marker(cx, cy, color);
      else if (have) line(last_x, last_y, cx, cy, color);
      else line(cx, cy, cx, cy, color);
      if (!s.labels.empty() && !s.labels[i].empty()) labels.push_back({cx, cy, cy + 4, s.labels[i], {color[0], color[1], color[2], 1.0f}});
      drawn.emplace_back(cx, cy);
      have = true, last_x = cx, last_y = cy;
    }
  }
  spread_labels(labels);
  for (const PlacedLabel& l : labels) {
    if (l.baseline != l.cy + 4) line(l.cx + 4, l.cy, l.cx + 8, l.baseline - 4, axis);  // moved: a tick to its point
    text(l.text, l.cx + 10, l.baseline, OIIO::ImageBufAlgo::TextAlignX::Left, l.color.data());
    drawn.emplace_back(l.cx + 10, l.baseline), drawn.emplace_back(l.cx + 10 + text_width(l.text), l.baseline);
  }

  // The legend, as wide as its longest name, in the corner of the plot area with the fewest
  // points and labels under it (top right first), on the ground color.
  int legend_width = 0;
  for (const PlotSeries& s : plot.series) legend_width = std::max(legend_width, text_width(s.name));
  legend_width += 30 + 8;
  const int legend_height = 18 * int(plot.series.size()) + 8;
  const std::array<std::pair<int, int>, 4> corners = {{{x1 - 8 - legend_width, y0 + 4},
                                                       {x0 + 8, y0 + 4},
                                                       {x1 - 8 - legend_width, y1 - 4 - legend_height},
                                                       {x0 + 8, y1 - 4 - legend_height}}};
  size_t best = 0, best_count = drawn.size() + 1;
  for (size_t c = 0; c < corners.size(); ++c) {
    const int lx = corners[c].first, ly = corners[c].second;  // not a structured binding: Clang 14 cannot capture one
    const size_t count = size_t(std::count_if(drawn.begin(), drawn.end(), [&](const std::pair<int, int>& p) {
      return p.first >= lx - 6 && p.first <= lx + legend_width + 6 && p.second >= ly - 6 && p.second <= ly + legend_height + 6;
    }));
    if (count < best_count) best = c, best_count = count;
  }
  const int legend_x = corners[best].first;
  int legend_y = corners[best].second + 16;
  if (best_count > 0)
    OIIO::ImageBufAlgo::fill(image, {ground, 4},
                             OIIO::ROI(legend_x - 4, legend_x + legend_width, legend_y - 16, legend_y - 16 + legend_height),
                             /*nthreads=*/1);
  for (const PlotSeries& s : plot.series) {
    const float color[4] = {s.rgb[0] / 255.0f, s.rgb[1] / 255.0f, s.rgb[2] / 255.0f, 1.0f};
    if (s.style == PlotStyle::markers) marker(legend_x + 12, legend_y - 4, color);
    else line(legend_x, legend_y - 4, legend_x + 24, legend_y - 4, color);
    text(s.name, legend_x + 30, legend_y, OIIO::ImageBufAlgo::TextAlignX::Left, white);
    legend_y += 18;
  }

  rasterizer::Image out(plot.width, plot.height);
  image.get_pixels(OIIO::ROI(0, plot.width, 0, plot.height, 0, 1, 0, 4), OIIO::TypeDesc::UINT8, out.rgba.data());
  return out;
}

}  // namespace luxel::cli
