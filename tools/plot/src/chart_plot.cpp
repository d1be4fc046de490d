// The design charts (Kurventafeln) of seed 002 from the CSV of `koppel synth chart`: curve
// families over φ0, one curve per value of the family parameter, labelled.
#include "koppel/plot/plots.hpp"
#include "koppel/core/expected.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

namespace koppel::plot {
namespace {

// At most this many curves of one family are drawn (evenly picked), so the legend stays legible.
constexpr size_t kMaxFamily = 9;

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  int Column(const std::string& name) const {
    const auto it = std::find(columns.begin(), columns.end(), name);
    return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
  }
};

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

Expected<CsvTable> ParseCsv(const std::string& text, const std::string& file) {
  CsvTable table;
  std::stringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const auto cells = SplitCsvLine(line);
    if (table.columns.empty()) {
      table.columns = cells;
      continue;
    }
    if (cells.size() != table.columns.size()) {
      return Expected<CsvTable>::Error(file + ":" + std::to_string(number) + ": " + std::to_string(cells.size()) +
                                       " cells, the header has " + std::to_string(table.columns.size()));
    }
    // `synth chart` writes a row for every grid point; without a design (status none, boundary,
    // failed) its numbers are empty: such a row is a gap. The rocker sense is a word: same = 1,
    // opposite = -1.
    const int status = table.Column("status"), sense = table.Column("rocker_sense");
    if (status >= 0 && cells[status] != "ok") continue;
    std::vector<double> row;
    for (size_t c = 0; c < cells.size(); ++c) {
      if (static_cast<int>(c) == status) {
        row.push_back(1);
        continue;
      }
      if (static_cast<int>(c) == sense && (cells[c] == "same" || cells[c] == "opposite")) {
        row.push_back(cells[c] == "same" ? 1 : -1);
        continue;
      }
      char* end = nullptr;
      const double v = std::strtod(cells[c].c_str(), &end);
      if (cells[c].empty() || *end != '\0' || !std::isfinite(v)) {
        return Expected<CsvTable>::Error(file + ":" + std::to_string(number) + ": column '" + table.columns[c] +
                                         "': not a number: '" + cells[c] + "'");
      }
      row.push_back(v);
    }
    table.rows.push_back(std::move(row));
  }
  if (table.columns.empty() || table.rows.empty()) {
    return Expected<CsvTable>::Error(file + ": no table (a header line and at least one row expected)");
  }
  return table;
}

// Points (x, y) sorted by x, split where a grid value of x is missing (a design that did not
// exist there): a gap is never bridged.
std::vector<std::vector<Eigen::Vector2d>> GridRuns(std::vector<Eigen::Vector2d> points, double grid_step) {
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.x() < b.x(); });
  std::vector<std::vector<Eigen::Vector2d>> runs;
  for (size_t i = 0; i < points.size(); ++i) {
    if (i == 0 || points[i].x() - points[i - 1].x() > 1.5 * grid_step) runs.emplace_back();
    runs.back().push_back(points[i]);
  }
  return runs;
}

double GridStep(const std::vector<double>& values) {
  std::vector<double> v = values;
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  double step = 0;
  for (size_t i = 1; i < v.size(); ++i) step = step == 0 ? v[i] - v[i - 1] : std::min(step, v[i] - v[i - 1]);
  return step == 0 ? 1 : step;
}

std::string FormatValue(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", v);
  return s;
}

// A panel of `y` over phi0; with `family` >= 0 one curve per distinct value of that column.
Panel FamilyPanel(const CsvTable& t, int phi0, int y, int family, const std::string& family_label, const std::string& y_label) {
  Panel panel;
  panel.title = y_label;
  std::vector<double> xs, ys;
  for (const auto& r : t.rows) xs.push_back(r[phi0]), ys.push_back(r[y]);
  const double step = GridStep(xs);
  std::vector<double> members = {0};
  if (family >= 0) {
    std::vector<double> all;
    for (const auto& r : t.rows) all.push_back(r[family]);
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    members.clear();
    const size_t n = std::min(kMaxFamily, all.size());
    for (size_t i = 0; i < n; ++i) members.push_back(all[n == 1 ? 0 : i * (all.size() - 1) / (n - 1)]);
  }
  for (size_t k = 0; k < members.size(); ++k) {
    const double member = members[k];
    std::vector<Eigen::Vector2d> points;
    for (const auto& r : t.rows)
      if (family < 0 || r[family] == member) points.emplace_back(r[phi0], r[y]);
    Curve c;
    c.name = family < 0 ? "" : family_label + " = " + FormatValue(member) + "°";
    // a family is ordered: a ramp gives each member its own colour, in the members' order
    if (family >= 0) c.stroke = RampColour(members.size() == 1 ? 0.0 : static_cast<double>(k) / static_cast<double>(members.size() - 1));
    c.runs = GridRuns(points, step);
    panel.curves.push_back(std::move(c));
  }
  panel.x = NiceAxis("φ0 [deg]", *std::min_element(xs.begin(), xs.end()), *std::max_element(xs.begin(), xs.end()), true);
  panel.y = NiceAxis(y_label, *std::min_element(ys.begin(), ys.end()), *std::max_element(ys.begin(), ys.end()));
  return panel;
}

}  // namespace

PlotResult ChartPlot(const std::string& csv_text, const std::string& file_name) {
  const Expected<CsvTable> parsed = ParseCsv(csv_text, file_name);
  if (!parsed) return {PlotStatus::kFailed, parsed.error(), ""};
  const CsvTable& t = *parsed;
  Figure figure;
  const int phi0 = t.Column("phi0");
  if (const int sense = t.Column("rocker_sense"); sense >= 0) {
    const bool mixed = std::any_of(t.rows.begin(), t.rows.end(), [&](const auto& r) { return r[sense] != t.rows.front()[sense]; });
    if (mixed) return {PlotStatus::kFailed, file_name + ": both rocker senses in one chart: plot one (synth chart --rocker-sense same or opposite)", ""};
  }
  if (phi0 >= 0 && t.Column("psi0") >= 0 && t.Column("beta") >= 0 && t.Column("mu_min") >= 0) {
    figure.title = "Crank-rocker design chart (dead-centre synthesis): max μ_min, best β";
    figure.panels.push_back(FamilyPanel(t, phi0, t.Column("mu_min"), t.Column("psi0"), "ψ0", "max μ_min [deg]"));
    figure.panels.push_back(FamilyPanel(t, phi0, t.Column("beta"), t.Column("psi0"), "ψ0", "β [deg]"));
  } else if (phi0 >= 0 && t.Column("e_s0") >= 0 && t.Column("l1_s0") >= 0 && t.Column("l2_s0") >= 0 && t.Column("mu_min") >= 0) {
    figure.title = "Slider-crank design chart (dead-centre synthesis): sizes, max μ_min";
    Panel sizes = FamilyPanel(t, phi0, t.Column("e_s0"), -1, "", "dimension / s0");
    double low = sizes.y.min, high = sizes.y.max;
    int colour = 0;
    sizes.curves.front().name = "e/s0";
    for (const char* column : {"l1_s0", "l2_s0"}) {
      Panel other = FamilyPanel(t, phi0, t.Column(column), -1, "", "");
      other.curves.front().name = column == std::string("l1_s0") ? "l1/s0" : "l2/s0";
      other.curves.front().colour = ++colour;
      low = std::min(low, other.y.min), high = std::max(high, other.y.max);
      sizes.curves.push_back(std::move(other.curves.front()));
    }
    sizes.y = NiceAxis("dimension / s0", low, high);
    figure.panels.push_back(std::move(sizes));
    figure.panels.push_back(FamilyPanel(t, phi0, t.Column("mu_min"), -1, "", "max μ_min [deg]"));
  } else {
    return {PlotStatus::kFailed,
            file_name + ":1: not a design chart of `koppel synth chart` (expected columns phi0, psi0, beta, mu_min or phi0, e_s0, "
                        "l1_s0, l2_s0, mu_min)",
            ""};
  }
  return {PlotStatus::kComplete, "", RenderFigure(figure)};
}

}  // namespace koppel::plot
