#pragma once
// The picture `luxel compare` writes: labelled images in rows (the frames, then the heat maps of
// their differences), with a legend of the heat map's colours underneath.
//
// Layout, in pixels: an 8-pixel margin and gap; above each image a 22-pixel strip holding its
// label; every column as wide as its widest image or label; images copied opaque (alpha 255) onto
// a dark grey ground, top-left aligned in their cell. The legend is one strip of swatches,
// frame::heat_colour at each of frame::kHeatStops, each followed by its number of 8-bit steps.
//
// Text is DejaVu Sans (Debian package fonts-dejavu-core) drawn by OpenImageIO's render_text
// (FreeType) on one thread: the same bytes on every run for the same packages.

#include "luxel/rasterizer/image.hpp"

#include <string>
#include <vector>

namespace luxel::cli {

/// The font the labels are drawn with.
inline constexpr const char* kSheetFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

struct SheetCell {
  std::string label;
  const rasterizer::Image* image;  ///< not owned; must outlive compose_sheet
};

/// The sheet: `rows` top to bottom, cells left to right, then the legend. Throws
/// std::runtime_error "FONT: cannot load the font (...)" when kSheetFont cannot be read.
rasterizer::Image compose_sheet(const std::vector<std::vector<SheetCell>>& rows);

}  // namespace luxel::cli
