#include "koppel/api/model.hpp"

#include "display.hpp"
#include "model_impl.hpp"

#include "admission.hpp"
#include "koppel/catalog/document_edit.hpp"
#include "koppel/catalog/mechanism_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace koppel {

using namespace api_detail;

namespace {

}  // namespace

AtBranchPoint ParseAtBranchPoint(const std::string& word) {
  if (word.empty()) return AtBranchPoint::kContinue;
  if (const std::optional<BranchPointAction> action = ParseBranchPointAction(word)) return *action;
  throw InputError({Diagnostic{"at_branch_point", 0, 0, "at_branch_point", "expected continue, stop or switch, found '" + word + "'"}});
}

ParameterValues ParseParameterValues(const std::vector<std::string>& assignments) {
  ParameterValues values;
  for (const std::string& a : assignments) values.push_back(ParseAssignment(a));
  return values;
}

Model::Model(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
Model::~Model() = default;

Model Model::FromEvaluated(MechanismSource source, const ParameterValues& set, MechanismFile file) {
  auto impl = std::make_shared<Impl>();
  impl->source = std::make_shared<const MechanismSource>(std::move(source));
  impl->overrides = set;
  impl->file = std::move(file);
  impl->notes = AdmitMechanism(impl->file);  // as ReadAdmittedMechanism
  return Model(std::move(impl));
}

// the file's YAML parsed once for the source and its first evaluation (MechanismSource::Read)
Model Model::Load(const std::string& path, const ParameterValues& set) {
  MechanismFile file;
  MechanismSource source = MechanismSource::Read(path, set, &file);
  return FromEvaluated(std::move(source), set, std::move(file));
}

Model Model::Parse(const std::string& yaml, const std::string& name, const ParameterValues& set) {
  MechanismFile file;
  MechanismSource source = MechanismSource::Parse(yaml, name, set, &file);
  return FromEvaluated(std::move(source), set, std::move(file));
}

Model Model::FromMechanism(const Mechanism& mechanism) {
  std::vector<Diagnostic> problems;
  for (const std::string& problem : CheckConsistency(mechanism)) problems.push_back({mechanism.name, 0, 0, "", problem});
  if (!problems.empty()) throw InputError(problems);
  auto impl = std::make_shared<Impl>();
  impl->file.path = mechanism.name;
  impl->file.id = mechanism.name;
  impl->file.mechanism = mechanism;
  impl->file.sweep = mechanism.InputIsAngle() ? SweepDefaults{0, 360, 1} : SweepDefaults{};
  impl->notes = AdmitMechanism(impl->file);
  return Model(std::move(impl));
}

Model ModelAccess::FromFile(MechanismFile file) {
  auto impl = std::make_shared<Model::Impl>();
  impl->file = std::move(file);
  impl->notes = AdmitMechanism(impl->file);
  return Model(std::move(impl));
}

const std::string& Model::name() const { return impl_->file.id; }
const std::string& Model::title() const { return impl_->file.title; }
const std::string& Model::path() const { return impl_->file.path; }

const Mechanism& Model::mechanism() const { return impl_->file.mechanism; }
const std::vector<std::string>& Model::notes() const { return impl_->notes; }
std::string Model::length_unit() const { return impl_->file.loads.LengthUnit(); }
const Loads& Model::loads() const { return impl_->file.loads; }
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

Model Model::With(const std::string& name, const std::string& formula) const {
  if (!impl_->source)
    BadInput(path(), "parameters." + name, "a mechanism built in code has no parameters to set");
  auto impl = std::make_shared<Impl>();
  impl->source = impl_->source;
  impl->overrides = impl_->overrides;
  const auto same = [&](const auto& o) { return o.first == name; };
  std::erase_if(impl->overrides, same);
  impl->overrides.emplace_back(name, formula);
  impl->file = impl->source->Evaluate(impl->overrides);  // throws InputError
  impl->notes = AdmitMechanism(impl->file);
  return Model(std::move(impl));
}

Model Model::With(const std::string& name, double value) const {
  if (!std::isfinite(value)) BadInput(path(), "parameters." + name, "the value is not a finite number");
  return With(name, NumberText(value));
}

std::string Model::ToYaml() const {
  if (impl_->source) {
    // the user's own text with the parameters set so far rewritten in place: nothing else moves
    DocumentChanges changes;
    changes.parameters = impl_->overrides;
    return EditMechanismText(impl_->source->text(), impl_->source->path(), changes);
  }
  const MechanismFile& f = impl_->file;
  const bool has_loads = f.loads.HasMass() || !f.loads.forces.empty() || !f.loads.torques.empty() || !f.loads.springs.empty();
  return WriteMechanismYaml(f.mechanism, f.title.empty() ? f.id : f.title, f.sweep, f.parameters.Values(),
                            has_loads ? &f.loads : nullptr);
}

}  // namespace koppel
