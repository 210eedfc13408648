// luxel report speed-error [--sections NAME,...] [--probes DIR] [--normals N] [--grid ROWS]
// [--repeats R] --out DIR: each approximation's cost and its error against a reference luxel
// computes itself (cli/report/report.hpp says what is written; each section's file what it
// measures). The tables also go to stdout; progress to stderr as a live line, on a terminal only.
//
// Exit codes: 2 for bad arguments (an unknown section), 1 for files (a probe that cannot be read,
// an output that cannot be written); one line on stderr each.

#include "commands.hpp"

#include "report/report.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

struct SpeedErrorOptions {
  std::vector<std::string> sections;
  std::string probes = "../shared/assets/hdr";
  std::string out;
  int normals = 1000, grid = 192, repeats = 5;
};

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
  const bool terminal = isatty(STDERR_FILENO);
  ReportSettings settings;
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
  CLI::App* report = app.add_subcommand("report", "Reports on luxel's approximations");
  report->require_subcommand(1);
  CLI::App* cmd = report->add_subcommand(
      "speed-error", "Each approximation's cost and its error against a reference computed in double, as tables and plots");
  cmd->add_option("--sections", o->sections, "Sections to run, comma-separated (default: all): " + section_names())
      ->delimiter(',');
  cmd->add_option("--probes", o->probes, "Folder searched for .hdr light probes (angular maps, lat-long 2:1)")
      ->capture_default_str();
  cmd->add_option("--normals", o->normals, "Normals (a Fibonacci set) each error is measured over")
      ->check(CLI::Range(6, 1000000))
      ->capture_default_str();
  cmd->add_option("--grid", o->grid, "Rows of the equal-area grid analytic environments are sampled on (x2 columns)")
      ->check(CLI::Range(8, 4096))
      ->capture_default_str();
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
