// Post-processing passes on a 1280x720 frame: the luminance histogram's range test (one bucket
// per frame, as auto exposure counts), the bloom's five passes one by one and together, the
// color correction that adds the bloom (Engine_Post, one LUT) and film grain, on a 1-sample
// frame and on a 4x MSAA one (Source draws bloomadd and the grain onto
// the multisampled back buffer; the copy resolves it), on 1 and 2 threads. One iteration = one
// pass over the whole frame; the passes run as the frame runs them (each flushes its draw, so on
// a busy machine a pass also waits for its worker to be scheduled: the 1-thread runs show the work
// alone). Each reports the median and the minimum of its repetitions.

#include "luxel/postfx/bloom.hpp"
#include "luxel/postfx/color_correction.hpp"
#include "luxel/postfx/grade.hpp"
#include "luxel/postfx/film_grain.hpp"
#include "luxel/postfx/full_frame.hpp"
#include "luxel/postfx/luminance_histogram.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace luxel::postfx {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

/// A frame with gradients and bright discs: the passes' cost does not depend on the content,
/// but the bloom then has something to spread.
rasterizer::Image frame_image() {
  rasterizer::Image image(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      uint8_t* p = image.pixel(x, y);
      const bool disc = std::hypot((x % 320) - 160, (y % 240) - 120) < 40;
      p[0] = disc ? 255 : static_cast<uint8_t>(x * 200 / kWidth);
      p[1] = disc ? 240 : static_cast<uint8_t>(y * 200 / kHeight);
      p[2] = disc ? 200 : 60;
      p[3] = 255;
    }
  return image;
}

/// A context (threads: the benchmark's second argument), a frame target (samples: the first) and
/// a bloom that has run once.
struct Setup {
  rasterizer::Context ctx;
  rasterizer::Image image = frame_image();
  rasterizer::ColorTarget frame;
  Bloom bloom;
  explicit Setup(const benchmark::State& state)
      : ctx(static_cast<int>(state.range(1))), frame(kWidth, kHeight, static_cast<int>(state.range(0))) {
    rasterizer::load_image(ctx, image, frame);
    bloom.apply(ctx, frame, 1.0f);
  }
};

void label(benchmark::State& state) {
  state.SetLabel(std::to_string(kWidth) + "x" + std::to_string(kHeight) + " msaa " + std::to_string(state.range(0)) +
                 ", " + std::to_string(state.range(1)) + " threads");
}

/// One histogram update: one bucket's range test over the center region of the frame's copy,
/// counted in an occlusion query, into a depth-stencil target with the frame's samples.
void BM_Histogram(benchmark::State& state) {
  Setup s(state);
  FullFrameTexture copy;
  copy.update(s.image);
  rasterizer::DepthStencilTarget target(kWidth, kHeight, static_cast<int>(state.range(0)));
  LuminanceHistogram histogram(HistogramSettings{});
  for (auto _ : state) histogram.update(s.ctx, copy.texture(), target);
  label(state);
}
void BM_BloomCopy(benchmark::State& state) {
  Setup s(state);
  for (auto _ : state) s.bloom.copy(s.ctx, s.frame);
  label(state);
}
void BM_BloomDownsample(benchmark::State& state) {
  Setup s(state);
  for (auto _ : state) s.bloom.downsample(s.ctx);
  label(state);
}
void BM_BloomBlurX(benchmark::State& state) {
  Setup s(state);
  for (auto _ : state) s.bloom.blur_x(s.ctx);
  label(state);
}
void BM_BloomBlurY(benchmark::State& state) {
  Setup s(state);
  for (auto _ : state) s.bloom.blur_y(s.ctx, 1.0f);
  label(state);
}
void BM_BloomAdd(benchmark::State& state) {
  Setup s(state);
  for (auto _ : state) s.bloom.add(s.ctx, s.frame);
  label(state);
}
void BM_Bloom(benchmark::State& state) {
  Setup s(state);
  for (auto _ : state) s.bloom.apply(s.ctx, s.frame, 1.0f);
  label(state);
}
void BM_FilmGrain(benchmark::State& state) {
  Setup s(state);
  FilmGrain grain;
  uint64_t frame_index = 0;
  for (auto _ : state) grain.apply(s.ctx, s.frame, frame_index++);
  label(state);
}

/// The engine's combine pass with one LUT (the courtyard's case): the bloom added to the frame
/// and the sum color-corrected in one draw, resolved into the same image every frame, as the
/// frame resolves it.
void BM_ColorCorrect(benchmark::State& state) {
  Setup s(state);
  const rasterizer::Image resolved = rasterizer::resolve(s.ctx, s.frame);
  s.bloom.blur(s.ctx, resolved, 1.0f);
  const Lut lut = sample_lut(grade_transform(*grade_preset("warm"), "builtin:warm"));
  const rasterizer::Texture volume = lut_volume(lut);  // kept from frame to frame, as the frame keeps it
  const WeightedLut luts[] = {{&lut, 1.0f, &volume}};
  rasterizer::Image out;
  for (auto _ : state) {
    color_correct_into(s.ctx, s.bloom, luts, out);
    benchmark::DoNotOptimize(out.rgba.data());
  }
  label(state);
}

double minimum(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

#define LUXEL_POSTFX_BENCH(name)                                                                  \
  BENCHMARK(name)->ArgsProduct({{1, 4}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime()->ComputeStatistics("min", minimum)
LUXEL_POSTFX_BENCH(BM_Histogram);
LUXEL_POSTFX_BENCH(BM_BloomCopy);
LUXEL_POSTFX_BENCH(BM_BloomDownsample);
LUXEL_POSTFX_BENCH(BM_BloomBlurX);
LUXEL_POSTFX_BENCH(BM_BloomBlurY);
LUXEL_POSTFX_BENCH(BM_BloomAdd);
LUXEL_POSTFX_BENCH(BM_Bloom);
LUXEL_POSTFX_BENCH(BM_FilmGrain);
LUXEL_POSTFX_BENCH(BM_ColorCorrect);

}  // namespace
}  // namespace luxel::postfx
