#include "koppel/catalog/check.hpp"

#include "figures.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/expression.hpp"
#include "koppel/core/structure.hpp"
#include "koppel/solver/sweep.hpp"

#include <algorithm>
#include <cmath>

namespace koppel {
namespace {

const char* TypeLetter(JointType type) { return type == JointType::kRevolute ? "D" : "S"; }

[[noreturn]] void Fail(const std::string& file, int line, const std::string& path, const std::string& message) {
  throw InputError({Diagnostic{file, line, 0, path, message}});
}

void RunEquations(const MechanismFile& file, const CatalogCard& card, const std::string& variant,
                  std::vector<CheckOutcome>& out) {
  if (card.equations.empty()) return;
  const Mechanism& m = file.mechanism;
  int order = 0;
  for (const EquationCheck& e : card.equations) order = std::max(order, e.order);
  const bool angle_input = m.InputIsAngle();
  SweepOptions options;
  options.from = angle_input ? DegToRad(card.from) : card.from;
  options.to = angle_input ? DegToRad(card.to) : card.to;
  options.step = angle_input ? DegToRad(card.step) : card.step;
  options.order = order;
  const SweepResult sweep = Sweep(m, options);

  std::vector<CheckOutcome> results(card.equations.size());
  std::vector<int> columns(card.equations.size());
  for (size_t i = 0; i < card.equations.size(); ++i) {
    const EquationCheck& e = card.equations[i];
    columns[i] = OutputColumn(m, e.output, e.component, e.order, order);
    if (columns[i] < 0) Fail(file.path, e.line, "catalog.equations", "equation '" + e.name + "' names no output '" + e.output + "'");
    results[i] = {variant, e.name, "equation", 0.0, e.tolerance, 0.0, 0.0, true, false, e.note};
  }
  for (size_t s = 0; s < sweep.inputs.size(); ++s) {
    std::string error;
    // `phi` is the document's input: radians for an R drive, length for a P drive
    ParameterSet sample = file.parameters;
    sample.DefineValue("phi", sweep.inputs[s]);
    for (const auto& [name, formula] : card.where) {
      if (!sample.Define(name, formula, &error)) Fail(file.path, 0, "catalog.where." + name, error);
    }
    for (size_t i = 0; i < card.equations.size(); ++i) {
      const EquationCheck& e = card.equations[i];
      const std::optional<double> expected = sample.Evaluate(e.formula, &error);
      if (!expected) Fail(file.path, e.line, "catalog.equations", "equation '" + e.name + "': " + error);
      const double deviation = std::abs(sweep.outputs(s, columns[i]) - *expected);
      if (deviation > results[i].worst) {
        results[i].worst = deviation;
        results[i].where = angle_input ? RadToDeg(sweep.inputs[s]) : sweep.inputs[s];
      }
    }
  }
  for (CheckOutcome& r : results) {
    r.passed = sweep.complete() && r.worst <= r.tolerance;
    if (!sweep.complete()) r.detail = sweep.message;
    out.push_back(r);
  }
}

}  // namespace

AccessFeatures ComputeFeatures(const Mechanism& m, const std::vector<std::string>& output_names) {
  const StructureSummary s = AnalyseStructure(m);
  AccessFeatures f;
  f.drive_joints = s.drive_joints;
  f.drive_joints_at_frame = s.drive_joints_at_frame;
  f.links = s.links;
  f.links_by_degree = s.links_by_degree;
  f.joints = s.joints;
  for (const Joint& j : m.joints) ++f.joints_by_type[TypeLetter(j.type)];
  // output links: distinct links carrying the Abtrieb outputs, and how many are jointed to the frame
  std::vector<int> links;
  for (const std::string& name : output_names) {
    const int o = m.FindOutput(name);
    if (o < 0) continue;
    const int link = OutputLink(m, m.outputs[o]);
    if (link >= 0 && std::find(links.begin(), links.end(), link) == links.end()) links.push_back(link);
  }
  const int frame = m.FrameLink();
  f.output_links = static_cast<int>(links.size());
  f.output_links_at_frame = 0;
  for (int link : links) {
    for (const Joint& j : m.joints) {
      if ((j.link_a == link && j.link_b == frame) || (j.link_b == link && j.link_a == frame)) {
        ++f.output_links_at_frame;
        break;
      }
    }
  }
  return f;
}

std::vector<std::string> CompareFeatures(const AccessFeatures& declared, const AccessFeatures& computed) {
  std::vector<std::string> diffs;
  auto compare = [&](const std::string& what, int d, int c) {
    if (d >= 0 && d != c) diffs.push_back(what + ": declared " + std::to_string(d) + ", computed " + std::to_string(c));
  };
  compare("drive joints", declared.drive_joints, computed.drive_joints);
  compare("drive joints at the frame", declared.drive_joints_at_frame, computed.drive_joints_at_frame);
  compare("output links", declared.output_links, computed.output_links);
  compare("output links at the frame", declared.output_links_at_frame, computed.output_links_at_frame);
  compare("links", declared.links, computed.links);
  compare("joints", declared.joints, computed.joints);
  if (!declared.links_by_degree.empty()) {
    std::map<int, int> all = declared.links_by_degree;
    for (const auto& [degree, n] : computed.links_by_degree) all.emplace(degree, 0);
    for (const auto& [degree, n] : all) {
      const auto d = declared.links_by_degree.find(degree);
      const auto c = computed.links_by_degree.find(degree);
      compare(DegreeName(degree) + " links", d == declared.links_by_degree.end() ? 0 : d->second,
              c == computed.links_by_degree.end() ? 0 : c->second);
    }
  }
  if (!declared.joints_by_type.empty()) {
    std::map<std::string, int> all = declared.joints_by_type;
    for (const auto& [type, n] : computed.joints_by_type) all.emplace(type, 0);
    for (const auto& [type, n] : all) {
      const auto d = declared.joints_by_type.find(type);
      const auto c = computed.joints_by_type.find(type);
      compare("joints " + type, d == declared.joints_by_type.end() ? 0 : d->second,
              c == computed.joints_by_type.end() ? 0 : c->second);
    }
  }
  return diffs;
}

bool EntryReport::passed() const {
  return std::all_of(checks.begin(), checks.end(), [](const CheckOutcome& c) { return c.passed || c.pending; });
}

EntryReport CheckEntry(const std::string& path) {
  const MechanismFile base = ReadMechanismFile(path);
  EntryReport report;
  report.id = base.id;
  if (!base.card) {
    report.checks.push_back({"", "catalog card", "features", 0, 0, 0, 0, false, false, "the file has no catalog section"});
    return report;
  }
  const CatalogCard& card = *base.card;
  const std::vector<std::string> diffs = CompareFeatures(card.declared, ComputeFeatures(base.mechanism, card.outputs));
  CheckOutcome features{"", "access features", "features", static_cast<double>(diffs.size()), 0, 0, 0, diffs.empty(), false, ""};
  for (const std::string& d : diffs) features.detail += (features.detail.empty() ? "" : "; ") + d;
  report.checks.push_back(features);

  std::vector<CheckVariant> variants = card.variants;
  if (variants.empty()) variants.push_back({});
  for (const CheckVariant& v : variants) {
    const MechanismFile file = v.overrides.empty() ? base : ReadMechanismFile(path, v.overrides);
    RunEquations(file, card, v.name, report.checks);
    for (const FigureCheck& figure : card.figures) {
      if (!FigureApplies(figure, v.name)) continue;
      report.checks.push_back(EvaluateFigure(file, card, figure, v.name));
    }
  }
  return report;
}

}  // namespace koppel
