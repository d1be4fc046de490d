// koppel cognates: the two Roberts–Chebyshev cognates of a four-bar, as mechanism files.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include "koppel/api/synthesis.hpp"

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
  const Model model = LoadModel(args.file, args.sets);
  ResolvePoint(model.mechanism(), args.point, "--point");  // a point not there: named with its flag, exit 2
  const Designs c = Checked([&] { return FindCognates(model, args.point); });
  if (!c.ok()) {
    Complain(args.file + ": " + c.message);
    throw Exit{c.status == DesignStatus::kReanalysisFailed ? kExitFailed : kExitBadInput};
  }
  for (const std::string& note : c.notes) Complain(args.file + ": note: " + note);
  MakeOutputDirectory(args.dir);
  Summary s;
  for (size_t i = 0; i < c.designs.size(); ++i) {
    const Design& d = c.designs[i];
    WriteOutput((std::filesystem::path(args.dir) / (d.model->name() + ".yaml")).string(), d.yaml);
    for (const DesignFigure& f : d.figures) s.Add("cognate" + std::to_string(i + 1) + "_" + f.name, f.value, f.unit);
  }
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
