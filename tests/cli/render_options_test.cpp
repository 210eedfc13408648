// `luxel render`'s options reach the renderer: for each, the PNG the command writes is byte-equal
// to frame::Renderer drawing the same scene with the FrameSettings field the option names set as
// the test sets it here, and (but for the thread count, which must not change anything) differs
// from the default frame, so an option that did nothing fails. Each run has a fixed exposure
// (--exposure 1: no settling, a frame the renderer alone gives) on the quickly baked courtyard.

#include "cli/run_luxel.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/scenes/image_io.hpp"

#include "frame_options.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace luxel::cli {
namespace {

constexpr int kWidth = 96, kHeight = 54;

struct OptionCase {
  std::string flags;
  std::function<void(frame::FrameSettings&)> set;
  bool changes = true;
};

TEST(RenderOptions, EachOptionReachesTheRendererAsItsSettingsField) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("luxel-render-options-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string common = "render --scene builtin:courtyard --bake quick --width " + std::to_string(kWidth) + " --height " +
                             std::to_string(kHeight) + " --exposure 1 ";
  // The scene as the command loads it (the same bake, from the same cache).
  FrameOptions options;
  options.scene = "builtin:courtyard";
  options.bake = "quick";
  options.settings.width = kWidth, options.settings.height = kHeight;
  frame::FrameSettings base = options.settings;
  int code = 0;
  ASSERT_EQ(test::run_luxel(common + "--out " + (dir / "warm.png").string() + " 2>/dev/null").exit_code, 0);  // bakes once
  const std::optional<scenes::Scene> scene = options.prepare_scene("render", base, {}, code);
  ASSERT_TRUE(scene.has_value());
  // render's own defaults: ps_3_0, the bloom on, exposure 1 from the flag.
  base.model = shading::ShaderModel::ps_3_0;
  base.exposure = 1.0f;
  base.bloom = postfx::BloomOptions{};
  auto draw = [&](const frame::FrameSettings& s) {
    frame::Renderer r(*scene, s);
    rasterizer::Context ctx(2);
    r.render(ctx);
    return r.image().rgba;
  };
  const std::vector<uint8_t> default_frame = draw(base);
  const std::vector<OptionCase> cases = {
      {"", [](frame::FrameSettings&) {}, false},
      {"--threads 1", [](frame::FrameSettings&) {}, false},
      {"--no-color-correction", [](frame::FrameSettings& s) { s.color_correction = false; }},
      {"--no-bloom", [](frame::FrameSettings& s) { s.bloom.reset(); }},
      {"--ambient trilinear", [](frame::FrameSettings& s) { s.ambient = frame::AmbientSampling::trilinear; }},
      {"--lights 4", [](frame::FrameSettings& s) { s.local_lights = 4; }},
      {"--pixel-attenuation", [](frame::FrameSettings& s) { s.pixel_attenuation = true; }},
      {"--model ps_2_0", [](frame::FrameSettings& s) { s.model = shading::ShaderModel::ps_2_0; }},
      {"--msaa 2", [](frame::FrameSettings& s) { s.samples = 2; }},
      {"--camera 1", [](frame::FrameSettings& s) { s.camera = 1; }},
      {"--film-grain 7", [](frame::FrameSettings& s) { s.film_grain = postfx::FilmGrainOptions{7}; }},
      {"--look archival", [](frame::FrameSettings& s) { s.look = frame::Look::archival; }},
      {"--water-size 64", [](frame::FrameSettings& s) { s.water_texture_size = 64; }},
  };
  for (const OptionCase& c : cases) {
    SCOPED_TRACE(c.flags.empty() ? "(no option)" : c.flags);
    const std::filesystem::path png = dir / "frame.png";
    const test::Process run = test::run_luxel(common + c.flags + " --out " + png.string() + " 2>/dev/null");
    ASSERT_EQ(run.exit_code, 0) << run.out;
    const scenes::PixelImage written = scenes::read_image(png.string());
    frame::FrameSettings s = base;
    c.set(s);
    const std::vector<uint8_t> expected = draw(s);
    EXPECT_TRUE(written.rgba8 == expected) << "the command's frame is not the renderer's with the option's setting";
    EXPECT_EQ(expected != default_frame, c.changes) << (c.changes ? "the option changes nothing" : "it must change nothing");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace luxel::cli
