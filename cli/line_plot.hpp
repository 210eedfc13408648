#pragma once
// A line plot as an image: what `luxel render --sequence` draws of the exposure over time, and
// the scatter plot `luxel report speed-error` draws of error against cost. Series of (x, y) points
// joined by straight lines or drawn as labeled markers, over axes with "nice" ticks (1, 2 or 5 x a
// power of ten; decades on a log y axis), a title, axis labels and a legend, in DejaVu Sans
// (cli/compare_sheet.hpp's font) on a dark ground; the same bytes on every run.

#include "luxel/rasterizer/image.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace luxel::cli {

enum class PlotStyle { lines, markers };

struct PlotSeries {
  std::string name;
  std::array<uint8_t, 3> rgb{255, 255, 255};
  std::vector<std::pair<double, double>> points;  ///< non-finite points are left out
  PlotStyle style = PlotStyle::lines;
  std::vector<std::string> labels;  ///< empty, or one per point, written beside its marker (none for "")
};

struct LinePlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  int width = 900, height = 500;
  bool log_y = false;  ///< y on a log scale; points with y <= 0 are left out
};

/// The plot. Throws std::invalid_argument for a size below 200 x 150, without a finite point, or
/// with labels that are not one per point; std::runtime_error when the font cannot be read.
rasterizer::Image draw_line_plot(const LinePlot& plot);

}  // namespace luxel::cli
