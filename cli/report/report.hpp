#pragma once
// `luxel report speed-error`: for each approximation luxel makes, its cost and its error against a
// reference luxel computes itself (in double, or a frame drawn without the approximation). The
// report is made of sections (lighting bases, MSAA, shader models, per-vertex lighting, world
// lighting, ambient sampling and popping, tone mapping, color correction, auto exposure, HDR cube
// maps, SIMD against scalar lanes); a section is one small file that measures its rows and says
// how its plot is drawn, and this file writes every section the same way:
//
//   DIR/speed_error.txt   the tables, one per section, with the notes and references under them
//                         and the section's findings last, each on a line starting "finding: "
//   DIR/speed_error.json  the same rows (cost, timing and error apart), each plot's points and
//                         each section's "findings"
//   DIR/<section>.png     cost on x, error on y, one labeled marker per row, a color per variant
//
// Findings: what a section's numbers show, as sentences the section computes from its own rows
// once they are measured (findings.hpp picks and formats the values), never typed in: numbers are
// printed as the table prints them and every comparison's wording follows the values, so the
// findings cannot go stale when the code or the machine changes what the rows hold.
//
// Determinism: everything but the `timing` values of the rows is the same on every run on the same
// machine (the CPU's name is printed, not measured), so plots take their x from a cost column,
// never from a timing.

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace luxel::cli {

struct ReportScene;  // report_scene.hpp

/// What a section is measured with: command-line settings shared by every section.
struct ReportSettings {
  std::string probes;        ///< folder searched (recursively) for .hdr light probes
  int normals = 1000;        ///< normals (a Fibonacci set) each error is measured over
  int grid_rows = 192;       ///< rows of the equal-area grid analytic environments are sampled on
  int timing_repeats = 5;    ///< timing runs per variant; the median is reported
  std::function<void(const std::string&)> progress;  ///< one line per slow step (stderr)
  /// The scene the frame sections render (--scene, prepared by the command when a chosen section
  /// renders frames); null otherwise.
  const ReportScene* scene = nullptr;
};

/// What a column holds, which decides where it goes in the JSON ("cost", "timing", "error").
enum class ColumnKind { cost, timing, error };

struct ReportColumn {
  std::string key;      ///< the JSON name: "slots", "max_relative"...
  std::string header;   ///< the text table's
  ColumnKind kind;
  std::string format;   ///< printf format of one value in the text table ("%.3f")
  double text_scale = 1.0;  ///< the text shows value x scale (100 for a fraction shown as %)
};

struct ReportRow {
  std::string scene;       ///< what was measured: an environment, a scene
  std::string resolution;  ///< of the scene or image ("1000x1000 angular map", "analytic")
  std::string variant;     ///< the approximation; one plot series per variant
  std::string label;       ///< the row's short name beside its marker in the plot
  std::string reference;   ///< how the reference the error is measured against was computed
  std::vector<double> values;  ///< one per column of the section, in column order
};

/// The plot of a section: x from a cost column, y from an error column.
struct ReportPlot {
  std::string title, x_label, y_label;
  std::string x_key, y_key;  ///< column keys
  double y_scale = 1.0;      ///< y plotted is the value x y_scale (100: a fraction as %)
  bool log_y = false;
};

struct SectionResult {
  std::string title;                ///< a line saying what the section compares
  std::vector<std::string> notes;   ///< lines printed under the table (skipped inputs, reproductions)
  std::vector<ReportColumn> columns;
  std::vector<ReportRow> rows;
  ReportPlot plot;
  nlohmann::json details;  ///< anything else the section states (null: nothing)
  /// What the rows show, computed from them (findings.hpp): printed after the table, notes and
  /// plot line as "finding: ..." lines and written to the JSON as "findings". Empty when there is
  /// nothing to compare (no rows).
  std::vector<std::string> findings;
};

struct ReportSection {
  std::string name;     ///< `--sections` picks it by this; also its PNG's name
  std::string summary;  ///< for --help
  std::function<SectionResult(const ReportSettings&)> run;
  bool renders_frames = false;  ///< needs ReportSettings::scene
};

/// `v` through printf format `format` ("%.2f"): a number in a row's text or a note.
std::string number(double v, const char* format);

/// The index of the column keyed `key` in `r.columns`; throws std::logic_error when there is none
/// (a section asking for a column it does not have is a bug of the section).
size_t column_index(const SectionResult& r, const std::string& key);

/// `v` as the table prints it in column `c`: through its format, times its text scale.
std::string column_text(const ReportColumn& c, double v);

/// Every section, in report order.
const std::vector<ReportSection>& report_sections();

/// Writes DIR/speed_error.txt, DIR/speed_error.json and DIR/<name>.png for the sections' results
/// (in the order given) and returns the text (what the command prints). Throws
/// std::runtime_error "PATH: problem" when a file cannot be written.
std::string write_report(const std::string& dir, const std::vector<std::pair<std::string, SectionResult>>& results);

}  // namespace luxel::cli
