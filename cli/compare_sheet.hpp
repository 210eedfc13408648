#pragma once
// The picture `luxel compare` writes: labelled images in rows (the frames, the heat maps of their
// differences, with --explain the causes' maps), with the legends of their colours underneath.
//
// Layout, in pixels: an 8-pixel margin and gap; above each image a 22-pixel strip holding its
// label; every column as wide as its widest image or label; images copied opaque (alpha 255) onto
// a dark grey ground, top-left aligned in their cell. Each legend is one strip: its title, then
// swatches each followed by its label.
//
// Text is DejaVu Sans (Debian package fonts-dejavu-core) drawn by OpenImageIO's render_text
// (FreeType) on one thread: the same bytes on every run for the same packages.

#include "luxel/rasterizer/image.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace luxel::cli {

/// The font the labels are drawn with.
inline constexpr const char* kSheetFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

struct SheetCell {
  std::string label;
  const rasterizer::Image* image;  ///< not owned; must outlive compose_sheet
};

struct Legend {
  std::string title;
  std::vector<std::pair<std::string, std::array<uint8_t, 3>>> swatches;  ///< label, colour
};

/// The heat map's legend: frame::heat_colour at each of frame::kHeatStops, each with its number
/// of 8-bit steps.
Legend heat_legend();

/// The sheet: `rows` top to bottom, cells left to right, then the legends. Throws
/// std::runtime_error "FONT: cannot load the font (...)" when kSheetFont cannot be read.
rasterizer::Image compose_sheet(const std::vector<std::vector<SheetCell>>& rows, const std::vector<Legend>& legends);

}  // namespace luxel::cli
