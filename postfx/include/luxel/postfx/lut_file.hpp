#pragma once
// LUT files in and out. Reading goes through OpenColorIO (a FileTransform): every format it reads
// (.cube Iridas and Resolve, 1D, 3D, shaper + 3D, DOMAIN_MIN/MAX; .3dl; .csp; .spi1d, .spi3d;
// .clf, .ctf...), evaluated by OpenColorIO's CPU processor in float at the file's own resolution
// with the interpolation OpenColorIO's own tools ask for (ociochecklut, ocioconvert --lut,
// ociobakelut --lut: INTERP_BEST): tetrahedral for 3D LUTs, linear for 1D LUTs, and a CLF/CTF
// file's own where it names one. (The FileTransform's INTERP_DEFAULT would be trilinear for every
// 3D LUT in OpenColorIO 2.1.) The engine samples it on its 32^3 lattice (lut.hpp);
// `luxel grade --exact` applies it as read.
//
// Bad files throw std::runtime_error with one line "PATH: problem": a missing file, a file no
// reader takes (the first reader's complaint, condensed from OpenColorIO's several lines), a
// .cube whose LUT_3D_SIZE / LUT_1D_SIZE is below 2 or above OpenColorIO's own limits (checked on
// the header before OpenColorIO reads it: its .cube reader reserves size^3 entries first and
// checks the size only after, unlike its readers of the other formats), a LUT of fewer than two
// points per axis in any format, a NaN or infinite LUT value, a transform giving a NaN or infinite
// color for any of the 9^3 colors of a lattice over [0, 1] (a file's matrix, range, CDL or domain
// holding NaN, infinity or a number beyond float).
//
// OpenColorIO caches what it read by path; reading clears its caches first, so a file rewritten
// since (a test's, an artist's) is read anew.

#include "luxel/postfx/color_transform.hpp"
#include "luxel/postfx/lut.hpp"

#include <string>

namespace luxel::postfx {

/// OpenColorIO's limits (its Lut3DOpData and Lut1DOpData): 3D LUT points per axis, 1D LUT entries.
inline constexpr int kMaxFileLut3dSize = 129;
inline constexpr int kMaxFileLut1dSize = 1024 * 1024;

/// The file's transform; its description names the LUTs in it ("3D LUT 33^3, tetrahedral").
ColorTransform read_lut_file(const std::string& path);

/// Writes the LUT as a 32^3 .cube (Iridas/Resolve 3D, red fastest, entries over 255).
/// Throws std::runtime_error "PATH: cannot write it" when the file cannot be written.
void write_cube(const Lut& lut, const std::string& path, const std::string& title);

}  // namespace luxel::postfx
