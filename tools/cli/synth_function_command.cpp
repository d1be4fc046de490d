// koppel synth function: function generation (function_synthesis.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/catalog/synthesis_spec.hpp"
#include "koppel/core/angles.hpp"

#include <fmt/core.h>

#include <iostream>

namespace koppel::cli {
namespace synth_function_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string spec, yaml, out, error_curve, format = "csv";
};

void Run(const Args& args) {
  CheckFormat(args.format);
  FunctionSpecFile spec = Checked([&] { return ReadFunctionSpec(args.spec); });  // bad input: its diagnostics, exit 2
  const FunctionRequest& r = spec.request;
  const FunctionDesign d = SynthesiseFunction(r);
  if (d.status == FunctionStatus::kInvalidRequest || d.status == FunctionStatus::kNoMechanism) {
    Complain(args.spec + ": " + d.Brief());
    throw Exit{d.status == FunctionStatus::kInvalidRequest ? kExitBadInput : kExitFailed};
  }
  const bool four_bar = r.type == FunctionGenerator::kFourBar;
  // the output in the user's unit: degrees for the rocker, length for the slider
  auto out_unit = [&](double v) { return four_bar ? RadToDeg(v) : v; };
  Summary s;
  s.Add("crank", d.crank, "length");
  s.Add("coupler", d.coupler, "length");
  if (four_bar) {
    s.Add("rocker", d.rocker, "length");
    s.Add("frame", d.frame, "length");
  } else {
    s.Add("offset", d.offset, "length");
  }
  // A design that misses a precision point was re-analysed on another assembly branch: its
  // lengths are the equations' solution, but its error curve belongs to a different mechanism.
  const bool curve_is_the_design = d.status != FunctionStatus::kMissesPoints;
  if (curve_is_the_design) s.Add("error_max", out_unit(d.error_max), four_bar ? "deg" : "length");
  if (!args.error_curve.empty() && curve_is_the_design) {
    Table t;
    t.columns = {"x", "crank", "desired", "generated", "error"};
    for (const StructuralErrorSample& e : d.error_curve)
      t.rows.push_back({e.x, RadToDeg(e.input), out_unit(e.desired), out_unit(e.generated), out_unit(e.error)});
    WriteOutput(args.error_curve, t.ToCsv());
  }
  if (!args.yaml.empty() && d.ok()) {  // its comment states the structural error: only for a design
    std::string points;
    for (double x : d.precision_x) points += fmt::format("{}{:.6g}", points.empty() ? "" : ", ", x);
    const std::string comment = fmt::format(
        "Function generator (koppel synth function {}): y = {} for x in [{:.6g}, {:.6g}]; the crank angle phi [deg] maps x\n"
        "from {:.6g} to {:.6g}, the output {} maps y from {:.6g} to {:.6g}. Precision points x = {}{}.\n"
        "Structural error: at most {:.6g} {} over the range, {:.3g} at the precision points.",
        args.spec, spec.formula, r.x_from, r.x_to, RadToDeg(r.input_from), RadToDeg(r.input_to), four_bar ? "psi [deg]" : "s", out_unit(r.output_from),
        out_unit(r.output_to), points, d.polished ? " (least squares, polished through the mechanism)" : "", out_unit(d.error_max),
        four_bar ? "deg" : "length", out_unit(d.error_at_precision));
    WriteOutput(args.yaml, WriteMechanismYaml(d.mechanism, comment, {RadToDeg(r.input_from), RadToDeg(r.input_to), (RadToDeg(r.input_to) - RadToDeg(r.input_from)) / 360}));
  }
  WriteOutput(args.out, args.format == "json" ? JsonText(s.ToJson()) : s.ToCsv());
  if (!d.ok()) {
    Complain(args.spec + ": " + d.Brief());
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace synth_function_command

void AddFunctionSubcommand(CLI::App& synth) {
  using namespace synth_function_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = synth.add_subcommand(
      "function",
      "Function generation: a four-bar whose rocker angle (or a slider-crank whose slider displacement, `type: slider-crank`)\n"
      "follows y = f(x) while the crank angle follows x, both mapped linearly (SPEC.yaml: function, x, input, output, points\n"
      "or at, frame; see README). Freudenstein's equation: exact for 3 precision points (Chebyshev spacing unless `at:`),\n"
      "least squares for more, then polished by the Ceres fit on the true output through the mechanism. Prints crank,\n"
      "coupler, rocker, frame (slider-crank: crank, coupler, offset) and error_max, the largest structural error over the\n"
      "whole range (deg, or length) by the solver. Exit 1 when the design does not run through the whole input range.\n"
      "Example: koppel synth function tests/data/function-log10.yaml --error-curve error.csv -o log10-generator.yaml");
  cmd->add_option("spec", args->spec, "SPEC.yaml")->required();
  OutputFile(cmd->add_option("-o,--yaml", args->yaml, "Write the mechanism as a YAML file"));
  OutputFile(cmd->add_option("--error-curve", args->error_curve, "Write the structural error over the range to this CSV file"));
  OutputFile(cmd->add_option("--output-file", args->out, "Write the table to this file instead of stdout"));
  cmd->add_option("--format", args->format, "csv (default) or json");
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
