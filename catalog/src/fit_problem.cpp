#include "koppel/catalog/fit_problem.hpp"
#include "koppel/catalog/parameter_builder.hpp"
#include "koppel/catalog/parameter_use.hpp"

#include "koppel/catalog/catalog.hpp"

#include "koppel/core/angles.hpp"
#include "input_file.hpp"
#include "mechanism_node.hpp"
#include "yaml_reader.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>

namespace koppel {
namespace {

// `parameters:` {name: {start, lower, upper} or nothing}: which parameters of the mechanism file
// the fit may change, and within which bounds.
void ReadFitParameters(YamlReader& r, const YAML::Node& root, const std::string& relative, FitProblem& problem) {
  const YAML::Node params = r.Require(root, "parameters", "");
  const std::vector<std::string> read = ParametersRead(problem.base);  // a free parameter nothing reads fits nothing
  for (const YamlReader::Entry& e : r.Entries(params, "parameters")) {
    const std::string ppath = Child("parameters", e.key);
    if (!problem.base.parameters.Has(e.key)) {
      r.Error(e.key_node, ppath, "'" + e.key + "' is not a parameter of " + relative);
      continue;
    }
    if (std::find(read.begin(), read.end(), e.key) == read.end()) {
      r.Error(e.key_node, ppath, UnreadParameterMessage(e.key, read));
      continue;
    }
    FitParameter p;
    p.name = e.key;
    p.start = problem.base.parameters.Value(e.key);
    if (e.value.IsMap()) {
      r.CheckKeys(e.value, ppath, {"start", "lower", "upper"});
      if (e.value["start"].IsDefined()) p.start = r.Number(e.value["start"], Child(ppath, "start")).value_or(p.start);
      if (e.value["lower"].IsDefined()) p.lower = r.Number(e.value["lower"], Child(ppath, "lower")).value_or(p.lower);
      if (e.value["upper"].IsDefined()) p.upper = r.Number(e.value["upper"], Child(ppath, "upper")).value_or(p.upper);
      if (p.lower > p.upper || p.start < p.lower || p.start > p.upper) r.Error(e.value, ppath, "needs lower <= start <= upper");
    } else if (!e.value.IsNull()) {
      r.Error(e.value, ppath, "expected {start, lower, upper} or nothing");
    }
    problem.parameters.push_back(p);
  }
}

// `starts`, `tolerance` (one number for every target in its own unit, or {length, angle}) and
// `require` {from, to} (the input range the fitted mechanism must be drivable over).
void ReadFitOptions(YamlReader& r, const YAML::Node& root, bool angle_input, FitProblem& problem) {
  auto input_of = [&](double v) { return angle_input ? DegToRad(v) : v; };
  if (const YAML::Node s = root["starts"]; s.IsDefined()) {
    problem.options.starts = r.Count(s, "starts").value_or(problem.options.starts);
    if (problem.options.starts < 1 || problem.options.starts > 10000) r.Error(s, "starts", "needs 1 to 10000 starts");
  }
  if (const YAML::Node tol = root["tolerance"]; tol.IsDefined()) {
    if (tol.IsMap()) {
      r.CheckKeys(tol, "tolerance", {"length", "angle"});
      if (tol["length"].IsDefined()) problem.options.length_tolerance = r.Number(tol["length"], "tolerance.length").value_or(0);
      if (tol["angle"].IsDefined()) problem.options.angle_tolerance = DegToRad(r.Number(tol["angle"], "tolerance.angle").value_or(0));
    } else {
      const double v = r.Number(tol, "tolerance").value_or(0);
      problem.options.length_tolerance = v;
      problem.options.angle_tolerance = DegToRad(v);
    }
    if (!(problem.options.length_tolerance > 0 && problem.options.angle_tolerance > 0)) r.Error(tol, "tolerance", "a tolerance must be positive");
  }
  if (const YAML::Node q = root["require"]; q.IsDefined() && r.ExpectMap(q, "require")) {
    r.CheckKeys(q, "require", {"from", "to"});
    problem.options.require_from = input_of(r.Number(r.Require(q, "from", "require"), "require.from").value_or(0));
    problem.options.require_to = input_of(r.Number(r.Require(q, "to", "require"), "require.to").value_or(0));
  }
}

// One entry of `targets:`; nullopt (with the problem reported) when it names no output.
std::optional<FitTarget> ReadFitTarget(YamlReader& r, const YAML::Node& t, const std::string& tpath, const Mechanism& m,
                                       const std::string& relative) {
  auto input_of = [&](double v) { return m.InputIsAngle() ? DegToRad(v) : v; };
  FitTarget target;
  if (t["straight"].IsDefined()) {
    // a straight line over [from, to]: `input` is `from`
    target.straight = true;
    target.input = input_of(r.Number(r.Require(t, "from", tpath), Child(tpath, "from")).value_or(0));
    target.to = input_of(r.Number(r.Require(t, "to", tpath), Child(tpath, "to")).value_or(0));
    target.samples = t["samples"].IsDefined() ? r.Count(t["samples"], Child(tpath, "samples")).value_or(0) : 21;
    if (target.samples < 3) r.Error(t, Child(tpath, "samples"), "a straight line needs at least 3 samples");
  } else if (t["input"].IsDefined()) target.input = input_of(r.Number(t["input"], Child(tpath, "input")).value_or(0));
  else r.Error(t, Child(tpath, "input"), "missing required key 'input' (the start value when free_input)");
  if (t["weight"].IsDefined()) target.weight = r.Number(t["weight"], Child(tpath, "weight")).value_or(1);
  if (t["weight"].IsDefined() && target.weight == 0) r.Error(t["weight"], Child(tpath, "weight"), "a weight must not be 0");
  if (t["free_input"].IsDefined()) target.input_free = r.Flag(t["free_input"], Child(tpath, "free_input")).value_or(false);
  const char* kind = t["point"].IsDefined() ? "point" : t["deadcentre"].IsDefined() ? "deadcentre" : t["straight"].IsDefined() ? "straight" : "output";
  const std::string name = t[kind].IsDefined() ? r.Text(t[kind], Child(tpath, kind)).value_or("") : "";
  target.output = m.FindOutput(name);
  if (target.output < 0) {
    r.Error(t, tpath, "names no output '" + name + "' of " + relative + " (give point: or output:)");
    return std::nullopt;
  }
  target.name = t["name"].IsDefined() ? r.Text(t["name"], Child(tpath, "name")).value_or(name) : name;
  if (target.straight) {
    if (m.outputs[target.output].kind != OutputKind::kPoint) r.Error(t["straight"], Child(tpath, "straight"), "'" + name + "' is not a point output");
  } else if (t["deadcentre"].IsDefined()) {
    // the output's dead centre next to `input` must lie at `input`
    target.deadcentre = true;
    if (m.outputs[target.output].Components() != 1) r.Error(t["deadcentre"], Child(tpath, "deadcentre"), "needs a scalar output");
  } else if (t["point"].IsDefined()) {
    target.point = true;
    if (m.outputs[target.output].kind != OutputKind::kPoint) r.Error(t["point"], Child(tpath, "point"), "'" + name + "' is not a point output");
    const YAML::Node at = r.Require(t, "at", tpath);
    if (at.IsDefined() && !at.IsNull()) target.position = r.Vector(at, Child(tpath, "at")).value_or(Eigen::Vector2d::Zero());
  } else {
    if (m.outputs[target.output].Components() != 1) r.Error(t["output"], Child(tpath, "output"), "use point: for a point output");
    const YAML::Node v = r.Require(t, "value", tpath);
    if (v.IsDefined() && !v.IsNull()) {
      const double value = r.Number(v, Child(tpath, "value")).value_or(0);
      target.value = TargetUnit(m, target) == FitUnit::kAngle ? DegToRad(value) : value;
    }
  }
  if (const YAML::Node tol = t["tolerance"]; tol.IsDefined()) {
    // in the target's unit: degrees for an angle output or a dead centre of an R drive
    const double v = r.Number(tol, Child(tpath, "tolerance")).value_or(0);
    const bool angle_target = TargetUnit(m, target) == FitUnit::kAngle;
    if (!(v > 0)) r.Error(tol, Child(tpath, "tolerance"), "a tolerance must be positive");
    target.tolerance = angle_target ? DegToRad(v) : v;
  }
  return target;
}

// The builder: the mechanism file again with the free parameters as overrides, parsed from the
// text in memory (the disk is read once, by ReadFitProblem).
MechanismBuilder BuilderFor(const FitProblem& problem, const std::string& mechanism_text) {
  std::vector<std::string> names;
  for (const FitParameter& p : problem.parameters) names.push_back(p.name);
  return ParameterBuilder(mechanism_text, problem.mechanism_path, {}, names);
}

}  // namespace

FitProblem ReadFitProblem(const std::string& path) {
  const YAML::Node root = ParseYamlText(ReadInputText(path), path);
  FitProblem problem;
  problem.path = path;
  YamlReader r(path, nullptr);
  r.set_fallback(YAML::Mark());
  if (!r.ExpectMap(root, "")) throw InputError(r.diagnostics());
  r.CheckKeys(root, "", {"mechanism", "parameters", "starts", "require", "tolerance", "targets"});
  const YAML::Node mech = r.Require(root, "mechanism", "");
  if (!r.diagnostics().empty()) throw InputError(r.diagnostics());
  const std::string relative = r.Text(mech, "mechanism").value_or("");
  // a file relative to the problem's folder; where there is none, a catalog id names the entry
  problem.mechanism_path = (std::filesystem::path(path).parent_path() / relative).string();
  if (std::error_code ec; !std::filesystem::exists(problem.mechanism_path, ec)) {
    if (const std::string entry = CatalogEntryFile(relative); !entry.empty()) problem.mechanism_path = entry;
  }
  std::string mechanism_text;
  try {
    problem.mechanism_text = ReadInputText(problem.mechanism_path);
    problem.base = ParseMechanismText(problem.mechanism_text, problem.mechanism_path);
    mechanism_text = MechanismTextWithoutCard(problem.mechanism_text, problem.mechanism_path);
  } catch (const InputError& e) {
    std::vector<Diagnostic> all = {{path, mech.Mark().line + 1, mech.Mark().column + 1, "mechanism", "the mechanism file has problems:"}};
    all.insert(all.end(), e.diagnostics().begin(), e.diagnostics().end());
    throw InputError(all);
  }
  const Mechanism& m = problem.base.mechanism;
  const bool angle = m.InputIsAngle();
  r.set_parameters(&problem.base.parameters);

  ReadFitParameters(r, root, relative, problem);
  ReadFitOptions(r, root, angle, problem);
  const YAML::Node targets = r.Require(root, "targets", "");
  if (targets.IsDefined() && r.ExpectSequence(targets, "targets")) {
    for (size_t i = 0; i < targets.size(); ++i) {
      const YAML::Node t = targets[i];
      const std::string tpath = Index("targets", static_cast<int>(i));
      if (!r.ExpectMap(t, tpath)) continue;
      r.CheckKeys(t, tpath, {"point", "output", "deadcentre", "straight", "input", "from", "to", "samples", "at", "value", "weight",
                             "free_input", "name", "tolerance"});
      const std::optional<FitTarget> target = ReadFitTarget(r, t, tpath, m, relative);
      if (!target) continue;
      problem.targets.push_back(*target);
    }
  }
  if (problem.targets.empty() && r.diagnostics().empty()) r.Error(root, "targets", "no targets");
  if (!r.diagnostics().empty()) throw InputError(r.diagnostics());

  problem.builder = BuilderFor(problem, std::move(mechanism_text));
  return problem;
}

std::string FitUnitName(const FitProblem& problem, FitUnit unit) {
  return unit == FitUnit::kAngle ? "deg" : problem.base.loads.LengthUnit();
}

std::string FitParameterUnitName(const FitProblem& problem, const std::string& name) {
  switch (MeasureOf(problem.base, name)) {
    case ParameterMeasure::kLength: return problem.base.loads.LengthUnit();
    case ParameterMeasure::kAngle: return "deg";
    case ParameterMeasure::kUnknown: break;
  }
  return "parameter";
}

}  // namespace koppel
