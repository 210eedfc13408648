#include "report/frame_error.hpp"

namespace luxel::cli {

std::vector<ReportColumn> frame_error_columns() {
  return {{"max_steps", "max steps", ColumnKind::error, "%.0f"},
          {"mean_steps", "mean steps", ColumnKind::error, "%.4f"},
          {"psnr_db", "PSNR dB", ColumnKind::error, "%.2f"},
          {"differing_share", "differ %", ColumnKind::error, "%.2f", 100.0}};
}

std::vector<double> frame_error_values(const rasterizer::Image& a, const rasterizer::Image& reference) {
  const frame::ImageDifference d = frame::image_difference(a, reference);
  return {double(d.max_error), d.mean_error, d.psnr_db, d.differing_share()};
}

}  // namespace luxel::cli
