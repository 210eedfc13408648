#pragma once
// The pieces a section's findings (report.hpp) are made of: its rows picked by what they measured,
// a column's values over them, and those values printed as the table prints them. A finding built
// from these states the table's own numbers, and its comparisons are decided by them.

#include "report/report.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace luxel::cli {

/// Which rows of a section a finding speaks of.
using RowTest = std::function<bool(const ReportRow&)>;

/// Every row.
bool any_row(const ReportRow& row);
RowTest variant_is(std::string variant);
RowTest variant_starts_with(std::string prefix);
RowTest scene_is(std::string scene);
/// The rows whose column `key` holds `value` (`r` must outlive the test).
RowTest value_is(const SectionResult& r, std::string key, double value);
/// The rows that pass both tests.
RowTest both(RowTest a, RowTest b);

/// The value of column `key` in `row` of `r`.
double value_of(const SectionResult& r, const ReportRow& row, const std::string& key);

/// The rows of `r` that pass `test`, in table order.
std::vector<const ReportRow*> rows_where(const SectionResult& r, const RowTest& test);

/// The first row of `r` that passes `test`; null when none does.
const ReportRow* first_row(const SectionResult& r, const RowTest& test);

/// The distinct values of `field` (variant, scene...) over the rows that pass `test`, in order of
/// first appearance.
std::vector<std::string> distinct(const SectionResult& r, std::string ReportRow::*field, const RowTest& test);

/// The least and the largest value of a column over some rows.
struct Span {
  double min = 0, max = 0;
};

/// The span of `values`, its non-finite ones (a cost that does not apply, an infinite PSNR) left
/// out; none when no value is left.
std::optional<Span> span_of(const std::vector<double>& values);

/// Column `key` over the rows that pass `test`, as span_of(values).
std::optional<Span> span_of(const SectionResult& r, const std::string& key, const RowTest& test);

/// `v` as the table prints it in column `key`.
std::string text_of(const SectionResult& r, const std::string& key, double v);

/// A span as the table prints it: "A to B", or "A" when both ends print the same.
std::string span_text(const SectionResult& r, const std::string& key, const Span& s);

/// Column `key` of each row that passes `test`, after its variant: "V1 X1; V2 X2" (variants may
/// hold commas).
std::string listing(const SectionResult& r, const std::string& key, const RowTest& test);

/// `count` and its unit, singular when the count prints as "1": "1 step", "3 steps".
std::string counted(const std::string& count, const std::string& one, const std::string& many);

/// How `to` compares to `from`: "down 6.9 %", "up 3.0 %" or "unchanged" (relative, one decimal).
std::string change_text(double from, double to);

/// `a` over `b` with two decimals ("0.40"); "n/a" when `b` is 0.
std::string ratio_text(double a, double b);

}  // namespace luxel::cli
