// koppel cognates: the two Roberts–Chebyshev cognates of a four-bar, as mechanism files.
#include "commands.hpp"
#include "common.hpp"

#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/synthesis/cognates.hpp"

#include <filesystem>

namespace koppel::cli {
namespace cognates_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, point, dir;
  std::vector<std::string> sets;
  std::string format = "csv", out;
};

void Run(const Args& args) {
  CheckFormat(args.format);
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const PointRef point = ResolvePoint(file.mechanism, args.point, "--point");
  const Cognates c = RobertsCognates(file.mechanism, point);
  if (!c.ok()) {
    Complain(args.file + ": " + c.message);
    throw Exit{c.status == DesignStatus::kReanalysisFailed ? kExitFailed : kExitBadInput};
  }
  MakeOutputDirectory(args.dir);
  const std::string note = "Roberts–Chebyshev cognate of " + file.path + " (koppel cognates): traces the same curve of K.\n";
  const SweepDefaults sweep = file.sweep;
  // cognate 1 is driven by a link that follows the original coupler: sweep its own input range,
  // a hundredth of a degree inside the dead centres at its ends
  double lo = RadToDeg(c.first_input_min) + 0.01, hi = RadToDeg(c.first_input_max) - 0.01;
  if (!(hi > lo)) {
    // a coupler that only translates (a parallelogram): cognate 1's crank stands still while K
    // moves, so its own input cannot drive it along the curve
    Complain(args.file + ": note: cognate 1's crank follows the original coupler, which does not turn here: cognate 1 "
             "cannot be driven by its crank (its file's sweep is its one pose)");
    lo = hi = RadToDeg(0.5 * (c.first_input_min + c.first_input_max));
  }
  const SweepDefaults sweep_first{lo, hi, hi > lo ? (hi - lo) / 180 : 1.0};
  const std::string first = (std::filesystem::path(args.dir) / (c.first.name + ".yaml")).string();
  const std::string second = (std::filesystem::path(args.dir) / (c.second.name + ".yaml")).string();
  WriteOutput(first, WriteMechanismYaml(c.first, note + "Pivots A0 and C0; its crank A0A1 turns with the original coupler.", sweep_first));
  WriteOutput(second, WriteMechanismYaml(c.second, note + "Pivots C0 and B0; its crank C0C2 turns with the original crank: same input.", sweep));
  Summary s;
  s.Add("cognate1_A0C0", c.frame_first, file.loads.LengthUnit());
  s.Add("cognate1_A0A1", c.crank_first, file.loads.LengthUnit());
  s.Add("cognate1_A1C1", c.coupler_first, file.loads.LengthUnit());
  s.Add("cognate1_C0C1", c.rocker_first, file.loads.LengthUnit());
  s.Add("cognate1_A1K", c.k_first, file.loads.LengthUnit());
  s.Add("cognate1_C1K", c.l_first, file.loads.LengthUnit());
  s.Add("cognate1_input_min", RadToDeg(c.first_input_min), "deg");
  s.Add("cognate1_input_max", RadToDeg(c.first_input_max), "deg");
  s.Add("cognate2_C0B0", c.frame_second, file.loads.LengthUnit());
  s.Add("cognate2_C0C2", c.crank_second, file.loads.LengthUnit());
  s.Add("cognate2_C2B2", c.coupler_second, file.loads.LengthUnit());
  s.Add("cognate2_B0B2", c.rocker_second, file.loads.LengthUnit());
  s.Add("cognate2_B2K", c.k_second, file.loads.LengthUnit());
  s.Add("cognate2_C2K", c.l_second, file.loads.LengthUnit());
  WriteOutput(args.out, args.format == "json" ? JsonText(s.ToJson()) : s.ToCsv());
}

}  // namespace
}  // namespace cognates_command

void AddCognatesCommand(CLI::App& app) {
  using namespace cognates_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "cognates",
      "The two cognates (Ersatzgetriebe, Satz von Roberts) of a four-bar: four-bars whose coupler point traces the\n"
      "same coupler curve. Writes DIR/<name>-cognate-1.yaml (pivots A0, C0) and DIR/<name>-cognate-2.yaml\n"
      "(pivots C0, B0, driven with the original's input) and prints their link lengths. The third pivot C0\n"
      "makes triangle A0 B0 C0 similar to the coupler triangle A B K.\n"
      "Example: koppel cognates catalog/entries/mzc-crank-rocker.yaml --point K -o cognates/");
  cmd->add_option("file", args->file, "Mechanism YAML file (a four-bar of R joints, driven at a frame pivot)")->required();
  cmd->add_option("--point", args->point, "The coupler point: a point output (K), link.point, or a point name")->required();
  OutputDirectory(cmd->add_option("-o,--dir", args->dir, "Directory for the two cognate files")->required());
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  cmd->add_option("--format", args->format, "csv (default) or json, for the printed dimensions");
  OutputFile(cmd->add_option("--output-file", args->out, "Write the dimensions to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
