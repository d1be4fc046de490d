// koppel export: the mechanism for the workshop, the laser cutter or CAD (tools/export, dxf.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "cycle_flags.hpp"
#include "model_loading.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/export/export.hpp"

namespace koppel::cli {
namespace export_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, at, out;
  std::vector<std::string> sets;
  CycleFlags cycle;
  bool dxf = false;
};

void Run(const Args& args) {
  if (!args.dxf) {
    Complain("name the format to write: --dxf (the only one so far)");
    throw Exit{kExitBadInput};
  }
  const Model model = LoadModel(args.file, args.sets);
  const Mechanism& m = model.mechanism();
  plot::WorkshopOptions options;
  options.cycle = ReadCycleFlags(model, args.cycle);
  if (!args.at.empty()) options.at = ParseNumberFlag("--at", args.at) * (m.InputIsAngle() ? DegToRad(1.0) : 1.0);
  const int units = plot::DxfUnits(model.loads().metres_per_unit, model.loads().length_unit_given);
  WriteExportResult(args.file, args.out, plot::ExportDxf(m, options, units));
}

}  // namespace
}  // namespace export_command

void AddExportCommand(CLI::App& app) {
  using namespace export_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "The mechanism as a DXF drawing (AutoCAD 2000, written with dxflib) for the workshop, a laser cutter or CAD, at one\n"
      "pose: each moving link a plate of width W around its points with a hole of diameter D at each joint, a slot of\n"
      "width D along each guide as long as its pin travels, the frame's pivot holes and guide slots, the coupler points\n"
      "as POINTs, and each traced point's coupler curve as a polyline over the drivable range of the assembly branch\n"
      "(closed for a full turn, 360 segments). One layer per link (its name) and per curve (curve-K).\n"
      "Coordinates are the file's, in its length unit: a pivot at (0, 0) in the file is at the drawing's origin.\n"
      "$INSUNITS says the unit where the file names one (units: {length: mm} -> 4 = mm; m 6, cm 5, in 1, ...);\n"
      "a file without `units` gives a unitless drawing (0).\n"
      "Example: koppel export catalog/entries/mzc-crank-rocker.yaml --dxf --at 30 --trace K -o m.dxf");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_flag("--dxf", args->dxf, "Write a DXF drawing");
  cmd->add_option("--at", args->at, "Input of the pose drawn [deg for an R drive] (default: the assembly hint's input)");
  AddCycleFlags(cmd, args->cycle);
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write the drawing to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
