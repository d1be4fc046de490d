// koppel synth function: function generation (function_synthesis.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include "koppel/api/synthesis.hpp"
#include "koppel/api/design_file.hpp"

namespace koppel::cli {
namespace synth_function_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string spec, yaml, out, error_curve, format = "csv", units, design;
};

void Run(const Args& args) {
  CheckFormat(args.format);
  const DesignSpace space = args.design.empty() ? DesignSpace() : Checked([&] { return ReadDesignFile(args.design); });  // file:line, exit 2
  const Design d = Checked([&] { return SynthesiseFunctionFile(args.spec, args.units, space); });  // bad input: its diagnostics, exit 2
  if (!d.figures.empty()) {  // a design that fails its check still shows its lengths
    Summary s;
    // error_at_precision: in the mechanism file's comment, not among the printed rows
    for (const DesignFigure& f : d.figures)
      if (f.name != "error_at_precision") s.Add(f.name, f.value, f.unit);
    if (!args.error_curve.empty() && !d.curve.columns.empty()) WriteOutput(args.error_curve, Table{d.curve.columns, d.curve.rows}.ToCsv());
    if (!args.yaml.empty() && d.ok()) WriteOutput(args.yaml, d.yaml);
    WriteOutput(args.out, args.format == "json" ? JsonText(s.ToJson()) : s.ToCsv());
  }
  if (!d.ok()) {
    Complain(args.spec + ": " + d.message);
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
      "or at, frame; see docs/synthesis.md). Freudenstein's equation: exact for 3 precision points (Chebyshev spacing unless `at:`),\n"
      "least squares for more, then polished by the Ceres fit on the true output through the mechanism. Prints crank,\n"
      "coupler, rocker, frame (slider-crank: crank, coupler, offset), error_max, the largest structural error over the\n"
      "whole range (deg, or length) by the solver, and mu_min, the least transmission angle over the input range (deg; a\n"
      "design that passes a small one jams in practice). Exit 1 when the design does not run through the whole input range.\n"
      "Example: koppel synth function tests/data/function-log10.yaml --error-curve error.csv -o log10-generator.yaml");
  cmd->add_option("spec", args->spec, "SPEC.yaml")->required();
  OutputFile(cmd->add_option("-o,--yaml", args->yaml, "Write the mechanism as a YAML file"));
  OutputFile(cmd->add_option("--error-curve", args->error_curve, "Write the structural error over the range to this CSV file"));
  OutputFile(cmd->add_option("--output-file", args->out, "Write the table to this file instead of stdout"));
  cmd->add_option("--format", args->format, "csv (default) or json");
  cmd->add_option("--design", args->design, "The design space: a YAML file (lengths, ratio, pivots, input, mu_min; A0 is at the\n"
                                             "origin, B0 at (frame, 0)): a generator outside it exits 1 naming the constraint");
  cmd->add_option("--units", args->units, "The length unit of the mechanism file -o writes: it says `units: {length: UNIT}`, the\n"
                                           "table labels lengths with it (m, dm, cm, mm, um, km, in, ft; default: none)");
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
