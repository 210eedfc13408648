#include "report/frame_error.hpp"

#include "report/findings.hpp"

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

std::string frame_difference_text(const SectionResult& r, const ReportRow& row) {
  const double share = value_of(r, row, "differing_share"), max = value_of(r, row, "max_steps");
  if (share == 0 && max == 0) return "the same bytes (0 pixels differ)";
  return text_of(r, "differing_share", share) + " % of the pixels differ, by up to " +
         counted(text_of(r, "max_steps", max), "step", "steps") + " (mean " + text_of(r, "mean_steps", value_of(r, row, "mean_steps")) +
         " steps)";
}

std::vector<std::string> findings_against_last_row(const SectionResult& r) {
  std::vector<std::string> findings;
  for (size_t i = 0; i + 1 < r.rows.size(); ++i)
    findings.push_back(r.rows[i].variant + " against " + r.rows.back().variant + ": " + frame_difference_text(r, r.rows[i]));
  return findings;
}

}  // namespace luxel::cli
