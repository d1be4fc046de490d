#include "koppel/plot/view_page.hpp"

#include "plot_support.hpp"

#include "koppel/analysis/coupler_curve.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/plot/sampled_run.hpp"
#include "koppel/plot/scheme.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace koppel::plot {
namespace assets {  // tools/view/view.cmake (uPlot's in plot_support.hpp)
extern const char* const k_template;
extern const char* const k_script;
}  // namespace assets

namespace {

// Six significant digits: well below a pixel on the page, and a third of the full digits' size.
double Rounded(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", v);
  return std::strtod(s, nullptr);
}

// Each output's page data: a point's trace in the scheme and its x and y in the readout; any
// other output's chart of its value and transfer functions (a transmission angle: its value only),
// also in the readout.
void AddViewOutputs(const Mechanism& m, const SampledRun& run, const std::string& length_unit, SchemeScene* scene, nlohmann::json* charts,
                    nlohmann::json* readout) {
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
    const Output& out = m.outputs[o];
    if (out.kind == OutputKind::kPoint) {
      // the coupler curve, traced in the scheme; x and y in the numbers
      for (const Stretch& s : run.stretches) {
        scene->trace.emplace_back();
        for (int i = s.begin; i < s.end; ++i)
          scene->trace.back().emplace_back(run.outputs(i, run.Column(m, o, 0, 0)), run.outputs(i, run.Column(m, o, 1, 0)));
      }
      scene->trace_name = out.name;
      for (int c = 0; c < 2; ++c) {
        std::vector<double> v;
        for (int i = 0; i < run.size(); ++i) v.push_back(Rounded(run.outputs(i, run.Column(m, o, c, 0))));
        readout->push_back({{"label", out.ComponentLabel(c)}, {"values", v}});
      }
      continue;
    }
    const int orders = out.kind == OutputKind::kTransmissionAngle ? 1 : 3;
    nlohmann::json series = nlohmann::json::array();
    for (int k = 0; k < orders; ++k) {
      std::vector<double> v;
      for (int i = 0; i < run.size(); ++i) v.push_back(Rounded(ShownOutput(m, o, k, run.outputs(i, run.Column(m, o, 0, k)))));
      const std::string label = DerivativeLabel(m, o, "", k, length_unit);
      series.push_back({{"label", label}, {"values", v}});
      readout->push_back({{"label", label}, {"values", v}});
    }
    charts->push_back({{"title", out.kind == OutputKind::kTransmissionAngle ? "transmission angle " + out.name
                                                                             : out.name + " and its transfer functions"},
                      {"series", series}});
  }
}

}  // namespace

bool ViewOptions::IsValid(std::string* why) const {
  // 3600 frames at most: the page would grow past a few MB
  return RangeIsValid(range, 3601, why);
}

PlotResult ViewPage(const Mechanism& m, const ViewOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) return {PlotStatus::kFailed, why, ""};
  SweepOptions sweep = options.range;
  sweep.order = 2;
  const SampledRun run = SampleMechanism(m, sweep);
  if (run.size() == 0) return {PlotStatus::kFailed, run.message, ""};
  nlohmann::json data;
  data["title"] = options.title.empty() ? m.name : options.title;
  const std::string input = m.drive.input_name == "phi" ? "φ" : m.drive.input_name;
  data["input_label"] = input + " [" + (m.InputIsAngle() ? "deg" : options.length_unit) + "]";
  data["coordinates"] = run.poses.cols();
  std::vector<double> poses, inputs;
  for (int i = 0; i < run.size(); ++i) {
    inputs.push_back(Rounded(ShownInput(m, run.inputs[i])));
    for (int c = 0; c < run.poses.cols(); ++c) poses.push_back(Rounded(run.poses(i, c)));
  }
  data["inputs"] = inputs;
  data["poses"] = poses;
  std::vector<int> breaks;
  for (const Stretch& s : run.stretches)
    if (s.begin > 0) breaks.push_back(s.begin);
  data["breaks"] = breaks;
  // a full turn of an R drive, completely computed, loops; anything else goes back and forth
  data["cyclic"] = run.complete && m.InputIsAngle() && std::abs(std::abs(options.range.to - options.range.from) - 2 * kPi) < 1e-9;
  data["message"] = run.complete ? "" : run.message;
  nlohmann::json charts = nlohmann::json::array(), readout = nlohmann::json::array();
  SchemeScene scene;
  AddViewOutputs(m, run, options.length_unit, &scene, &charts, &readout);
  data["charts"] = charts;
  data["readout"] = readout;
  scene.q = run.poses.row(0).transpose();
  for (int i = 0; i < run.size(); ++i) scene.extent.push_back(run.poses.row(i).transpose());
  scene.caption = input + " = " + std::to_string(ShownInput(m, run.inputs[0]));
  scene.animatable = true;
  scene.width = 560;
  std::string title = nlohmann::json(data["title"]).get<std::string>();
  PlotResult result;
  result.svg = Fill(assets::k_template, {{"TITLE", EscapeXml(title)},
                                         {"UPLOT_CSS", assets::k_uplot_css},
                                         {"SCHEME", DrawScheme(m, scene)},
                                         {"DATA", ScriptSafe(data.dump())},
                                         {"UPLOT_LICENSE", assets::k_uplot_license},
                                         {"UPLOT_JS", assets::k_uplot_js},
                                         {"VIEW_JS", assets::k_script}});
  if (!run.complete) {
    result.status = PlotStatus::kPartial;
    result.message = run.message;
  }
  return result;
}

}  // namespace koppel::plot
