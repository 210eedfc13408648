#include "report/report.hpp"

#include "line_plot.hpp"

#include "luxel/rasterizer/cpu_model.hpp"
#include "luxel/rasterizer/simd.hpp"
#include "luxel/scenes/image_io.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace luxel::cli {

std::string number(double v, const char* format) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string column_text(const ReportColumn& c, double v) { return number(v * c.text_scale, c.format.c_str()); }

size_t column_index(const SectionResult& r, const std::string& key) {
  for (size_t i = 0; i < r.columns.size(); ++i)
    if (r.columns[i].key == key) return i;
  throw std::logic_error("report: a section asks for column '" + key + "', which it does not have");
}

namespace {

/// Series colors in order of first appearance: distinct on the plot's dark ground.
constexpr std::array<std::array<uint8_t, 3>, 6> kPalette = {{
    {255, 170, 60}, {90, 190, 255}, {140, 230, 120}, {235, 110, 200}, {240, 230, 100}, {200, 200, 200}}};

std::string lanes_line() {
  return std::string(rasterizer::simd::kIsaName) + ", " + std::to_string(rasterizer::simd::kLanes) + " floats per SIMD lane";
}

const char* kind_key(ColumnKind k) {
  switch (k) {
    case ColumnKind::cost: return "cost";
    case ColumnKind::timing: return "timing";
    case ColumnKind::error: return "error";
  }
  return "?";
}

/// The references of a section in order of first use: row i's is "R" + (index + 1).
std::vector<std::string> references_of(const SectionResult& r) {
  std::vector<std::string> refs;
  for (const ReportRow& row : r.rows)
    if (std::find(refs.begin(), refs.end(), row.reference) == refs.end()) refs.push_back(row.reference);
  return refs;
}

std::string ref_key(const std::vector<std::string>& refs, const std::string& reference) {
  return "R" + std::to_string(std::find(refs.begin(), refs.end(), reference) - refs.begin() + 1);
}

/// The plot as series, one per variant in order of first appearance; a row without a finite x or
/// y (a cost that does not apply to it) has no point, and a variant without one no series.
LinePlot plot_of(const SectionResult& r) {
  LinePlot plot;
  plot.width = 1000, plot.height = 600;  // room for a label per point
  plot.title = r.plot.title, plot.x_label = r.plot.x_label, plot.y_label = r.plot.y_label, plot.log_y = r.plot.log_y;
  const size_t x = column_index(r, r.plot.x_key), y = column_index(r, r.plot.y_key);
  for (const ReportRow& row : r.rows) {
    if (!std::isfinite(row.values[x]) || !std::isfinite(row.values[y] * r.plot.y_scale)) continue;
    auto it = std::find_if(plot.series.begin(), plot.series.end(), [&](const PlotSeries& s) { return s.name == row.variant; });
    if (it == plot.series.end()) {
      PlotSeries s;
      s.name = row.variant;
      s.rgb = kPalette[plot.series.size() % kPalette.size()];
      s.style = PlotStyle::markers;
      plot.series.push_back(s);
      it = plot.series.end() - 1;
    }
    it->points.emplace_back(row.values[x], row.values[y] * r.plot.y_scale);
    it->labels.push_back(row.label);
  }
  return plot;
}

std::string table_text(const std::string& name, const SectionResult& r) {
  const std::vector<std::string> refs = references_of(r);
  std::vector<std::string> header = {"scene", "resolution", "variant"};
  for (const ReportColumn& c : r.columns) header.push_back(c.header);
  header.push_back("ref");
  std::vector<std::vector<std::string>> cells = {header};
  for (const ReportRow& row : r.rows) {
    std::vector<std::string> line = {row.scene, row.resolution, row.variant};
    for (size_t i = 0; i < r.columns.size(); ++i) line.push_back(column_text(r.columns[i], row.values[i]));
    line.push_back(ref_key(refs, row.reference));
    cells.push_back(line);
  }
  std::vector<size_t> width(header.size(), 0);
  for (const auto& line : cells)
    for (size_t i = 0; i < line.size(); ++i) width[i] = std::max(width[i], line[i].size());
  std::string out = "== " + name + ": " + r.title + "\n";
  for (const auto& line : cells) {
    std::string text;
    for (size_t i = 0; i < line.size(); ++i) {
      const bool left = i < 3;  // names left, numbers right
      const std::string pad(width[i] - line[i].size(), ' ');
      text += (i ? " | " : "") + (left ? line[i] + pad : pad + line[i]);
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    out += text + "\n";
  }
  for (size_t i = 0; i < refs.size(); ++i) out += "R" + std::to_string(i + 1) + ": " + refs[i] + "\n";
  for (const std::string& note : r.notes) out += note + "\n";
  out += "plot: " + name + ".png (" + r.plot.y_label + " against " + r.plot.x_label + ")\n";
  for (const std::string& finding : r.findings) out += "finding: " + finding + "\n";
  return out;
}

nlohmann::json section_json(const std::string& name, const SectionResult& r, const std::string& cpu) {
  nlohmann::json s = {{"name", name}, {"title", r.title}, {"notes", r.notes}};
  s["columns"] = nlohmann::json::array();
  for (const ReportColumn& c : r.columns) s["columns"].push_back({{"key", c.key}, {"header", c.header}, {"kind", kind_key(c.kind)}});
  s["rows"] = nlohmann::json::array();
  for (const ReportRow& row : r.rows) {
    nlohmann::json j = {{"scene", row.scene},       {"resolution", row.resolution}, {"variant", row.variant},
                        {"label", row.label},       {"reference", row.reference},   {"cpu", cpu},
                        {"cost", nlohmann::json::object()}, {"timing", nlohmann::json::object()},
                        {"error", nlohmann::json::object()}};
    for (size_t i = 0; i < r.columns.size(); ++i) j[kind_key(r.columns[i].kind)][r.columns[i].key] = row.values[i];
    s["rows"].push_back(j);
  }
  const LinePlot plot = plot_of(r);
  nlohmann::json series = nlohmann::json::array();
  for (const PlotSeries& ps : plot.series) {
    nlohmann::json points = nlohmann::json::array();
    for (size_t i = 0; i < ps.points.size(); ++i)
      points.push_back({{"label", ps.labels[i]}, {"x", ps.points[i].first}, {"y", ps.points[i].second}});
    series.push_back({{"name", ps.name}, {"points", points}});
  }
  s["plot"] = {{"file", name + ".png"}, {"width", plot.width}, {"height", plot.height}, {"title", plot.title}, {"x_label", plot.x_label}, {"y_label", plot.y_label},
               {"log_y", plot.log_y}, {"series", series}};
  s["findings"] = r.findings;
  if (!r.details.is_null()) s["details"] = r.details;
  return s;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f.flush()) throw std::runtime_error(path + ": cannot write it");
}

}  // namespace

std::string write_report(const std::string& dir, const std::vector<std::pair<std::string, SectionResult>>& results) {
  const std::string cpu = rasterizer::cpu_model();
  std::string text = "luxel report speed-error\ncpu: " + cpu + "\nlanes: " + lanes_line() +
                     "\ntimings vary from run to run and with the machine's load; everything else is the same on every run\n";
  nlohmann::json json = {{"report", "speed-error"}, {"cpu", cpu}, {"lanes", lanes_line()}, {"sections", nlohmann::json::array()}};
  for (const auto& [name, r] : results) {
    text += "\n" + table_text(name, r);
    json["sections"].push_back(section_json(name, r, cpu));
    const rasterizer::Image image = draw_line_plot(plot_of(r));
    scenes::write_image(image.width, image.height, image.rgba, dir + "/" + name + ".png");
  }
  write_text(dir + "/speed_error.txt", text);
  write_text(dir + "/speed_error.json", json.dump(2) + "\n");
  return text;
}

}  // namespace luxel::cli
