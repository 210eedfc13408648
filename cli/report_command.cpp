// luxel report speed-error [--sections NAME,...] [--probes DIR] [--normals N] [--grid ROWS]
// [--scene SCENE] [--width W] [--height H] [--bake full|quick] [--threads N] [--repeats R] --out DIR:
// each approximation's cost and its error against a reference luxel computes itself
// (cli/report/report.hpp says what is written; each section's file what it measures). The frame
// sections render --scene, prepared once here as `luxel render` prepares it (frame_options.hpp),
// only when one of them is chosen. The tables also go to stdout; progress to stderr as a live
// line, on a terminal only.
//
// Exit codes: 2 for bad arguments (an unknown section, a --scene that names no scene), 1 for files
// (a probe or scene that cannot be read, an output that cannot be written); one line on stderr each.

#include "commands.hpp"
#include "frame_options.hpp"

#include "report/report.hpp"
#include "report/report_scene.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

struct SpeedErrorOptions {
  std::vector<std::string> sections;
  std::string probes;  ///< none by default: the probe rows need a folder of the user's
  std::string out;
  int normals = 1000, grid = 192, repeats = 5;
  FrameOptions frame;  ///< --scene --width --height --bake --threads; the rest is the report's (report_scene.hpp)
};

/// The frames' options: the scene at --width x --height, the frame's defaults otherwise, the post
/// passes off (report_scene.hpp).
FrameOptions report_frame_options() {
  FrameOptions o;
  o.scene = "builtin:courtyard";
  o.settings.width = 320, o.settings.height = 180;
  o.settings.color_correction = false;
  return o;
}

std::string section_names() {
  std::string names;
  for (const ReportSection& s : report_sections()) names += (names.empty() ? "" : ", ") + s.name;
  return names;
}

/// The sections asked for, in report order, or an error message.
std::vector<const ReportSection*> chosen_sections(const std::vector<std::string>& names, std::string& error) {
  std::vector<const ReportSection*> chosen;
  for (const std::string& n : names) {
    bool known = false;
    for (const ReportSection& s : report_sections()) known = known || s.name == n;
    if (!known) {
      error = "--sections: unknown section '" + n + "' (sections: " + section_names() + ")";
      return {};
    }
  }
  for (const ReportSection& s : report_sections())
    if (names.empty() || std::find(names.begin(), names.end(), s.name) != names.end()) chosen.push_back(&s);
  return chosen;
}

int run_speed_error(const SpeedErrorOptions& o) {
  std::string error;
  const std::vector<const ReportSection*> sections = chosen_sections(o.sections, error);
  if (!error.empty()) {
    std::cerr << "luxel report: " << error << "\n";
    return 2;
  }
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (!std::filesystem::is_directory(o.out)) {
    std::cerr << "luxel report: " << o.out << ": cannot create the folder for the report\n";
    return 1;
  }
  // The scene, when a chosen section renders frames: loaded, baked (or its bake loaded), its
  // textures uploaded once.
  std::optional<scenes::Scene> scene;
  std::optional<rasterizer::Context> ctx;
  ReportScene frames;
  if (std::any_of(sections.begin(), sections.end(), [](const ReportSection* s) { return s->renders_frames; })) {
    int code = 0;
    const auto context_options = o.frame.context_options("report", code);
    if (!context_options) return code;
    frames.settings = o.frame.settings;
    scene = o.frame.prepare_scene("report", frames.settings, {}, code);
    if (!scene) return code;
    try {
      frames.textures = std::make_shared<const frame::SceneTextures>(*scene);
    } catch (const std::exception& e) {
      std::cerr << "luxel report: " << o.frame.scene << ": " << e.what() << "\n";
      return 1;
    }
    ctx.emplace(*context_options);
    frames.name = o.frame.scene, frames.scene = &*scene, frames.ctx = &*ctx;
  }
  const bool terminal = isatty(STDERR_FILENO);
  ReportSettings settings;
  if (scene) settings.scene = &frames;
  settings.probes = o.probes, settings.normals = o.normals, settings.grid_rows = o.grid, settings.timing_repeats = o.repeats;
  // Progress: a live line on a terminal, cleared when done; nothing in a log, where an error
  // stays the one line on stderr.
  settings.progress = [terminal](const std::string& line) {
    if (terminal) std::fprintf(stderr, "\r\033[Kluxel report: %s", line.c_str());
  };
  try {
    std::vector<std::pair<std::string, SectionResult>> results;
    for (const ReportSection* s : sections) results.emplace_back(s->name, s->run(settings));
    if (terminal) std::fprintf(stderr, "\r\033[K");
    const std::string text = write_report(o.out, results);
    std::printf("%s\nwrote %s/speed_error.txt, speed_error.json", text.c_str(), o.out.c_str());
    for (const auto& [name, r] : results) std::printf(", %s.png", name.c_str());
    std::printf("\n");
  } catch (const std::exception& e) {  // files: "PATH: problem"
    if (terminal) std::fprintf(stderr, "\r\033[K");
    std::cerr << "luxel report: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

Runner add_report_command(CLI::App& app) {
  auto o = std::make_shared<SpeedErrorOptions>();
  o->frame = report_frame_options();
  CLI::App* report = app.add_subcommand("report", "Reports on luxel's approximations");
  report->require_subcommand(1);
  CLI::App* cmd = report->add_subcommand(
      "speed-error", "Each approximation's cost and its error against a reference luxel computes itself, as tables and plots");
  cmd->add_option("--sections", o->sections, "Sections to run, comma-separated (default: all): " + section_names())
      ->delimiter(',');
  cmd->add_option("--probes", o->probes,
                  "Folder searched for .hdr light probes (angular maps, lat-long 2:1); without it the probe rows are skipped");
  cmd->add_option("--normals", o->normals, "Normals (a Fibonacci set) each error is measured over")
      ->check(CLI::Range(6, 1000000))
      ->capture_default_str();
  cmd->add_option("--grid", o->grid, "Rows of the equal-area grid analytic environments are sampled on (x2 columns)")
      ->check(CLI::Range(8, 4096))
      ->capture_default_str();
  cmd->add_option("--scene", o->frame.scene, "Scene the frame sections render: FILE.gltf, FILE.glb or builtin:NAME")
      ->capture_default_str();
  cmd->add_option("--width", o->frame.settings.width, "Width of the frame sections' frames")
      ->check(CLI::Range(1, 8192))
      ->capture_default_str();
  cmd->add_option("--height", o->frame.settings.height, "Height of the frame sections' frames")
      ->check(CLI::Range(1, 8192))
      ->capture_default_str();
  cmd->add_option("--bake", o->frame.bake,
                  "When the scene needs a bake it lacks (kept as `luxel bake` keeps it): full, or quick (a preview in seconds)")
      ->check(CLI::IsMember({"full", "quick"}))
      ->capture_default_str();
  cmd->add_option("--threads", o->frame.threads, "Worker threads of the frame sections (0 = one per core)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  o->frame.memory.add_to(*cmd);
  cmd->add_option("--repeats", o->repeats, "Timing runs per variant (the median is reported)")
      ->check(CLI::Range(1, 101))
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Folder for speed_error.txt, speed_error.json and one PNG per section")->required();
  return [cmd, o]() -> int {
    if (!cmd->parsed()) return -1;
    return run_speed_error(*o);
  };
}

}  // namespace luxel::cli
