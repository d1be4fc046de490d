#include "koppel/plot/scheme_drawing.hpp"

#include "koppel/analysis/coupler_curve.hpp"
#include "koppel/analysis/dead_centres.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/plot/sampled_run.hpp"
#include "koppel/plot/scheme.hpp"
#include "koppel/solver/sweep.hpp"

#include <fmt/format.h>

#include <cmath>

namespace koppel::plot {
namespace {

// The request's sweep in the solver's units (radians for an R drive), order 0: poses only.
SweepOptions SchemeSweepOf(const Model& model, const SchemeRequest& request) {
  const double unit = model.input_is_angle() ? DegToRad(1.0) : 1.0;
  const SweepSpan span = model.Span(request.from, request.to, request.step);
  SweepOptions range;
  range.from = span.from * unit;
  range.to = span.to * unit;
  range.step = span.step * unit;
  range.order = 0;
  range.continuation.at_branch_point = request.at_branch_point;
  return range;
}

// An input for people: degrees for an R drive.
double Shown(const Model& model, double input) { return model.input_is_angle() ? RadToDeg(input) : input; }

// The labels of the caption: φ for phi, degrees for an R drive.
struct InputWords {
  std::string name, unit;
};
InputWords InputWordsOf(const Model& model) {
  return {model.input_name() == "phi" ? "φ" : model.input_name(), model.input_is_angle() ? "°" : ""};
}

// The index of a scalar output by name ("": the first scalar output); -1 when there is none.
int ScalarOutputIndex(const Mechanism& m, const std::string& name) {
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o)
    if (m.outputs[o].Components() == 1 && (name.empty() || m.outputs[o].name == name)) return o;
  return -1;
}

// The dead-centre poses of request.output drawn over the scheme, named in the caption; what
// cannot be drawn goes to `problems`. Searched on the drawing's own sweep (its branch and its
// --at-branch-point, so that the search stops where the sweep stops) at the resolution of
// `koppel deadcentres`, 1 deg, or the sweep's step when finer. (Model::FindDeadCentres takes no
// at_branch_point yet: the analysis is called directly, as the picture library may.)
void AddDeadCentrePoses(const Model& model, const SchemeRequest& request, const SampledRun& run, SchemeScene& scene,
                        std::vector<std::string>& problems) {
  const Mechanism& m = model.mechanism();
  const InputWords words = InputWordsOf(model);
  const int output = ScalarOutputIndex(m, request.output);
  if (output < 0) throw InputError({Diagnostic{model.path(), 0, 0, "output", "'" + request.output + "' is not a scalar output"}});
  SweepOptions search = SchemeSweepOf(model, request);
  const double degree = model.input_is_angle() ? DegToRad(1.0) : 1.0;
  search.step = degree < std::abs(search.step) ? degree : search.step;
  const DeadCentreReport dead = FindDeadCentres(m, output, 0, search);
  if (!dead.sweep.complete()) problems.push_back("dead centres: " + dead.sweep.message);
  int unnamed = 0;
  std::string list;
  for (const DeadCentre& d : dead.points) {
    OverlayPose overlay;
    overlay.suffix = d.kind == DeadCentreKind::kExtended ? "a" : d.kind == DeadCentreKind::kFolded ? "i" : std::to_string(++unnamed);
    const double shown = Shown(model, d.input);
    const Expected<Eigen::VectorXd> dead_pose = PoseAt(m, run, d.input);
    if (!dead_pose) {
      problems.push_back("dead centre at " + fmt::format("{:g}", shown) + ": " + dead_pose.error());
      continue;
    }
    overlay.q = *dead_pose;
    list += fmt::format("{}{}_{} = {:.2f}{}", list.empty() ? "" : ", ", words.name, overlay.suffix, shown, words.unit);
    scene.overlays.push_back(std::move(overlay));
  }
  if (dead.points.empty()) problems.push_back("no dead centre of '" + m.outputs[output].name + "' found");
  if (!list.empty()) scene.caption += "; dead centres of " + m.outputs[output].name + ": " + list;
}

}  // namespace

bool SchemeRequest::IsValid(const Model& model, std::string* why) const {
  const SweepOptions range = SchemeSweepOf(model, *this);
  std::string problem;
  if (range.step == 0 || SampleCount(range.from, range.to, range.step) > kMaxSchemeSamples)
    problem = "the sweep's step must not be 0 (and give at most 20000 samples)";
  if (why) *why = problem;
  return problem.empty();
}

SchemeDrawing DrawSchemeOf(const Model& model, const SchemeRequest& request) {
  if (std::string why; !request.IsValid(model, &why)) throw InputError({Diagnostic{model.path(), 0, 0, "from/to/step", why}});
  const Mechanism& m = model.mechanism();
  const double unit = model.input_is_angle() ? DegToRad(1.0) : 1.0;
  SchemeDrawing drawing;
  // one sweep for the view, the guides' lengths, the trace and the poses' starting points
  const Mechanism traced = request.trace ? WithPointOutput(m, *request.trace) : m;
  const SampledRun run = SampleMechanism(traced, SchemeSweepOf(model, request));
  if (run.size() == 0) {
    drawing.status = PlotStatus::kFailed;
    drawing.message = run.message;
    return drawing;
  }
  if (!run.complete) drawing.problems.push_back(run.message);
  const InputWords words = InputWordsOf(model);
  SchemeScene scene;
  const double at = request.at ? *request.at * unit : m.hint.input;
  const Expected<Eigen::VectorXd> pose = PoseAt(m, run, at);
  if (!pose) {
    drawing.status = PlotStatus::kFailed;
    drawing.message = "cannot reach " + words.name + " = " + fmt::format("{:g}", Shown(model, at)) + ": " + pose.error();
    return drawing;
  }
  scene.q = *pose;
  scene.caption = fmt::format("{}: {} = {:.2f}{}", m.name, words.name, Shown(model, at), words.unit);
  for (int i = 0; i < run.size(); ++i) scene.extent.push_back(run.poses.row(i).transpose());
  if (request.trace) {
    for (const Stretch& s : run.stretches) {
      scene.trace.emplace_back();
      for (int i = s.begin; i < s.end; ++i) scene.trace.back().emplace_back(run.outputs(i, 0), run.outputs(i, 1));
    }
    scene.trace_name = request.trace_name;
  }
  if (request.dead_centres) AddDeadCentrePoses(model, request, run, scene, drawing.problems);
  drawing.svg = DrawScheme(m, scene);
  if (!drawing.problems.empty()) drawing.status = PlotStatus::kPartial;
  return drawing;
}

}  // namespace koppel::plot
