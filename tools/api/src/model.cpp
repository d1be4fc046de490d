#include "koppel/api/model.hpp"

#include "display.hpp"
#include "model_impl.hpp"

#include "koppel/api/admission.hpp"
#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/solver/assembly.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/position.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace koppel {

using namespace api_detail;

namespace {

void CheckOrder(const std::string& file, int order) {
  if (order < 0 || order > kMaxOrder)
    BadInput(file, "order", "the transfer-function order must be 0.." + std::to_string(kMaxOrder) + ", not " + std::to_string(order));
}

std::string NumberText(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace

void Model::Impl::StartWalk(const Assembly& assembly, AtBranchPoint action) {
  ContinuationOptions options;
  options.at_branch_point = action;
  walk = std::make_unique<Continuation>(*solver, options);
  walk_action = action;
  walk->Start(assembly.input, assembly.q);
}

PoseResult Model::Impl::Pose(int order) {
  const Mechanism& m = file.mechanism;
  const SweepColumns layout = SweepLayout(m, order, file.loads.LengthUnit());
  PoseResult r;
  r.status = AnalysisStatus::kComplete;
  r.input = InputShown(m, walk->input());
  r.columns = layout.names;
  r.values.resize(layout.names.size());
  // the Taylor series of q to at least 2nd order: OutputDerivatives reads the angles' rates
  const Eigen::MatrixXd& series = walk->Series(std::max(order, 2));
  std::vector<double> outputs(solver->OutputWidth(order));
  solver->OutputDerivatives(series, order, outputs.data());
  r.valid_order = std::min(walk->ValidOrder(), order);
  r.singular = walk->AtSingularPose();
  DisplayRow(m, layout, walk->input(), outputs.data(), r.valid_order, r.singular, r.values.data());
  return r;
}

AtBranchPoint ParseAtBranchPoint(const std::string& word) {
  if (word.empty()) return AtBranchPoint::kContinue;
  if (const std::optional<BranchPointAction> action = ParseBranchPointAction(word)) return *action;
  throw InputError({Diagnostic{"at_branch_point", 0, 0, "at_branch_point", "expected continue, stop or switch, found '" + word + "'"}});
}

Model::Model(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Model::~Model() = default;
Model::Model(Model&&) noexcept = default;
Model& Model::operator=(Model&&) noexcept = default;
Model::Model(const Model& other) : impl_(std::make_unique<Impl>()) { *this = other; }
Model& Model::operator=(const Model& other) {
  if (this == &other) return *this;
  auto copy = std::make_unique<Impl>();
  copy->source = other.impl_->source;  // immutable: shared
  copy->overrides = other.impl_->overrides;
  copy->file = other.impl_->file;  // the pose is not copied: the copy assembles anew
  copy->notes = other.impl_->notes;
  impl_ = std::move(copy);
  return *this;
}

Model Model::FromSource(MechanismSource source, const ParameterValues& set) {
  auto impl = std::make_unique<Impl>();
  impl->source = std::make_shared<const MechanismSource>(std::move(source));
  impl->overrides = set;
  impl->file = impl->source->Evaluate(set);
  impl->notes = AdmitMechanism(impl->file);  // as ReadAdmittedMechanism
  return Model(std::move(impl));
}

Model Model::Load(const std::string& path, const ParameterValues& set) { return FromSource(MechanismSource::Read(path), set); }

Model Model::Parse(const std::string& yaml, const std::string& name, const ParameterValues& set) {
  return FromSource(MechanismSource::Parse(yaml, name), set);
}

Model Model::FromMechanism(const Mechanism& mechanism) {
  std::vector<Diagnostic> problems;
  for (const std::string& problem : CheckConsistency(mechanism)) problems.push_back({mechanism.name, 0, 0, "", problem});
  if (!problems.empty()) throw InputError(problems);
  auto impl = std::make_unique<Impl>();
  impl->file.path = mechanism.name;
  impl->file.id = mechanism.name;
  impl->file.mechanism = mechanism;
  impl->file.sweep = mechanism.InputIsAngle() ? SweepDefaults{0, 360, 1} : SweepDefaults{};
  impl->notes = AdmitMechanism(impl->file);
  return Model(std::move(impl));
}

const std::string& Model::name() const { return impl_->file.id; }
const std::string& Model::title() const { return impl_->file.title; }
const std::string& Model::path() const { return impl_->file.path; }

const Mechanism& Model::mechanism() const { return impl_->file.mechanism; }
const std::vector<std::string>& Model::notes() const { return impl_->notes; }
std::string Model::length_unit() const { return impl_->file.loads.LengthUnit(); }
std::string Model::input_name() const { return mechanism().drive.input_name; }
bool Model::input_is_angle() const { return mechanism().InputIsAngle(); }
double Model::sweep_from() const { return impl_->file.sweep.from; }
double Model::sweep_to() const { return impl_->file.sweep.to; }
double Model::sweep_step() const { return impl_->file.sweep.step; }
SweepSpan Model::Span(std::optional<double> from, std::optional<double> to, std::optional<double> step) const {
  return {from.value_or(sweep_from()), to.value_or(sweep_to()), step.value_or(sweep_step())};
}

std::vector<std::string> Model::output_names() const {
  std::vector<std::string> names;
  for (const Output& o : mechanism().outputs) names.push_back(o.name);
  return names;
}

bool Model::output_is_angle(const std::string& output) const {
  const int index = mechanism().FindOutput(output);
  if (index < 0) BadInput(path(), "output", "the mechanism has no output '" + output + "'");
  return mechanism().OutputIsAngle(index);
}

std::vector<std::pair<std::string, double>> Model::parameters() const { return impl_->file.parameters.Values(); }

void Model::Set(const std::string& name, const std::string& formula) {
  if (!impl_->source)
    BadInput(path(), "parameters." + name, "a mechanism built in code has no parameters to set");
  Overrides with = impl_->overrides;
  const auto same = [&](const auto& o) { return o.first == name; };
  with.erase(std::remove_if(with.begin(), with.end(), same), with.end());
  with.emplace_back(name, formula);
  MechanismFile file = impl_->source->Evaluate(with);  // throws InputError: nothing changed yet
  std::vector<std::string> notes = AdmitMechanism(file);
  impl_->Forget();
  impl_->file = std::move(file);
  impl_->notes = std::move(notes);
  impl_->overrides = std::move(with);
}

void Model::Set(const std::string& name, double value) {
  if (!std::isfinite(value)) BadInput(path(), "parameters." + name, "the value is not a finite number");
  Set(name, NumberText(value));
}

bool Model::assembled() const { return impl_->walk != nullptr; }

PoseResult Model::Assemble(int order) {
  CheckOrder(path(), order);
  impl_->Forget();
  impl_->solver = std::make_unique<PositionSolver>(mechanism());
  const Assembly assembly = AssembleRegular(mechanism(), *impl_->solver);
  if (!assembly.ok()) {
    impl_->Forget();
    PoseResult r;
    r.status = AnalysisStatus::kFailed;
    r.message = assembly.error;
    r.input = InputShown(mechanism(), mechanism().hint.input);
    return r;
  }
  impl_->StartWalk(assembly, AtBranchPoint::kContinue);
  return impl_->Pose(order);
}

PoseResult Model::MoveTo(double input, int order, AtBranchPoint at_branch_point) {
  CheckOrder(path(), order);
  if (!std::isfinite(input)) BadInput(path(), "input", "the input is not a finite number");
  if (!assembled() || impl_->walk_action != at_branch_point) {
    // a walk keeps its options: start one with these from the current pose (or the assembly)
    std::optional<Assembly> from;
    if (assembled()) {
      from = Assembly{impl_->walk->q(), impl_->walk->input(), "", {}};
    } else {
      const PoseResult assembled_pose = Assemble(order);
      if (assembled_pose.status != AnalysisStatus::kComplete) return assembled_pose;
      from = Assembly{impl_->walk->q(), impl_->walk->input(), "", {}};
    }
    impl_->StartWalk(*from, at_branch_point);
  }
  const WalkReport report = impl_->walk->AdvanceTo(InputInternal(mechanism(), input), std::numeric_limits<double>::infinity());
  PoseResult r = impl_->Pose(order);
  if (!report.ok()) {
    r.status = AnalysisStatus::kFailed;
    r.message = report.message;
  }
  return r;
}

std::string Model::ToYaml() const {
  const MechanismFile& f = impl_->file;
  const bool has_loads = f.loads.HasMass() || !f.loads.forces.empty() || !f.loads.torques.empty() || !f.loads.springs.empty();
  return WriteMechanismYaml(f.mechanism, f.title.empty() ? f.id : f.title, f.sweep, f.parameters.Values(),
                            has_loads ? &f.loads : nullptr);
}

}  // namespace koppel
