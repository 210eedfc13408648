// LUT files through OpenColorIO, and .cube export (lut_file.hpp).

#include "luxel/postfx/lut_file.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace luxel::postfx {

namespace OCIO = OCIO_NAMESPACE;

namespace {

constexpr OCIO::Interpolation kFileInterpolation = OCIO::INTERP_BEST;

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw std::runtime_error(path + ": " + problem);
}

/// OpenColorIO's message on one printable line: the first reader's complaint without the
/// boilerplate around it, the path (which the caller puts first) left out where it is quoted and
/// shortened to the name given elsewhere, and the bytes of a binary file's "line" as '?'.
std::string condensed(std::string what, const std::string& absolute, const std::string& path) {
  const std::string marker = "failed with: ";
  if (const size_t at = what.find(marker); at != std::string::npos) {
    what = what.substr(at + marker.size());
    if (const size_t next = what.find("    '"); next != std::string::npos) what.resize(next);
  }
  for (const std::string& quoted : {" (" + absolute + ")", "'" + absolute + "'"}) {
    for (size_t at; (at = what.find(quoted)) != std::string::npos;) what.erase(at, quoted.size());
  }
  // On from past each replacement: `path` may hold `absolute` (it is absolute when given so).
  for (size_t at = what.find(absolute); at != std::string::npos; at = what.find(absolute, at + path.size()))
    what.replace(at, absolute.size(), path);
  std::string line;
  for (char c : what) {
    const unsigned char u = static_cast<unsigned char>(c);
    const bool space = std::isspace(u);
    if (space && (line.empty() || line.back() == ' ')) continue;
    line += space ? ' ' : (u < 0x20 || u >= 0x7f) ? '?' : c;
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line;
}

/// A .cube's declared sizes, from its keyword lines before the first line of numbers: refused
/// here when out of range, before OpenColorIO reserves memory for them. Keywords in any case, as
/// OpenColorIO's reader takes them (`LuT_3D_SIZE 20880` made it reserve 25 GB).
void check_cube_header(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  for (int n = 0; n < 10000 && std::getline(in, line); ++n) {
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword)) continue;
    const char first = keyword[0];
    if (std::isdigit(static_cast<unsigned char>(first)) || first == '-' || first == '+' || first == '.') return;
    std::string upper = keyword;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const bool is3d = upper == "LUT_3D_SIZE", is1d = upper == "LUT_1D_SIZE";
    if (!is3d && !is1d) continue;
    long size = 0;
    if (!(words >> size)) return;  // OpenColorIO's reader names a malformed size
    const long max = is3d ? kMaxFileLut3dSize : kMaxFileLut1dSize;
    if (size < 2) fail(path, keyword + " " + std::to_string(size) + ": a LUT needs at least 2 points to interpolate");
    if (size > max) fail(path, keyword + " " + std::to_string(size) + " is above " + std::to_string(max) + ", the most OpenColorIO takes");
  }
}

/// The rule OpenColorIO 2.1's CPU renderer applies for a 3D LUT's interpolation
/// (Lut3DOpData::GetConcreteInterpolation): best and tetrahedral are tetrahedral; default, linear,
/// cubic and nearest are all trilinear.
const char* interpolation_name(OCIO::Interpolation i) {
  switch (i) {
    case OCIO::INTERP_BEST:
    case OCIO::INTERP_TETRAHEDRAL: return "tetrahedral";
    default: return "trilinear";
  }
}

/// What the file holds ("1D LUT 6 + 3D LUT 3^3, trilinear"), refusing LUTs that cannot
/// interpolate and values that are not finite.
std::string describe_and_check(const OCIO::ConstProcessorRcPtr& processor, const std::string& path) {
  const OCIO::GroupTransformRcPtr group = processor->createGroupTransform();
  std::string description;
  auto finite = [&](float r, float g, float b, const std::string& where) {
    if (!std::isfinite(r) || !std::isfinite(g) || !std::isfinite(b)) fail(path, "a NaN or infinite value in its " + where);
  };
  for (int t = 0; t < group->getNumTransforms(); ++t) {
    const OCIO::ConstTransformRcPtr transform = group->getTransform(t);
    std::string part;
    if (const auto lut3d = OCIO::DynamicPtrCast<const OCIO::Lut3DTransform>(transform)) {
      const unsigned long n = lut3d->getGridSize();
      if (n < 2) fail(path, "a 3D LUT of " + std::to_string(n) + " point per axis cannot interpolate");
      for (unsigned long r = 0; r < n; ++r)
        for (unsigned long g = 0; g < n; ++g)
          for (unsigned long b = 0; b < n; ++b) {
            float v[3];
            lut3d->getValue(r, g, b, v[0], v[1], v[2]);
            finite(v[0], v[1], v[2], "3D LUT");
          }
      part = "3D LUT " + std::to_string(n) + "^3, " + interpolation_name(lut3d->getInterpolation());
    } else if (const auto lut1d = OCIO::DynamicPtrCast<const OCIO::Lut1DTransform>(transform)) {
      const unsigned long n = lut1d->getLength();
      if (n < 2) fail(path, "a 1D LUT of " + std::to_string(n) + " entry cannot interpolate");
      for (unsigned long i = 0; i < n; ++i) {
        float v[3];
        lut1d->getValue(i, v[0], v[1], v[2]);
        finite(v[0], v[1], v[2], "1D LUT");
      }
      part = "1D LUT " + std::to_string(n);
    } else if (OCIO::DynamicPtrCast<const OCIO::RangeTransform>(transform)) {
      part = "range";
    } else if (OCIO::DynamicPtrCast<const OCIO::MatrixTransform>(transform)) {
      part = "matrix";
    } else {
      part = "other";
    }
    description += (description.empty() ? "" : " + ") + part;
  }
  return description.empty() ? "identity" : description;
}

}  // namespace

ColorTransform read_lut_file(const std::string& path) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  if (error || !std::filesystem::is_regular_file(absolute, error) || !std::ifstream(absolute).good()) {
    fail(path, "cannot open it");
  }
  std::string extension = absolute.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".cube") check_cube_header(path);

  OCIO::ConstCPUProcessorRcPtr cpu;
  std::string description;
  try {
    OCIO::ClearAllCaches();
    const OCIO::FileTransformRcPtr file = OCIO::FileTransform::Create();
    file->setSrc(absolute.c_str());
    // What OpenColorIO's own tools evaluate a file with (ociochecklut, ocioconvert --lut,
    // ociobakelut --lut): INTERP_BEST, tetrahedral for 3D LUTs and linear for 1D ones. A CLF/CTF
    // file that names an interpolation keeps its own (the FileTransform's applies only to LUTs
    // that name none). INTERP_DEFAULT would be trilinear for every 3D LUT in OpenColorIO 2.1:
    // up to 23 steps in 8 bits away from those tools on tests/data/luts' 16^3 teal-and-orange
    // .cube, 12 on its 17^3 discreet-3d-lut.3dl.
    file->setInterpolation(kFileInterpolation);
    const OCIO::ConstProcessorRcPtr processor = OCIO::Config::CreateRaw()->getProcessor(file);
    description = describe_and_check(processor, path);
    cpu = processor->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_LOSSLESS);
  } catch (const OCIO::Exception& e) {
    fail(path, "not a LUT OpenColorIO reads: " + condensed(e.what(), absolute.string(), path));
  } catch (const std::bad_alloc&) {
    fail(path, "too large to read");
  }
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "colors are handed to OpenColorIO as packed RGB floats");
  // An OpenColorIO exception from applying it becomes the same one line naming the file as one
  // from reading it.
  ColorTransform transform{path, description, [cpu, path](std::span<glm::vec3> colors) {
                             if (colors.empty()) return;
                             OCIO::PackedImageDesc image(&colors[0].x, static_cast<long>(colors.size()), 1, 3);
                             try {
                               cpu->apply(image);
                             } catch (const OCIO::Exception& e) {
                               fail(path, std::string("OpenColorIO cannot apply it: ") + e.what());
                             }
                           }};
  // The LUTs' entries are checked above; a file's other numbers (a matrix, a range, a CDL's slope,
  // a 1D LUT's domain) may be NaN or infinite too, and then so is what they give: run the 9^3
  // lattice of [0, 1] through the whole transform.
  std::vector<glm::vec3> probe;
  for (int b = 0; b <= 8; ++b)
    for (int g = 0; g <= 8; ++g)
      for (int r = 0; r <= 8; ++r) probe.emplace_back(r / 8.0f, g / 8.0f, b / 8.0f);
  transform.apply(probe);
  for (const glm::vec3& c : probe)
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
      fail(path, "gives NaN or infinite colors for colors in [0, 1] (a number in it is NaN, infinite or beyond float)");
  return transform;
}

void write_cube(const Lut& lut, const std::string& path, const std::string& title) {
  std::ofstream out(path);
  if (!out) fail(path, "cannot write it");
  std::string quoted = title;
  std::replace(quoted.begin(), quoted.end(), '"', '\'');  // the title is the only quoted field
  out << "TITLE \"" << quoted << "\"\n";
  out << "# luxel: the engine's " << lut.size << "^3 color-correction LUT (8-bit entries / 255), red fastest\n";
  out << "LUT_3D_SIZE " << lut.size << "\nDOMAIN_MIN 0 0 0\nDOMAIN_MAX 1 1 1\n";
  char line[64];
  for (const Lut::Color24& e : lut.entries) {
    std::snprintf(line, sizeof line, "%.6f %.6f %.6f\n", e[0] / 255.0, e[1] / 255.0, e[2] / 255.0);
    out << line;
  }
  out.flush();
  if (!out) fail(path, "cannot write it");
}

}  // namespace luxel::postfx
