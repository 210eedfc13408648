// `luxel grade --exact` against OpenColorIO itself, on every LUT file the tests ship: the EXR it
// writes for an 8-bit gradient and random colors is what OpenColorIO's own tools compute for each
// pixel, within 1e-4. Two references computed apart from luxel's code: a FileTransform CPU
// processor built here the way ociochecklut, ocioconvert --lut and ociobakelut --lut build theirs
// (INTERP_BEST), for every pixel; and ociochecklut's printed output for a subset of the colors,
// when the program is installed (opencolorio-tools, scripts/install-deps).

#include "test_paths.hpp"
#include "cli/run_luxel.hpp"
#include "scenes/temp_dir.hpp"

#include "luxel/rasterizer/image.hpp"
#include "luxel/scenes/image_io.hpp"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace luxel::cli {
namespace grade_exact_ocio {

namespace OCIO = OCIO_NAMESPACE;
using test::run_luxel;

/// 256 x 4: a grey ramp over every 8-bit value, a ramp through the hues, two rows of random colors.
rasterizer::Image gradient_frame() {
  rasterizer::Image image(256, 4);
  std::mt19937 rng(7);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 256; ++x) {
      uint8_t* p = &image.rgba[4 * (size_t(y) * 256 + x)];
      const uint8_t v = uint8_t(x);
      if (y == 0) p[0] = p[1] = p[2] = v;
      else if (y == 1) p[0] = v, p[1] = uint8_t((x * 7) & 0xff), p[2] = uint8_t(255 - x);
      else p[0] = uint8_t(rng() & 0xff), p[1] = uint8_t(rng() & 0xff), p[2] = uint8_t(rng() & 0xff);
      p[3] = 255;
    }
  return image;
}

/// The file applied to the frame's colors (over 255) by a processor of OpenColorIO's own.
std::vector<float> ocio_reference(const std::string& lut, const rasterizer::Image& frame) {
  OCIO::ClearAllCaches();
  const OCIO::FileTransformRcPtr file = OCIO::FileTransform::Create();
  file->setSrc(lut.c_str());
  file->setInterpolation(OCIO::INTERP_BEST);
  const OCIO::ConstCPUProcessorRcPtr cpu = OCIO::Config::CreateRaw()->getProcessor(file)->getDefaultCPUProcessor();
  std::vector<float> rgb;
  for (size_t p = 0; p < size_t(frame.width) * frame.height; ++p)
    for (int c = 0; c < 3; ++c) rgb.push_back(frame.rgba[4 * p + c] / 255.0f);
  OCIO::PackedImageDesc image(rgb.data(), long(rgb.size() / 3), 1, 3);
  cpu->apply(image);
  return rgb;
}

bool have_ociochecklut() { return std::system("command -v ociochecklut >/dev/null 2>&1") == 0; }

/// ociochecklut's output for one color, or an empty vector when it printed no three numbers.
std::vector<double> ociochecklut(const std::string& lut, const uint8_t* rgb) {
  char args[128];
  std::snprintf(args, sizeof args, " %.9g %.9g %.9g", rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
  FILE* pipe = popen(("ociochecklut '" + lut + "'" + args + " 2>/dev/null").c_str(), "r");
  if (!pipe) return {};
  char line[256] = {};
  const bool read = std::fgets(line, sizeof line, pipe) != nullptr;
  pclose(pipe);
  std::istringstream words(read ? line : "");
  std::vector<double> out(3);
  if (!(words >> out[0] >> out[1] >> out[2])) return {};
  return out;
}

std::vector<std::string> shipped_lut_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(luxel::test::data_dir() + "/luts")) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".cube" || ext == ".3dl") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(GradeExactOcio, EveryShippedLutIsWhatOpenColorIOComputes) {
  const scenes::test::TempDir dir;
  const rasterizer::Image frame = gradient_frame();
  scenes::write_image(frame.width, frame.height, frame.rgba, dir.file("gradient.png"));
  const bool checklut = have_ociochecklut();
  if (!checklut) std::printf("ociochecklut not found (opencolorio-tools): checked against the processor alone\n");
  const std::vector<std::string> files = shipped_lut_files();
  ASSERT_EQ(files.size(), 6u);
  for (const std::string& lut : files) {
    const std::string name = std::filesystem::path(lut).filename().string();
    const test::Process run =
        run_luxel("grade " + dir.file("gradient.png") + " " + dir.file("out.exr") + " --exact --lut " + lut + " 2>&1");
    ASSERT_EQ(run.exit_code, 0) << run.out;
    const scenes::PixelImage got = scenes::read_image(dir.file("out.exr"));
    ASSERT_EQ(got.rgba32f.size(), frame.rgba.size()) << name;
    const std::vector<float> want = ocio_reference(lut, frame);
    double worst = 0.0, worst_checklut = 0.0;
    int checked = 0;
    for (size_t p = 0; p < size_t(frame.width) * frame.height; ++p) {
      for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(got.rgba32f[4 * p + c] - want[3 * p + c])));
      // ociochecklut is a process per color: every sixteenth grey, and every sixteenth color of the
      // other rows.
      if (!checklut || p % 16 != 0) continue;
      const std::vector<double> tool = ociochecklut(lut, &frame.rgba[4 * p]);
      ASSERT_EQ(tool.size(), 3u) << name << ": ociochecklut printed no color";
      for (int c = 0; c < 3; ++c) worst_checklut = std::max(worst_checklut, std::abs(got.rgba32f[4 * p + c] - tool[c]));
      ++checked;
    }
    EXPECT_LE(worst, 1e-4) << name << " against OpenColorIO's processor";
    EXPECT_LE(worst_checklut, 1e-4) << name << " against ociochecklut";
    std::printf("%s: max |exact - OpenColorIO| %.3g over %zu colors; |exact - ociochecklut| %.3g over %d\n", name.c_str(),
                worst, size_t(frame.width) * frame.height, worst_checklut, checked);
  }
}

}  // namespace grade_exact_ocio
}  // namespace luxel::cli
