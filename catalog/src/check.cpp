#include "koppel/catalog/check.hpp"

#include "figures.hpp"
#include "koppel/catalog/classes.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/expression.hpp"
#include "koppel/core/structure.hpp"
#include "koppel/solver/position.hpp"
#include "koppel/solver/sweep.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace koppel {
namespace {

const char* TypeLetter(JointType type) { return type == JointType::kRevolute ? "D" : "S"; }

[[noreturn]] void Fail(const std::string& file, int line, const std::string& path, const std::string& message) {
  throw InputError({Diagnostic{file, line, 0, path, message}});
}

// An equation's verdict from its worst deviation over the sweep: not computed when the sweep
// is not complete; `skipped` samples at singular poses are said in the detail.
CheckOutcome EquationVerdict(const SweepResult& sweep, int skipped, CheckOutcome r) {
  if (!sweep.complete()) {
    r.status = CheckStatus::kNotComputed;
    r.detail = sweep.message;
  } else {
    r.status = r.worst <= r.tolerance ? CheckStatus::kPassed : CheckStatus::kFailed;
    if (skipped > 0)
      r.detail += (r.detail.empty() ? "" : " ") + std::string("(") + std::to_string(skipped) +
                  " samples at singular poses not compared: the order is not computable there)";
  }
  return r;
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
  std::vector<bool> angle(card.equations.size());
  std::vector<int> skipped(card.equations.size(), 0);
  for (size_t i = 0; i < card.equations.size(); ++i) {
    const EquationCheck& e = card.equations[i];
    columns[i] = OutputColumn(m, e.output, e.component, e.order, order);
    if (columns[i] < 0) Fail(file.path, e.line, "catalog.equations", "equation '" + e.name + "' names no output '" + e.output + "'");
    angle[i] = e.order == 0 && m.OutputIsAngle(m.FindOutput(e.output));
    results[i].variant = variant;
    results[i].name = e.name;
    results[i].kind = CheckKind::kEquation;
    results[i].tolerance = e.tolerance;
    results[i].detail = e.note;
  }
  for (size_t s = 0; s < sweep.inputs.size(); ++s) {
    // `phi` is the document's input: radians for an R drive, length for a P drive
    ParameterSet sample = file.parameters;
    sample.DefineValue("phi", sweep.inputs[s]);
    for (const auto& [name, formula] : card.where) {
      if (const Expected<double> v = sample.Define(name, formula); !v) Fail(file.path, 0, "catalog.where." + name, v.error());
    }
    for (size_t i = 0; i < card.equations.size(); ++i) {
      const EquationCheck& e = card.equations[i];
      // at a singular pose the sweep leaves the orders it cannot compute empty: not compared
      if (!sweep.valid_order.empty() && sweep.valid_order[s] < e.order) {
        ++skipped[i];
        continue;
      }
      const Expected<double> expected = sample.Evaluate(e.formula);
      if (!expected) Fail(file.path, e.line, "catalog.equations", "equation '" + e.name + "': " + expected.error());
      // an angle is compared wrap-aware: a closed form in atan2 may differ by whole turns
      const double difference = sweep.outputs(s, columns[i]) - *expected;
      const double deviation = std::abs(angle[i] ? AngleDifference(difference, 0.0) : difference);
      if (deviation > results[i].worst) {
        results[i].worst = deviation;
        results[i].where = angle_input ? RadToDeg(sweep.inputs[s]) : sweep.inputs[s];
      }
    }
  }
  for (size_t i = 0; i < results.size(); ++i) out.push_back(EquationVerdict(sweep, skipped[i], results[i]));
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

const char* ToString(CheckKind kind) {
  switch (kind) {
    case CheckKind::kFeatures: return "features";
    case CheckKind::kEquation: return "equation";
    case CheckKind::kFigure: return "figure";
  }
  return "?";
}

const char* ToString(CheckStatus status) {
  switch (status) {
    case CheckStatus::kNotRun: return "not run";
    case CheckStatus::kPassed: return "pass";
    case CheckStatus::kFailed: return "FAIL";
    case CheckStatus::kNotComputed: return "not computed";
  }
  return "?";
}

double CheckOutcome::Ratio() const {
  if (status == CheckStatus::kNotComputed || status == CheckStatus::kNotRun) return std::numeric_limits<double>::infinity();
  if (tolerance > 0) return worst / tolerance;
  return worst == 0 ? 0.0 : std::numeric_limits<double>::infinity();
}

bool EntryReport::passed() const {
  return !checks.empty() && std::all_of(checks.begin(), checks.end(), [](const CheckOutcome& c) { return c.passed(); });
}

int EntryReport::Count(CheckStatus status) const {
  return static_cast<int>(std::count_if(checks.begin(), checks.end(), [&](const CheckOutcome& c) { return c.status == status; }));
}

const CheckOutcome* EntryReport::Worst() const {
  const CheckOutcome* worst = nullptr;
  for (const CheckOutcome& c : checks) {
    if (!worst || c.Ratio() > worst->Ratio()) worst = &c;
  }
  return worst;
}

std::string EntryReport::Brief() const {
  const int passed_checks = Count(CheckStatus::kPassed);
  std::string s = id + ": " + std::to_string(passed_checks) + "/" + std::to_string(checks.size()) + " passed";
  if (const CheckOutcome* w = Worst()) {
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.2g", w->Ratio());
    // a deviation against a tolerance of 0 has an unbounded ratio: said so, not "not computed"
    char deviation[64];
    std::snprintf(deviation, sizeof deviation, "%.3g against a tolerance of 0", w->worst);
    const bool computed = w->status != CheckStatus::kNotComputed && w->status != CheckStatus::kNotRun;
    s += std::string(", worst ") + (!computed ? "not computed" : std::isinf(w->Ratio()) ? deviation : ratio) +
         (computed && std::isinf(w->Ratio()) ? "" : " of tolerance") + " (" + w->name + ")";
  }
  return s;
}

namespace {

// declared access features and classes against the joint graph
CheckOutcome FeatureCheck(const MechanismFile& file, const CatalogCard& card) {
  std::vector<std::string> diffs = CompareFeatures(card.declared, ComputeFeatures(file.mechanism, card.outputs));
  for (const std::string& p : ClassProblems(file.mechanism, card.classes)) diffs.push_back(p);
  CheckOutcome features;
  features.name = "access features";
  features.kind = CheckKind::kFeatures;
  features.worst = static_cast<double>(diffs.size());
  features.status = diffs.empty() ? CheckStatus::kPassed : CheckStatus::kFailed;
  for (const std::string& d : diffs) features.detail += (features.detail.empty() ? "" : "; ") + d;
  return features;
}

// How far each hint point is moved to show that the hint pins the branch: 2 % of the mechanism's
// length scale, in eight directions.
constexpr double kHintNudge = 0.02;
constexpr int kHintDirections = 8;
// The same pose: every coordinate within this (relative to the length scale; radians for angles).
constexpr double kSamePose = 1e-6;

// The assembly hint pins one branch: it leaves no link's pose to the solver's choice
// (LinksTheHintLeavesOpen), and assembling from its points moved a little lands on the same pose.
CheckOutcome HintCheck(const MechanismFile& file, const std::string& variant) {
  CheckOutcome hint;
  hint.name = "assembly hint pins the branch";
  hint.kind = CheckKind::kFeatures;
  hint.variant = variant;
  hint.tolerance = kSamePose;
  const Mechanism& m = file.mechanism;
  std::string open;
  for (const int l : LinksTheHintLeavesOpen(m)) open += (open.empty() ? "" : ", ") + m.links[l].name;
  if (!open.empty()) {
    hint.status = CheckStatus::kFailed;
    hint.worst = 1;
    hint.detail = "the hint leaves the pose of " + open + " to the solver (assembly: points: name a point of each)";
    return hint;
  }
  PositionSolver solver(m);
  Eigen::VectorXd q;
  if (const SolveReport r = solver.Assemble(q); !r.ok()) {
    hint.status = CheckStatus::kNotComputed;
    hint.detail = "the hint does not assemble: " + r.message;
    return hint;
  }
  const double scale = solver.system().length_scale();
  for (int k = 0; k < kHintDirections; ++k) {
    Mechanism nudged = m;
    for (size_t e = 0; e < nudged.hint.points.size(); ++e) {
      const double angle = 2 * kPi * (k + 0.37 * static_cast<double>(e)) / kHintDirections;
      nudged.hint.points[e].global += kHintNudge * scale * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    }
    Eigen::VectorXd other;
    const SolveReport r = PositionSolver(nudged).Assemble(other);
    double off = r.ok() ? 0.0 : std::numeric_limits<double>::infinity();
    for (int i = 0; r.ok() && i < q.size(); ++i)
      off = std::max(off, i % 3 == 2 ? std::abs(std::remainder(other(i) - q(i), 2 * kPi)) : std::abs(other(i) - q(i)) / scale);
    hint.worst = std::max(hint.worst, off);
    if (off > kSamePose) {
      hint.status = CheckStatus::kFailed;
      hint.detail = r.ok() ? "a hint moved by 2 % of the mechanism's size assembles another pose (differing by " + std::to_string(off) + ")"
                           : "a hint moved by 2 % of the mechanism's size does not assemble: " + r.message;
      return hint;
    }
  }
  hint.status = CheckStatus::kPassed;
  return hint;
}

// A time ratio this far from 1 is a quick return; closer, roundoff of the dead centres' inputs.
constexpr double kQuickReturn = 1e-6;

// quick-return computed: the card's first Abtrieb output, a scalar over a whole turn of an R drive,
// has a time ratio other than 1 (its dead centres, dead_centres.hpp); the class is declared
// exactly when it has. Empty (no check) for an entry where no time ratio is defined that does not
// declare the class.
std::optional<CheckOutcome> QuickReturnCheck(FigureContext& context, const CatalogCard& card, const std::string& variant) {
  const bool declared = std::find(card.classes.begin(), card.classes.end(), "quick-return") != card.classes.end();
  CheckOutcome quick;
  quick.name = "class quick-return: the time ratio";
  quick.kind = CheckKind::kFeatures;
  quick.variant = variant;
  quick.tolerance = 0;  // a class holds or not: worst 1 when declared and computed differ, else 0
  const Mechanism& m = context.mechanism();
  const int output = card.outputs.empty() ? -1 : m.FindOutput(card.outputs[0]);
  const SweepOptions range = context.CardRange();
  const bool whole_turn = m.InputIsAngle() && std::abs(std::abs(range.to - range.from) - 2 * kPi) < 1e-9;
  if (output < 0 || m.outputs[output].Components() != 1 || !whole_turn) {
    if (!declared) return std::nullopt;
    quick.status = CheckStatus::kFailed;
    quick.worst = 1;
    quick.detail = "declared, but the entry has no time ratio (a scalar Abtrieb output over a whole turn of a crank)";
    return quick;
  }
  const DeadCentreReport& r = context.DeadCentres(output, 0);
  const double ratio = r.has_stroke && r.sweep.complete() ? r.TimeRatio() : 1.0;
  quick.value = ratio;
  const bool computed = std::abs(ratio - 1) > kQuickReturn;
  // a quick return states its time ratio (the slow stroke over the fast one, >= 1) as a figure
  const bool stated = std::any_of(card.figures.begin(), card.figures.end(), [](const FigureCheck& f) { return f.quantity == FigureQuantity::kTimeRatio; });
  const bool holds = computed == declared && (stated || !declared);
  quick.worst = holds ? 0 : 1;
  quick.status = holds ? CheckStatus::kPassed : CheckStatus::kFailed;
  if (computed && !declared) quick.detail = fmt::format("{}'s time ratio is {:.6g}: declare quick-return", card.outputs[0], ratio);
  if (!computed && declared) quick.detail = fmt::format("declared, but {}'s time ratio is {:.6g}", card.outputs[0], ratio);
  if (computed && declared && !stated) quick.detail = fmt::format("{}'s time ratio is {:.6g}: state it as a time_ratio figure", card.outputs[0], ratio);
  return quick;
}

// dwell computed: the class is declared exactly where the card states a rest (a `rest` figure: an
// output that stands within its band over an input range), and each rest is checked as a figure,
// so a declared dwell the mechanism does not make fails there.
std::optional<CheckOutcome> DwellCheck(const CatalogCard& card) {
  const bool declared = std::find(card.classes.begin(), card.classes.end(), "dwell") != card.classes.end();
  const bool stated = std::any_of(card.figures.begin(), card.figures.end(), [](const FigureCheck& f) { return f.quantity == FigureQuantity::kRest; });
  if (!declared && !stated) return std::nullopt;
  CheckOutcome dwell;
  dwell.name = "class dwell: a rest";
  dwell.kind = CheckKind::kFeatures;
  dwell.tolerance = 0;  // a class holds or not
  dwell.worst = declared == stated ? 0 : 1;
  dwell.status = declared == stated ? CheckStatus::kPassed : CheckStatus::kFailed;
  if (declared && !stated) dwell.detail = "declared, but no figure states the rest (quantity rest: the output, from, to and the band as tolerance)";
  if (stated && !declared) dwell.detail = "a rest figure states a dwell: declare the class dwell";
  return dwell;
}

}  // namespace

namespace {
EntryReport CheckWith(const std::string& path, const MechanismFile& base, const CatalogCard& card);
}  // namespace

EntryReport CheckEntry(const std::string& path) {
  const MechanismFile base = ReadMechanismFile(path);
  if (!base.card) {
    EntryReport report;
    report.id = base.id;
    CheckOutcome missing;
    missing.name = "catalog card";
    missing.status = CheckStatus::kFailed;
    missing.detail = "the file has no catalog section";
    report.checks.push_back(missing);
    return report;
  }
  return CheckWith(path, base, *base.card);
}

EntryReport CheckCard(const std::string& path, const CatalogCard& card) { return CheckWith(path, ReadMechanismFile(path), card); }

namespace {

EntryReport CheckWith(const std::string& path, const MechanismFile& base, const CatalogCard& card) {
  EntryReport report;
  report.id = base.id;
  report.checks.push_back(FeatureCheck(base, card));
  // the classes describe the file's own parameters, not each variant's (a centric slider-crank among
  // an offset one's variants has no quick return)
  FigureContext own(base, card);
  if (std::optional<CheckOutcome> quick = QuickReturnCheck(own, card, "")) report.checks.push_back(*quick);
  if (std::optional<CheckOutcome> dwell = DwellCheck(card)) report.checks.push_back(*dwell);
  std::vector<CheckVariant> variants = card.variants;
  if (variants.empty()) variants.push_back({});
  for (const CheckVariant& v : variants) {
    const MechanismFile file = v.overrides.empty() ? base : ReadMechanismFile(path, v.overrides);
    report.checks.push_back(HintCheck(file, v.name));
    RunEquations(file, card, v.name, report.checks);
    FigureContext context(file, card);
    for (const FigureCheck& figure : card.figures) {
      if (FigureApplies(figure, v.name)) report.checks.push_back(EvaluateFigure(context, figure, v.name));
    }
  }
  return report;
}

}  // namespace
}  // namespace koppel
