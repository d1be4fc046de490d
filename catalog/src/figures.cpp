#include "figures.hpp"

#include "koppel/core/angles.hpp"

#include <cmath>
#include <cstdio>

namespace koppel {

int OutputColumn(const Mechanism& m, const std::string& name, int component, int k, int order) {
  int column = 0;
  for (const koppel::Output& o : m.outputs) {
    if (o.name == name) return column + component * (order + 1) + k;
    column += o.Components() * (order + 1);
  }
  return -1;
}

int FigureContext::Output(const FigureCheck& f) const {
  const int output = mechanism().FindOutput(f.output);
  if (output < 0) Fail(f, "names no output '" + f.output + "'");
  return output;
}

void FigureContext::Fail(const FigureCheck& f, const std::string& message) const {
  throw InputError({Diagnostic{file_.path, f.line, 0, "catalog.figures." + f.name, message}});
}

bool FigureContext::Has(const FigureCheck& f, const char* argument) const { return f.args.count(argument) > 0; }

double FigureContext::Number(const FigureCheck& f, const char* argument) const {
  const auto it = f.args.find(argument);
  if (it == f.args.end()) Fail(f, std::string("missing argument '") + argument + "'");
  const Expected<double> v = file_.parameters.Evaluate(it->second);
  if (!v) Fail(f, std::string(argument) + ": " + v.error());
  return *v;
}

double FigureContext::Input(const FigureCheck& f, const char* argument) const {
  const double v = Number(f, argument);
  return mechanism().InputIsAngle() ? DegToRad(v) : v;
}

int FigureContext::Order(const FigureCheck& f, const char* argument) const {
  return static_cast<int>(Number(f, argument));  // the reader made sure it is a whole number 1..8
}

int FigureContext::Joint(const FigureCheck& f, const char* argument) const {
  const auto it = f.args.find(argument);
  if (it == f.args.end()) Fail(f, std::string("missing argument '") + argument + "'");
  const int joint = mechanism().FindJoint(it->second);
  if (joint < 0) Fail(f, "names no joint '" + it->second + "'");
  return joint;
}

SweepOptions FigureContext::CardRange() const {
  const bool angle = mechanism().InputIsAngle();
  SweepOptions options;
  options.from = angle ? DegToRad(card_.from) : card_.from;
  options.to = angle ? DegToRad(card_.to) : card_.to;
  options.step = angle ? DegToRad(card_.step) : card_.step;
  options.order = 0;
  return options;
}

const SweepResult& FigureContext::RangeSweep(const FigureCheck& f) {
  SweepOptions options = CardRange();
  if (Has(f, "from")) options.from = Input(f, "from");
  if (Has(f, "to")) options.to = Input(f, "to");
  std::unique_ptr<SweepResult>& cached = sweeps_[{options.from, options.to}];
  if (!cached) cached = std::make_unique<SweepResult>(Sweep(mechanism(), options));
  return *cached;
}

const DeadCentreReport& FigureContext::DeadCentres(int output, int component) {
  std::unique_ptr<DeadCentreReport>& cached = dead_centres_[{output, component}];
  if (!cached) cached = std::make_unique<DeadCentreReport>(FindDeadCentres(mechanism(), output, component, CardRange()));
  return *cached;
}

namespace {
std::string FormatShort(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}
}  // namespace

const RangeReport& FigureContext::Ranges() {
  if (!ranges_) ranges_ = std::make_unique<RangeReport>(DrivableRanges(mechanism()));
  return *ranges_;
}

const StraightStretch& FigureContext::LongestStretch(int output, double qg, std::optional<double> at) {
  std::unique_ptr<StraightStretch>& cached = stretches_[{output, qg, at}];
  // the search range and resolution of seed 003's reading example: half a turn either way, 0.02 deg
  if (!cached) cached = std::make_unique<StraightStretch>(LongestStraightStretch(mechanism(), mechanism().outputs[output].p, qg, at, kPi, DegToRad(0.02)));
  return *cached;
}

bool FigureApplies(const FigureCheck& figure, const std::string& variant) {
  return figure.variant.empty() || figure.variant == variant;
}

CheckOutcome EvaluateFigure(FigureContext& context, const FigureCheck& f, const std::string& variant) {
  CheckOutcome out;
  out.variant = variant;
  out.name = f.name;
  out.kind = CheckKind::kFigure;
  out.tolerance = f.tolerance;
  out.detail = f.note;
  const Expected<double> expected = context.file().parameters.Evaluate(f.expected);
  if (!expected) context.Fail(f, "expected value: " + expected.error());

  const FigureValue result = QuantityInfo(f.quantity).evaluate(context, f);
  if (!result.value) {
    out.status = CheckStatus::kNotComputed;
    out.detail = result.why_not;
    return out;
  }
  // koppel's value in the figure's unit: degrees when the figure is an angle given in degrees
  out.value = f.degrees ? RadToDeg(*result.value) : *result.value;
  // an angle position is the same modulo a turn (a maximum at 360 deg is the one at 0)
  const bool periodic = f.degrees && QuantityInfo(f.quantity).angle == AngleKind::kPosition;
  out.worst = periodic ? std::abs(std::remainder(out.value - *expected, 360.0)) : std::abs(out.value - *expected);
  out.status = out.worst <= f.tolerance ? CheckStatus::kPassed : CheckStatus::kFailed;
  if (!out.passed()) out.detail = "document " + FormatShort(*expected) + ", koppel " + FormatShort(out.value);
  return out;
}

}  // namespace koppel
