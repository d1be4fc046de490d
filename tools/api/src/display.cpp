#include "display.hpp"

#include "koppel/core/angles.hpp"

#include <cmath>
#include <limits>

namespace koppel::api_detail {

void DisplayRow(const Mechanism& m, const SweepColumns& layout, double input, const double* outputs, int valid_order, bool singular,
                double* row) {
  const size_t width = layout.names.size();
  row[0] = InputShown(m, input);
  for (size_t c = 1; c + 1 < width; ++c) {
    const double v = outputs[c - 1];
    row[c] = layout.order_of_column[c] > valid_order ? std::numeric_limits<double>::quiet_NaN()
             : layout.angle_value[c]                 ? RadToDeg(v)
                                                     : v;
  }
  row[width - 1] = singular ? 1.0 : 0.0;
}

double InputShown(const Mechanism& m, double input) { return m.InputIsAngle() ? RadToDeg(input) : input; }
double InputInternal(const Mechanism& m, double input) { return m.InputIsAngle() ? DegToRad(input) : input; }

std::vector<SingularPosition> Shown(const Mechanism& m, const std::vector<SingularPoint>& points) {
  std::vector<SingularPosition> shown;
  for (const SingularPoint& p : points) {
    SingularPosition s;
    s.kind = ToString(p.kind);
    s.input = InputShown(m, p.input);
    s.rcond = p.rcond;
    for (int j : p.joints) s.joints.push_back(m.joints[j].name);
    s.action = ToString(p.action);
    shown.push_back(std::move(s));
  }
  return shown;
}

std::vector<InputGap> Shown(const Mechanism& m, const std::vector<InputInterval>& gaps) {
  std::vector<InputGap> shown;
  for (const InputInterval& g : gaps) shown.push_back({InputShown(m, g.from), InputShown(m, g.to)});
  return shown;
}

AnalysisStatus FromSweep(SweepStatus status) {
  switch (status) {
    case SweepStatus::kComplete: return AnalysisStatus::kComplete;
    case SweepStatus::kPartial: return AnalysisStatus::kPartial;
    case SweepStatus::kNotRun: return AnalysisStatus::kNotRun;
    default: return AnalysisStatus::kFailed;
  }
}

SweepRecord Shown(const Mechanism& m, const SweepEvents& events) {
  SweepRecord r;
  r.status = FromSweep(events.status);
  r.message = events.message;
  r.notes = events.notes;
  r.singular_points = Shown(m, events.singular_points);
  r.gaps = Shown(m, events.gaps);
  r.reached = {InputShown(m, events.reached.from), InputShown(m, events.reached.to)};
  for (double input : events.singular_inputs) r.singular_inputs.push_back(InputShown(m, input));
  return r;
}

void BadInput(const std::string& file, const std::string& field, const std::string& message) {
  throw InputError({Diagnostic{file, 0, 0, field, message}});
}

}  // namespace koppel::api_detail
