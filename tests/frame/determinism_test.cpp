// Determinism of whole frames: every built-in scene (at reduced size), drawn as each shader model,
// resolves to identical bytes and reports identical stats with 1, 2, 3 and 8 threads, frame after
// frame; and the courtyard's bytes per model against golden hashes.

#include "frame/frame_support.hpp"

#include <gtest/gtest.h>

#include "luxel/rasterizer/simd.hpp"
#include "luxel/scenes/content_hash.hpp"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace luxel::frame {
namespace {

RenderedFrame render(std::string_view name, const FrameSettings& settings, int threads, int frames) {
  rasterizer::ContextOptions options;
  options.threads = threads;
  return render_builtin(name, settings, options, frames);
}

bool same_stats(const rasterizer::DrawStats& a, const rasterizer::DrawStats& b) {
  return a.triangles == b.triangles && a.bad_index == b.bad_index && a.non_finite == b.non_finite &&
         a.outside == b.outside && a.clipped == b.clipped && a.clip_overflow == b.clip_overflow &&
         a.culled == b.culled && a.degenerate == b.degenerate &&
         a.rasterized == b.rasterized && a.stamps_full == b.stamps_full && a.stamps_partial == b.stamps_partial &&
         a.stamps_wide_edges == b.stamps_wide_edges && a.stamps_shaded == b.stamps_shaded;
}

// Returns the bytes all thread counts agreed on.
std::vector<uint8_t> check(std::string_view name, const FrameSettings& settings) {
  const RenderedFrame one = render(name, settings, 1, 2);
  EXPECT_EQ(one.image.rgba.size(), size_t(settings.width) * settings.height * 4);
  // Not a blank image: the scene drew something.
  bool varied = false;
  for (size_t i = 4; i < one.image.rgba.size() && !varied; ++i) varied = one.image.rgba[i] != one.image.rgba[i % 4];
  EXPECT_TRUE(varied) << name;
  for (int threads : {2, 3, 8}) {
    const RenderedFrame f = render(name, settings, threads, 2);
    EXPECT_TRUE(f.image.rgba == one.image.rgba) << name << " " << settings.width << "x" << settings.height << "x" << settings.samples
                                    << ": " << threads << " threads differ from 1 thread";
    EXPECT_TRUE(same_stats(f.stats, one.stats)) << name << ": stats differ with " << threads << " threads";
  }
  return one.image.rgba;
}

constexpr shading::ShaderModel kModels[] = {shading::ShaderModel::ps_2_0, shading::ShaderModel::ps_2_b,
                                             shading::ShaderModel::ps_3_0};

FrameSettings as_model(FrameSettings s, shading::ShaderModel model) {
  s.model = model;
  return s;
}

// One test per scene, so that gtest's shards (tests/CMakeLists.txt) share them out.
class FrameDeterminismOfScene : public testing::TestWithParam<std::string> {};

// A scene drawn only by UnlitGeneric (the peer's workloads) draws the same trivial shader under
// every model: the thread sweep runs for one model, and the others must give its bytes. Sweeping
// each would triple the largest test (tris's million triangles) for no new path.
bool only_unlit(const scenes::Scene& scene) {
  for (const scenes::Material& m : scene.materials)
    if (m.family != scenes::ShaderFamily::unlit_generic) return false;
  return true;
}

TEST_P(FrameDeterminismOfScene, AsEveryModel) {
  const std::string& name = GetParam();
  const FrameSettings size{kReduced ? 64 : 120, kReduced ? 40 : 72, 4};
  if (only_unlit(*builtin_scene(name, size.width, size.height))) {
    const std::vector<uint8_t> ps_3_0 = check(name, as_model(size, shading::ShaderModel::ps_3_0));
    for (shading::ShaderModel model : {shading::ShaderModel::ps_2_0, shading::ShaderModel::ps_2_b})
      EXPECT_TRUE(render(name, as_model(size, model), 2, 1).image.rgba == ps_3_0)
          << name << " as " << shading::caps(model).name << " differs from ps_3_0";
    return;
  }
  for (shading::ShaderModel model : kModels) {
    SCOPED_TRACE(name + " as " + std::string(shading::caps(model).name));
    check(name, as_model(size, model));
  }
}

INSTANTIATE_TEST_SUITE_P(Builtin, FrameDeterminismOfScene, testing::ValuesIn(scenes::builtin_scene_names()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

// FNV-1a, 64 bits, of the image bytes: a hash a reader can recompute with a few lines of anything.
uint64_t fnv1a(const std::vector<uint8_t>& bytes) {
  scenes::ContentHash h;
  h.bytes(bytes.data(), bytes.size());
  return h.h;
}

// Golden bytes of the courtyard per model (160x90, 4x MSAA, the test bake): any change to what a
// frame draws shows here first. They hold for 8 and 16 lanes alike (the ASan and release presets
// on an AVX-512 machine). A deliberate change of the
// picture updates them: the failure prints the new value. Each model has three: the frame as
// drawn, the same without its passes on the finished image (bloom, color correction), and that
// with the 3D passes' textures read by the ideal sampling rules (rasterizer/texture.hpp).
TEST(FrameDeterminism, CourtyardGoldenHashes) {
  const struct { shading::ShaderModel model; uint64_t hash, without_post, ideal_without_post; } golden[] = {
      {shading::ShaderModel::ps_2_0, 0xe2c8934ba49d808cull, 0x40463020b44defb5ull, 0xbb1f0e5be1f1d6b9ull},
      {shading::ShaderModel::ps_2_b, 0x228f035147358a96ull, 0xc9f4dc9017b4bc3bull, 0xd9366270ba0fc728ull},
      {shading::ShaderModel::ps_3_0, 0x228f035147358a96ull, 0xc9f4dc9017b4bc3bull, 0xd9366270ba0fc728ull},
  };
  // ps_2_b and ps_3_0 run the same combos on the courtyard (no combo there needs more than
  // ps_2_b offers), hence the same bytes.
  enum class Variant { drawn, without_post, ideal_without_post };
  for (const auto& g : golden) {
    for (Variant v : {Variant::drawn, Variant::without_post, Variant::ideal_without_post}) {
      FrameSettings settings = as_model({160, 90, 4}, g.model);
      settings.color_correction = v == Variant::drawn;
      if (v == Variant::drawn) settings.bloom = postfx::BloomOptions{};
      if (v == Variant::ideal_without_post) settings.sampling = rasterizer::SamplingRules::ideal;
      const RenderedFrame f = render("courtyard", settings, 2, 1);
      const uint64_t h = fnv1a(f.image.rgba);
      char hex[32];
      std::snprintf(hex, sizeof hex, "0x%016llxull", static_cast<unsigned long long>(h));
      const uint64_t want = v == Variant::drawn ? g.hash : v == Variant::without_post ? g.without_post : g.ideal_without_post;
      const char* what = v == Variant::drawn ? "" : v == Variant::without_post ? " without bloom and color correction"
                                                                              : " without bloom and color correction, ideal sampling";
      EXPECT_EQ(h, want) << shading::caps(g.model).name << what << ": the courtyard's bytes changed; new hash " << hex;
    }
  }
}

TEST(FrameDeterminism, FillScene) {
  check("fill", {200, 120, 4});
  check("fill", {131, 67, 1});
}

TEST(FrameDeterminism, TrisScene) {
  check("tris", {kReduced ? 96 : 320, kReduced ? 64 : 180, 4});
  if (!kReduced) check("tris", {131, 67, 8});
}

TEST(FrameDeterminism, DemoScene) {
  check("demo", {kReduced ? 96 : 200, kReduced ? 64 : 120, 4});
  check("demo", {131, 67, 1});
}

TEST(FrameDeterminism, CourtyardScene) {
  check("courtyard", {kReduced ? 96 : 240, kReduced ? 64 : 136, 4});
  FrameSettings on_path{kReduced ? 64 : 160, kReduced ? 48 : 90, 2};
  on_path.camera_path = true;
  on_path.time = 7.5f;
  check("courtyard", on_path);
  for (int camera : {1, 2}) check("courtyard", {kReduced ? 64 : 160, kReduced ? 48 : 90, 1, camera});
}

TEST(FrameDeterminism, BadSettingsAndCamerasThrow) {
  const scenes::Scene fill = scenes::make_builtin_scene("fill");
  EXPECT_THROW(Renderer(fill, {0, 10, 1}), std::invalid_argument);
  EXPECT_THROW(Renderer(fill, {10, 10, 3}), std::invalid_argument);
  EXPECT_THROW(Renderer(fill, {10, 10, 1, 1}), std::invalid_argument);   // fill has one camera
  EXPECT_THROW(Renderer(fill, {10, 10, 1, -1}), std::invalid_argument);
  FrameSettings on_path{10, 10, 1};
  on_path.camera_path = true;
  EXPECT_THROW(Renderer(fill, on_path), std::invalid_argument);         // and no camera path
  scenes::Scene broken = fill;
  broken.meshes[0].material = 99;
  EXPECT_THROW(Renderer(broken, {10, 10, 1}), std::invalid_argument);   // scenes::validate
}

}  // namespace
}  // namespace luxel::frame
