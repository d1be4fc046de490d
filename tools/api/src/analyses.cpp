// The analyses of a Model: sweep, dead centres, drivable ranges, in the API's units.
#include "koppel/api/model.hpp"

#include "display.hpp"
#include "scalar_output.hpp"

#include "koppel/analysis/dead_centres.hpp"
#include "koppel/analysis/ranges.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace koppel {

using namespace api_detail;

static_assert(kMaxTransferOrder == kMaxOrder, "the API's order limit is the solver's");

namespace {

// The sweep options in the solver's units; InputError for a range that cannot be sampled.
SweepOptions Options(const Model& model, double from, double to, double step, int order, AtBranchPoint action) {
  const Mechanism& m = model.mechanism();
  if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(step) || step == 0)
    BadInput(model.path(), "from/to/step", "the range needs finite from and to and a step that is not 0");
  if (SampleCount(from, to, step) > static_cast<double>(kMaxSweepSamples))
    BadInput(model.path(), "from/to/step", "more than kMaxSweepSamples (" + std::to_string(kMaxSweepSamples) + ") samples");
  SweepOptions options;
  options.from = InputInternal(m, from);
  options.to = InputInternal(m, to);
  options.step = InputInternal(m, step);
  options.order = order;
  options.continuation.at_branch_point = action;
  if (std::string why; !options.IsValid(&why)) BadInput(model.path(), "from/to/step/order", why);
  return options;
}

std::string Plural(size_t n, const std::string& word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

}  // namespace

int api_detail::ScalarOutput(const Model& model, const std::string& output) {
  const Mechanism& m = model.mechanism();
  int index = -1;
  for (int o = 0; o < static_cast<int>(m.outputs.size()) && index < 0; ++o) {
    if (output.empty() ? m.outputs[o].Components() == 1 : m.outputs[o].name == output) index = o;
  }
  if (index < 0 || m.outputs[index].Components() != 1)
    BadInput(model.path(), "output", output.empty() ? "the mechanism has no scalar output" : "'" + output + "' is not a scalar output");
  return index;
}

int SweepTable::ColumnIndex(const std::string& name) const {
  for (size_t c = 0; c < columns.size(); ++c) {
    if (columns[c] == name) return static_cast<int>(c);
  }
  return -1;
}

std::vector<double> SweepTable::Column(const std::string& name) const {
  const int c = ColumnIndex(name);
  if (c < 0) BadInput("sweep table", "column", "no column '" + name + "'");
  std::vector<double> column(rows);
  for (int r = 0; r < rows; ++r) column[r] = At(r, c);
  return column;
}

std::string SweepTable::Brief() const {
  return std::string(ToString(status)) + ": " + Plural(rows, "row") + ", " + Plural(singular_points.size(), "singular point") + ", " +
         Plural(gaps.size(), "gap") + (message.empty() ? "" : "; " + message);
}

double PoseResult::Get(const std::string& name) const {
  for (size_t c = 0; c < columns.size() && c < values.size(); ++c) {
    if (columns[c] == name) return values[c];
  }
  BadInput("pose", "column", values.empty() ? "the pose was not found: " + message : "no column '" + name + "'");
}

std::string PoseResult::Brief() const {
  return std::string(ToString(status)) + " at " + std::to_string(input) + (singular ? " (singular)" : "") +
         (message.empty() ? "" : "; " + message);
}

std::string DeadCentres::Brief() const {
  return std::string(ToString(status)) + ": " + Plural(points.size(), "dead centre") +
         (has_stroke ? ", stroke " + std::to_string(stroke) : "") + (message.empty() ? "" : "; " + message);
}

std::string Ranges::Brief() const {
  return std::string(ToString(status)) + ": " + Plural(branches.size(), "branch") + (message.empty() ? "" : "; " + message);
}

namespace {

// A sweep's table without its rows, then every row in the API's units handed to `emit` (one
// buffer, reused): cells above a row's valid order, and cells an output has no number for (not
// differentiable there), are NaN.
template <class Emit>
SweepTable SweepRows(const Model& model, double from, double to, double step, int order, AtBranchPoint action, Emit&& emit) {
  const Mechanism& m = model.mechanism();
  SweepOptions options = Options(model, from, to, step, order, action);
  options.poses = false;  // a table shows the outputs
  const SweepResult result = koppel::Sweep(m, options);
  const SweepColumns layout = SweepLayout(m, order, model.length_unit());
  SweepTable t;
  t.status = FromSweep(result.status);
  t.message = result.message;
  if (!result.undefined.empty() && t.status == AnalysisStatus::kComplete) t.status = AnalysisStatus::kPartial;  // cells missing
  t.notes = result.notes;
  t.order = order;
  t.columns = layout.names;
  t.units = layout.units;
  t.rows = static_cast<int>(result.inputs.size());
  t.valid_order.assign(result.valid_order.begin(), result.valid_order.end());
  t.singular_points = Shown(m, result.singular_points);
  t.gaps = Shown(m, result.gaps);
  t.record = Shown(m, EventsOf(result));
  t.sweep_status = ToString(result.status);
  std::vector<double> row(t.columns.size());
  auto undefined = result.undefined.begin();  // ascending by row
  for (int i = 0; i < t.rows; ++i) {
    DisplayRow(m, layout, result.inputs[i], result.outputs.row(i).data(), result.valid_order[i], result.singular[i] != 0, row.data());
    for (; undefined != result.undefined.end() && undefined->row == i; ++undefined)
      row[undefined->column + 1] = std::numeric_limits<double>::quiet_NaN();
    emit(t, i, row.data());
  }
  return t;
}

}  // namespace

SweepTable Model::Sweep(double from, double to, double step, int order, AtBranchPoint action) const {
  std::vector<double> values;
  SweepTable t = SweepRows(*this, from, to, step, order, action, [&](const SweepTable& table, int i, const double* row) {
    if (i == 0) values.reserve(static_cast<size_t>(table.rows) * table.columns.size());
    values.insert(values.end(), row, row + table.columns.size());
  });
  t.values = std::move(values);
  return t;
}

SweepTable Model::Sweep(double from, double to, double step, int order, AtBranchPoint action, const SweepRowSink& each_row) const {
  return SweepRows(*this, from, to, step, order, action, each_row);
}

SweepTable Model::Sweep(int order) const { return Sweep(sweep_from(), sweep_to(), sweep_step(), order); }

DeadCentres Model::FindDeadCentres(const std::string& output, std::optional<double> from, std::optional<double> to,
                                   std::optional<double> step, AtBranchPoint action) const {
  const Mechanism& m = mechanism();
  const int index = ScalarOutput(*this, output);
  const SweepOptions range = Options(*this, from.value_or(sweep_from()), to.value_or(sweep_to()), step.value_or(1.0), 2, action);
  const DeadCentreReport r = koppel::FindDeadCentres(m, index, 0, range);
  const bool angle_out = m.OutputIsAngle(index);
  auto value = [&](double v) { return angle_out ? RadToDeg(v) : v; };
  DeadCentres d;
  d.status = r.status;
  d.message = r.message.empty() ? r.sweep.message : r.message;
  for (const DeadCentre& p : r.points) d.points.push_back({ToString(p.kind), InputShown(m, p.input), value(p.value), p.second});
  d.has_stroke = r.has_stroke;
  if (r.has_stroke) {
    d.input_a = InputShown(m, r.phi_a);
    d.input_i = InputShown(m, r.phi_i);
    d.value_a = value(r.s_a);
    d.value_i = value(r.s_i);
    d.stroke = value(r.stroke);
    d.forward_angle = m.InputIsAngle() ? RadToDeg(r.phi_h) : 0.0;
    d.phase_ratio = m.InputIsAngle() ? r.phase_ratio : 0.0;
    d.time_ratio = m.InputIsAngle() ? r.TimeRatio() : 0.0;
  }
  d.has_extremes = Usable(r.extremes.status);
  d.extremes_message = r.extremes.message;
  if (d.has_extremes) {
    d.minimum = {ToString(r.extremes.minimum.kind), InputShown(m, r.extremes.minimum.input), value(r.extremes.minimum.value)};
    d.maximum = {ToString(r.extremes.maximum.kind), InputShown(m, r.extremes.maximum.input), value(r.extremes.maximum.value)};
  }
  for (double input : r.unresolved) d.unresolved.push_back(InputShown(m, input));
  d.singular_points = Shown(m, r.sweep.singular_points);
  d.gaps = Shown(m, r.sweep.gaps);
  d.output = m.outputs[index].name;
  d.transmission_angle = m.outputs[index].kind == OutputKind::kTransmissionAngle;
  d.classified = r.classified;
  d.search_message = r.message;
  d.extremes_status = r.extremes.status;
  d.sweep = Shown(m, r.sweep);
  return d;
}

Ranges Model::DrivableRanges(bool all_branches, AtBranchPoint action) const {
  const Mechanism& m = mechanism();
  RangeOptions options;
  options.all_branches = all_branches;
  options.continuation.at_branch_point = action;
  const RangeReport report = koppel::DrivableRanges(m, options);
  Ranges r;
  r.message = report.message;
  r.notes = report.notes;
  r.walked = report.status == RangeStatus::kDone;
  r.status = report.status == RangeStatus::kDone && !report.HasFailure() ? AnalysisStatus::kComplete : AnalysisStatus::kFailed;
  if (report.status == RangeStatus::kDone && report.HasFailure() && r.message.empty()) r.message = "a walk failed: see the branches' messages";
  for (const BranchRange& b : report.branches) {
    BranchInterval i;
    i.branch = b.branch;
    i.from = InputShown(m, b.from);
    i.to = InputShown(m, b.to);
    i.from_kind = ToString(b.from_kind);
    i.to_kind = ToString(b.to_kind);
    i.period = b.period > 0 ? InputShown(m, b.period) : 0.0;
    i.singular_points = Shown(m, b.singular_points);
    i.message = b.message;
    r.branches.push_back(std::move(i));
  }
  return r;
}

std::vector<SingularPosition> Model::SingularPositions() const { return Sweep(0).singular_points; }

}  // namespace koppel
