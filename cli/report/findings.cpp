#include "report/findings.hpp"

#include <algorithm>
#include <cmath>

namespace luxel::cli {

bool any_row(const ReportRow&) { return true; }

RowTest variant_is(std::string variant) {
  return [variant = std::move(variant)](const ReportRow& row) { return row.variant == variant; };
}

RowTest variant_starts_with(std::string prefix) {
  return [prefix = std::move(prefix)](const ReportRow& row) { return row.variant.starts_with(prefix); };
}

RowTest scene_is(std::string scene) {
  return [scene = std::move(scene)](const ReportRow& row) { return row.scene == scene; };
}

RowTest value_is(const SectionResult& r, std::string key, double value) {
  return [&r, key = std::move(key), value](const ReportRow& row) { return value_of(r, row, key) == value; };
}

RowTest both(RowTest a, RowTest b) {
  return [a = std::move(a), b = std::move(b)](const ReportRow& row) { return a(row) && b(row); };
}

double value_of(const SectionResult& r, const ReportRow& row, const std::string& key) { return row.values.at(column_index(r, key)); }

std::vector<const ReportRow*> rows_where(const SectionResult& r, const RowTest& test) {
  std::vector<const ReportRow*> out;
  for (const ReportRow& row : r.rows)
    if (test(row)) out.push_back(&row);
  return out;
}

const ReportRow* first_row(const SectionResult& r, const RowTest& test) {
  const std::vector<const ReportRow*> rows = rows_where(r, test);
  return rows.empty() ? nullptr : rows.front();
}

std::vector<std::string> distinct(const SectionResult& r, std::string ReportRow::*field, const RowTest& test) {
  std::vector<std::string> out;
  for (const ReportRow* row : rows_where(r, test))
    if (std::find(out.begin(), out.end(), row->*field) == out.end()) out.push_back(row->*field);
  return out;
}

std::optional<Span> span_of(const std::vector<double>& values) {
  std::optional<Span> span;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    if (!span) span = Span{v, v};
    span->min = std::min(span->min, v), span->max = std::max(span->max, v);
  }
  return span;
}

std::optional<Span> span_of(const SectionResult& r, const std::string& key, const RowTest& test) {
  std::vector<double> values;
  for (const ReportRow* row : rows_where(r, test)) values.push_back(value_of(r, *row, key));
  return span_of(values);
}

std::string text_of(const SectionResult& r, const std::string& key, double v) { return column_text(r.columns[column_index(r, key)], v); }

std::string span_text(const SectionResult& r, const std::string& key, const Span& s) {
  const std::string lo = text_of(r, key, s.min), hi = text_of(r, key, s.max);
  return lo == hi ? lo : lo + " to " + hi;
}

std::string listing(const SectionResult& r, const std::string& key, const RowTest& test) {
  std::string text;
  for (const ReportRow* row : rows_where(r, test)) text += (text.empty() ? "" : "; ") + row->variant + " " + text_of(r, key, value_of(r, *row, key));
  return text;
}

std::string counted(const std::string& count, const std::string& one, const std::string& many) {
  return count + " " + (count == "1" ? one : many);
}

std::string change_text(double from, double to) {
  if (from == to) return "unchanged";
  if (from == 0) return "up from 0";
  const double percent = 100.0 * (to - from) / std::abs(from);
  return (percent < 0 ? "down " : "up ") + number(std::abs(percent), "%.1f") + " %";
}

std::string ratio_text(double a, double b) { return b == 0 ? "n/a" : number(a / b, "%.2f"); }

}  // namespace luxel::cli
