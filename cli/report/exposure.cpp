// The report's section "exposure": auto exposure the engine's way (postfx/auto_exposure.hpp: one
// histogram bucket counted per frame by an occlusion query, read back `query_latency` frames
// later) over the first seconds of the scene's sequence, for each way of counting (the direct
// query; the stencil pass with a second counting draw) and each query latency, against the exact
// histogram of each frame (postfx::exact_target: every bucket counted from the frame itself, now).
// Error: how far the target the engine's histogram gives is from the exact target of the same
// frame, in stops (|log2(target / exact)|), its max and mean over the frames and its mean over
// the second half (after the histogram has filled). Cost: the latency, and ms per frame.

#include "report/findings.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include "luxel/postfx/auto_exposure.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

constexpr int kExposureFrames = 60;
constexpr float kExposureFps = 30.0f;
constexpr int kLatencies[] = {1, 2, 3, 4};

struct Count {
  postfx::HistogramCount count;
  const char* name;
};
constexpr Count kCounts[] = {{postfx::HistogramCount::direct_query, "direct query"},
                             {postfx::HistogramCount::stencil, "stencil + query"}};

/// The first counting's error from the shortest latency to the longest, and whether the other
/// countings give the same errors at every latency.
std::vector<std::string> exposure_findings(const SectionResult& r) {
  std::vector<std::string> findings;
  const std::vector<std::string> countings = distinct(r, &ReportRow::variant, any_row);
  const std::optional<Span> latency = span_of(r, "query_latency", any_row);
  if (countings.empty() || !latency) return findings;
  const std::string& first = countings.front();
  const ReportRow* shortest = first_row(r, both(variant_is(first), value_is(r, "query_latency", latency->min)));
  const ReportRow* longest = first_row(r, both(variant_is(first), value_is(r, "query_latency", latency->max)));
  if (!shortest || !longest) return findings;
  auto at = [&](const char* key) {
    return text_of(r, key, value_of(r, *shortest, key)) + " stops at latency " + text_of(r, "query_latency", latency->min) + " to " +
           text_of(r, key, value_of(r, *longest, key)) + " at " + text_of(r, "query_latency", latency->max);
  };
  std::string finding = first + ": the target's mean distance from the exact one goes from " + at("mean_stops") +
                        " over all frames, and from " + at("mean_stops_second_half") + " over the second half";
  if (const std::optional<Span> max = span_of(r, "max_stops", variant_is(first)))
    finding += "; at most " + text_of(r, "max_stops", max->max) + " stops";
  findings.push_back(finding);
  for (size_t c = 1; c < countings.size(); ++c) {
    double largest = 0;  // of a difference of an error column from the first counting's, same latency
    for (const ReportRow* row : rows_where(r, variant_is(countings[c]))) {
      const ReportRow* same = first_row(r, both(variant_is(first), value_is(r, "query_latency", value_of(r, *row, "query_latency"))));
      if (!same) continue;
      for (const char* key : {"max_stops", "mean_stops", "mean_stops_second_half"})
        largest = std::max(largest, std::abs(value_of(r, *row, key) - value_of(r, *same, key)));
    }
    findings.push_back(countings[c] + (largest == 0 ? " gives the same errors as " + first + " at every latency"
                                                    : " differs from " + first + " by up to " + text_of(r, "max_stops", largest) + " stops"));
  }
  return findings;
}

SectionResult run_exposure(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "auto exposure's occlusion-query histogram against each frame's exact histogram, per counting and latency";
  out.columns = {{"query_latency", "latency", ColumnKind::cost, "%.0f"},
                 {"ms_per_frame", "ms/frame", ColumnKind::timing, "%.2f"},
                 {"max_stops", "max stops", ColumnKind::error, "%.3f"},
                 {"mean_stops", "mean stops", ColumnKind::error, "%.3f"},
                 {"mean_stops_second_half", "mean 2nd half", ColumnKind::error, "%.3f"}};
  out.plot = {"Auto exposure: the engine's histogram target against the exact one", "query latency (frames)",
              "mean |log2(target / exact)| (stops)", "query_latency", "mean_stops", 1.0, false};
  const bool path = !scene.scene->camera_path.empty();
  for (const Count& count : kCounts) {
    for (int latency : kLatencies) {
      s.progress("exposure: " + std::string(count.name) + ", latency " + std::to_string(latency));
      frame::FrameSettings f = scene.settings;
      f.exposure = std::nullopt;
      f.camera_path = path;
      f.histogram.count = count.count;
      f.histogram.query_latency = latency;
      const std::unique_ptr<frame::Renderer> renderer = scene.renderer(f);
      const postfx::AutoExposure* a = renderer->auto_exposure();
      if (a == nullptr) {
        out.notes.push_back(scene.name + " has a fixed exposure: nothing to measure.");
        return out;
      }
      std::vector<double> stops, ms;
      for (int n = 0; n < kExposureFrames; ++n) {
        if (n > 0) renderer->set_time(float(n) / kExposureFps);
        const float drawn = renderer->exposure();
        const auto start = std::chrono::steady_clock::now();
        renderer->render(*scene.ctx);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        const float exact = postfx::exact_target(renderer->image(), a->settings(), drawn);
        stops.push_back(std::fabs(std::log2(double(a->last_target()) / double(exact))));
      }
      std::sort(ms.begin(), ms.end());
      double max = 0, sum = 0, late = 0;
      for (size_t i = 0; i < stops.size(); ++i) {
        max = std::max(max, stops[i]);
        sum += stops[i];
        if (i >= stops.size() / 2) late += stops[i];
      }
      const std::string label = std::string(count.count == postfx::HistogramCount::direct_query ? "direct" : "stencil") +
                                ", " + std::to_string(latency);
      out.rows.push_back({scene.name, scene.resolution() + ", " + std::to_string(kExposureFrames) + " frames", count.name, label,
                          "the target of each frame's exact histogram (postfx::exact_target: every bucket counted from the "
                          "frame drawn, with no query latency)",
                          {double(latency), median_of_sorted(ms), max, sum / double(stops.size()),
                           late / double(stops.size() - stops.size() / 2)}});
    }
  }
  out.notes.push_back("Frames 0 to " + std::to_string(kExposureFrames - 1) + " at " + std::to_string(int(kExposureFps)) + " fps" +
                      (path ? " along the scene's camera path" : " from its first camera") +
                      ", the shaders' pixels (no bloom, no color correction), each drawn with the exposure the frames "
                      "before it chose; the histogram's region, buckets and target rule are the scene's.");
  out.notes.push_back("The engine counts one bucket per frame and reads it `latency` frames later, so its target lags the "
                      "frame it is compared with; the first frames have few buckets counted. ms/frame: median over the "
                      "frames, the histogram pass included.");
  out.findings = exposure_findings(out);
  return out;
}

}  // namespace

ReportSection exposure_section() {
  return {"exposure",
          "auto exposure's occlusion histogram against the exact histogram over the first 2 s of --scene's sequence, per "
          "counting method and query latency",
          run_exposure, true};
}

}  // namespace luxel::cli
