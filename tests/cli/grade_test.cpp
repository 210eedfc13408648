// `luxel grade` checked by what it writes: the engine's way gives the bytes postfx::color_correct
// gives for the same image, LUTs and weights, for 1 and 2 threads alike; --exact gives
// postfx::color_correct_exact's floats in an EXR; --save-lut writes the engine's lattice as .cube
// or .raw.

#include "test_paths.hpp"
#include "cli/run_luxel.hpp"
#include "scenes/temp_dir.hpp"

#include "luxel/postfx/color_correction.hpp"
#include "luxel/postfx/lut_file.hpp"
#include "luxel/postfx/lut_source.hpp"
#include "luxel/scenes/image_io.hpp"

#include <gtest/gtest.h>

#include <random>

namespace luxel::cli {
namespace {

using test::run_luxel;

/// A 97 x 61 image of random bytes (alpha too), written as PNG.
rasterizer::Image write_random_png(const std::string& path) {
  rasterizer::Image image(97, 61);
  std::mt19937 rng(11);
  for (uint8_t& b : image.rgba) b = static_cast<uint8_t>(rng() & 0xff);
  scenes::write_image(image.width, image.height, image.rgba, path);
  return image;
}

const std::string kCrosstalk = luxel::test::data_dir() + "/luts/opencolorio/crosstalk.3dl";

TEST(GradeCommand, EngineWayWritesTheLibrarysBytesForAnyThreadCount) {
  const scenes::test::TempDir dir;
  const rasterizer::Image frame = write_random_png(dir.file("in.png"));
  const std::string luts = " --lut builtin:day-for-night --weight 0.25 --lut " + kCrosstalk + " --weight 0.5";
  for (const char* threads : {"1", "2"}) {
    const test::Process run = run_luxel("grade " + dir.file("in.png") + " " + dir.file(std::string("out") + threads + ".png") +
                                        luts + " --threads " + threads + " 2>&1");
    ASSERT_EQ(run.exit_code, 0) << run.out;
  }
  const postfx::Lut night = postfx::resolve_lut("builtin:day-for-night"), crosstalk = postfx::resolve_lut(kCrosstalk);
  const postfx::WeightedLut weighted[] = {{&night, 0.25f}, {&crosstalk, 0.5f}};
  rasterizer::Context ctx(2);
  const rasterizer::Image want = postfx::color_correct(ctx, frame, weighted);
  for (const char* name : {"out1.png", "out2.png"}) {
    const scenes::PixelImage got = scenes::read_image(dir.file(name));
    EXPECT_EQ(got.rgba8, want.rgba) << name;
  }
}

TEST(GradeCommand, ExactWritesTheFloatBlendAsExr) {
  const scenes::test::TempDir dir;
  const rasterizer::Image frame = write_random_png(dir.file("in.png"));
  const test::Process run =
      run_luxel("grade " + dir.file("in.png") + " " + dir.file("out.exr") + " --exact --lut " + kCrosstalk + " 2>&1");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("crosstalk.3dl (3D LUT 17^3, tetrahedral) x 1, exact"), std::string::npos) << run.out;
  const postfx::ColorTransform t = postfx::read_lut_file(kCrosstalk);
  const postfx::WeightedTransform weighted[] = {{&t, 1.0f}};
  const std::vector<float> want = postfx::color_correct_exact(frame, weighted);
  const scenes::PixelImage got = scenes::read_image(dir.file("out.exr"));
  ASSERT_EQ(got.rgba32f.size(), want.size());
  double worst = 0.0;
  for (size_t i = 0; i < want.size(); ++i) worst = std::max(worst, double(std::abs(got.rgba32f[i] - want[i])));
  EXPECT_LE(worst, 1e-6) << "float EXR: the floats as computed";
}

TEST(GradeCommand, SaveLutWritesTheEngineLatticeAsCubeOrRaw) {
  const scenes::test::TempDir dir;
  write_random_png(dir.file("in.png"));
  for (const char* file : {"archival.cube", "archival.raw"}) {
    const test::Process run = run_luxel("grade " + dir.file("in.png") + " " + dir.file("out.png") +
                                        " --lut builtin:archival --save-lut " + dir.file(file) + " 2>&1");
    ASSERT_EQ(run.exit_code, 0) << run.out;
    EXPECT_EQ(postfx::resolve_lut(dir.file(file)), postfx::resolve_lut("builtin:archival")) << file;
  }
}

}  // namespace
}  // namespace luxel::cli
