#pragma once
// The error columns every frame section reports for a frame against its reference, as `luxel
// compare` reports a pair (frame/image_difference.hpp: idiff's numbers, alpha counted): the
// largest and mean channel difference in 8-bit steps, the PSNR (+infinity for identical frames:
// "inf" in the text, null in the JSON) and the share of pixels that differ.

#include "report/report.hpp"

#include "luxel/frame/image_difference.hpp"

#include <string>
#include <vector>

namespace luxel::cli {

/// The four error columns, in the order frame_error_values gives them.
std::vector<ReportColumn> frame_error_columns();

/// `a` against `reference` (the same size): max steps, mean steps, PSNR dB, differing share.
std::vector<double> frame_error_values(const rasterizer::Image& a, const rasterizer::Image& reference);

/// What `row`'s error columns say, as the table prints them: "the same bytes (0 pixels differ)",
/// or "D % of the pixels differ, by up to N steps (mean M steps)".
std::string frame_difference_text(const SectionResult& r, const ReportRow& row);

/// A finding per row but the last, where the frame sections that draw their reference again put
/// it: "V against REF: <frame_difference_text>".
std::vector<std::string> findings_against_last_row(const SectionResult& r);

}  // namespace luxel::cli
