// Model::Tolerances: the analysis library's tolerance stack-up in the API's units, with the
// builder that reads the model's file again with the toleranced parameters set.
#include "koppel/api/model.hpp"

#include "display.hpp"
#include "model_impl.hpp"

#include "koppel/analysis/tolerance.hpp"
#include "koppel/catalog/parameter_builder.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/memory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace koppel {

using namespace api_detail;

namespace {

// "s" (a scalar output) or "K_x" / "K_y" (a point output's component).
std::pair<int, int> ResolveOutput(const Model& model, const std::string& name) {
  const Mechanism& m = model.mechanism();
  const int direct = m.FindOutput(name);
  if (direct >= 0) {
    if (m.outputs[direct].Components() == 1) return {direct, 0};
    BadInput(model.path(), "output", "'" + name + "' is a point: name its component, " + ComponentName(name, 0) + " or " + ComponentName(name, 1));
  }
  if (const auto split = SplitComponentName(name)) {
    const int point = m.FindOutput(split->first);
    if (point >= 0 && m.outputs[point].Components() == 2) return {point, split->second};
  }
  BadInput(model.path(), "output", "the mechanism has no output '" + name + "'");
}

}  // namespace

std::string ToleranceResult::Brief() const {
  return std::string(ToString(status)) + ": " + std::to_string(rows.size()) + " inputs, " + std::to_string(samples) + " samples" +
         (message.empty() ? "" : "; " + message);
}

std::vector<std::string> ToleranceResult::Columns() const {
  std::vector<std::string> c = {input_name, "nominal"};
  for (const std::string& p : parameters) c.push_back("sens_" + p);
  for (const std::string& j : joints) c.push_back("sens_clearance_" + j);
  c.insert(c.end(), {"worst_case", "rss", "clearance_worst_case", "linear_std"});
  for (const std::string& p : parameters) c.push_back("share_" + p);
  for (const std::string& j : joints) c.push_back("share_clearance_" + j);
  if (samples > 0) {
    c.insert(c.end(), {"mc_samples", "mc_failed", "mc_min", "mc_max", "mc_mean", "mc_std"});
    for (double level : quantile_levels) {
      char name[32];
      std::snprintf(name, sizeof name, "mc_q%g", level);
      c.push_back(name);
    }
  }
  return c;
}

std::vector<std::optional<double>> ToleranceResult::Row(size_t i) const {
  const ToleranceRowReport& row = rows.at(i);
  std::vector<std::optional<double>> v = {row.input};
  auto add = [&](double x) { v.push_back(row.ok ? std::optional<double>(x) : std::nullopt); };
  add(row.nominal);
  for (size_t j = 0; j < parameters.size(); ++j) add(row.ok ? row.sensitivity[j] : 0);
  for (size_t j = 0; j < joints.size(); ++j) add(row.ok ? row.clearance_gain[j] : 0);
  for (double x : {row.worst_case, row.rss, row.clearance_worst_case, row.linear_std}) add(x);
  for (size_t j = 0; j < parameters.size() + joints.size(); ++j) add(row.ok ? row.share[j] : 0);
  if (samples > 0) {
    add(static_cast<double>(row.mc_samples));
    add(static_cast<double>(row.mc_failed));
    const bool any = row.ok && row.mc_samples > 0;
    for (double x : {row.mc_min, row.mc_max, row.mc_mean, row.mc_std}) v.push_back(any ? std::optional<double>(x) : std::nullopt);
    for (size_t q = 0; q < quantile_levels.size(); ++q) v.push_back(any ? std::optional<double>(row.quantiles[q]) : std::nullopt);
  }
  return v;
}

namespace {

// The request checked against the model (each problem an InputError naming its field) as the
// analysis' options; `names` and `nominal` receive the toleranced parameters and their values.
ToleranceOptions CheckedToleranceOptions(const Model& model, const ToleranceRequest& request, std::vector<std::string>& names,
                                         std::vector<double>& nominal) {
  const auto [output, component] = ResolveOutput(model, request.output);
  ToleranceOptions o;
  o.output = output;
  o.component = component;
  if (request.inputs.empty()) BadInput(model.path(), "input", "no input to evaluate at");
  for (double x : request.inputs) {
    if (!std::isfinite(x)) BadInput(model.path(), "input", "the input is not a finite number");
    o.inputs.push_back(InputInternal(model.mechanism(), x));
  }
  // the toleranced parameters and their nominal values (after every override so far)
    const auto values = model.parameters();
  for (const auto& [name, tolerance] : request.tolerances) {
    auto found = std::find_if(values.begin(), values.end(), [&](const auto& v) { return v.first == name; });
    if (found == values.end()) BadInput(model.path(), "tol", "the mechanism has no parameter '" + name + "'");
    if (std::find(names.begin(), names.end(), name) != names.end()) BadInput(model.path(), "tol", "parameter '" + name + "' is toleranced twice");
    if (!IsToleranceSize(tolerance)) BadInput(model.path(), "tol", "the tolerance of '" + name + "' must be " + kToleranceSizeRule);
    names.push_back(name);
    nominal.push_back(found->second);
    o.tolerances.push_back(tolerance);
  }
  for (const auto& [joint, radius] : request.clearances) {
    const int j = model.mechanism().FindJoint(joint);
    if (j < 0) BadInput(model.path(), "clearance", "the mechanism has no joint '" + joint + "'");
    if (model.mechanism().joints[j].type != JointType::kRevolute)
      BadInput(model.path(), "clearance", "joint '" + joint + "' is a slide: clearance is modelled for revolute joints (a pin in a hole)");
    if (!IsToleranceSize(radius)) BadInput(model.path(), "clearance", "the clearance of '" + joint + "' must be " + kToleranceSizeRule);
    if (std::find(o.clearance_joints.begin(), o.clearance_joints.end(), j) != o.clearance_joints.end())
      BadInput(model.path(), "clearance", "joint '" + joint + "' is given twice");
    o.clearance_joints.push_back(j);
    o.clearances.push_back(radius);
  }
  if (names.empty() && o.clearances.empty()) BadInput(model.path(), "tol", "give at least one tolerance or clearance");
  if (request.distribution == "uniform") o.distribution = ToleranceDistribution::kUniform;
  else if (request.distribution == "normal") o.distribution = ToleranceDistribution::kNormal;
  else BadInput(model.path(), "distribution", "the distribution is uniform or normal, not '" + request.distribution + "'");
  o.samples = request.samples;
  o.seed = request.seed;
  o.threads = request.threads;
  o.progress = request.progress;
  if (std::string why; !o.IsValid(model.mechanism(), &why)) BadInput(model.path(), "tolerance", why);
  const MemoryLimit memory = UsableMemory();
  if (const Outcome fits = CheckToleranceMemory(o, memory.bytes, memory.source); !fits) BadInput(model.path(), "samples", fits.error());
  return o;
}

// One row in the units of the request: `k` turns the output's radians into degrees (1 for a length).
ToleranceRowReport ToleranceRowShown(const ToleranceRow& row, double k, double input) {
  ToleranceRowReport r;
  r.input = input;  // as asked for, not through radians and back
  r.ok = row.ok;
  r.message = row.message;
  r.nominal = k * row.nominal;
  for (double s : row.sensitivity) r.sensitivity.push_back(k * s);
  for (double g : row.clearance_gain) r.clearance_gain.push_back(k * g);
  r.worst_case = k * row.worst_case;
  r.rss = k * row.rss;
  r.clearance_worst_case = k * row.clearance_worst_case;
  r.linear_std = k * row.linear_std;
  r.share = row.share;
  r.mc_samples = row.mc_samples;
  r.mc_failed = row.mc_failed;
  r.mc_min = k * row.mc_min;
  r.mc_max = k * row.mc_max;
  r.mc_mean = k * row.mc_mean;
  r.mc_std = k * row.mc_std;
  for (double q : row.quantiles) r.quantiles.push_back(k * q);
  // radians to degrees can overflow what radians held
  std::vector<double> shown = {r.nominal, r.worst_case, r.rss, r.clearance_worst_case, r.linear_std, r.mc_min, r.mc_max, r.mc_mean, r.mc_std};
  for (const auto* part : {&r.sensitivity, &r.clearance_gain, &r.quantiles}) shown.insert(shown.end(), part->begin(), part->end());
  if (r.ok && !std::all_of(shown.begin(), shown.end(), [](double x) { return std::isfinite(x); })) {
    r.ok = false;
    r.message = "the output's numbers in degrees exceed the range of double-precision numbers";
  }
  return r;
}

}  // namespace

ToleranceResult Model::Tolerances(const ToleranceRequest& request) const {
  const Mechanism& m = mechanism();
  if (!impl_->source) BadInput(path(), "tol", "a mechanism built in code has no parameters to tolerance");
  std::vector<std::string> names;
  std::vector<double> nominal;
  const ToleranceOptions o = CheckedToleranceOptions(*this, request, names, nominal);
  const int output = o.output;

  // every sample evaluates the parsed file anew, without the catalog card (it does not make the mechanism)
  const MechanismBuilder builder = ParameterBuilder(impl_->source->WithoutCard(), impl_->overrides, names);
  const ToleranceReport report = AnalyseTolerances(builder, nominal, o);

  ToleranceResult out;
  out.status = report.status;
  out.message = report.message;
  out.output = request.output;
  out.input_name = input_name();
  out.input_unit = input_is_angle() ? "deg" : length_unit();  // the file's length unit, "length" when it names none
  const bool angle = m.OutputIsAngle(output);
  out.unit = angle ? "deg" : length_unit();
  out.parameters = names;
  out.tolerances = o.tolerances;
  for (const auto& c : request.clearances) {
    out.joints.push_back(c.first);
    out.clearances.push_back(c.second);
  }
  out.distribution = ToString(o.distribution);
  out.samples = o.samples;
  out.seed = o.seed;
  out.quantile_levels = o.quantile_levels;
  const double k = angle ? RadToDeg(1.0) : 1.0;
  for (size_t i = 0; i < report.rows.size(); ++i) out.rows.push_back(ToleranceRowShown(report.rows[i], k, request.inputs[i]));
  return out;
}

}  // namespace koppel
