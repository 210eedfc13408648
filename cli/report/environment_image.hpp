#pragma once
// An environment image (a light probe) as radiance samples, one per pixel with the pixel's solid
// angle, so that sphere_quadrature.hpp's irradiance and the fits (project_sh9, fit_ambient_cube)
// integrate every pixel's radiance: no resampling, no small bright source missed between grid
// cells.
//
// Frame (every probe alike, R&H 2001's for the angular map, ramamoorthi2001.hpp): +y up, +z the direction seen at the image's centre, +x toward the image's right.
//
// Angular map ("light probe", square): pixel (i, j) of a w x w image at its centre,
// u = (j + ½ − w/2)/(w/2), v = (w/2 − i − ½)/(w/2), r = √(u² + v²) < 1 (pixels beyond the circle
// are not the sphere), θ = π r from +z, direction (sin θ · u/r, sin θ · v/r, cos θ), solid angle
// (2π/w)² sin θ / θ (the map's Jacobian: the paper's prefilter program's weight).
//
// Latitude-longitude (2:1): row i of h at polar angle φ = π (i + ½)/h from +y, column j of w at
// azimuth α = 2π ((j + ½)/w − ½) from +z toward +x, direction (sin φ sin α, cos φ, sin φ cos α),
// solid angle (2π/w)(cos(π i/h) − cos(π (i+1)/h)): the row band's exact area, so the pixels sum
// to 4π exactly.

#include "luxel/scenes/scene.hpp"
#include "luxel/shading/source/sphere_quadrature.hpp"

#include <string>

namespace luxel::cli {

enum class EnvironmentMapping { angular, latlong };

/// The mapping an image's shape says: square -> angular, 2:1 -> lat-long. Throws
/// std::runtime_error "NAME: WxH is neither ..." for any other shape.
EnvironmentMapping mapping_of(const scenes::PixelImage& image, const std::string& name);

/// "angular map" or "lat-long".
const char* mapping_name(EnvironmentMapping mapping);

/// The image's pixels as radiance samples (rgb of a float image; alpha ignored). Throws
/// std::runtime_error "NAME: ..." for an 8-bit image (a probe holds radiance, not display values).
shading::source::SampledRadiance environment_samples(const scenes::PixelImage& image, EnvironmentMapping mapping,
                                                     const std::string& name);

}  // namespace luxel::cli
