// koppel edit: one self-contained HTML page that edits the mechanism with koppel's own solver
// compiled to WebAssembly (see editor_page.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include "koppel/plot/editor_page.hpp"

namespace koppel::cli {
namespace edit_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file;
  std::vector<std::string> sets;
  std::string out;
};

void Run(const Args& args) {
  const Model model = LoadModel(args.file, args.sets);
  const plot::PlotResult r = plot::EditorPage(model);
  if (r.status == plot::PlotStatus::kFailed) {
    Complain(args.file + ": " + r.message);
    throw Exit{kExitFailed};
  }
  WriteOutput(args.out, r.svg);
  // the page is written either way (its sliders can fix the file); a sweep of the file's range
  // that does not reach every sample is said here too, and the exit code says it
  const SweepTable t = model.Sweep(0);
  if (!t.record.complete()) {
    Complain(args.file + ": " + (t.message.empty() ? t.sweep_status : t.message) + " (the page says so)");
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace edit_command

void AddEditCommand(CLI::App& app) {
  using namespace edit_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "edit",
      "One self-contained HTML editor page (opens offline from disk, no server) whose solver is koppel's own kernel\n"
      "compiled to WebAssembly: drag the frame pivots and joint points (the mechanism re-solves on its branch; where\n"
      "it cannot assemble the page says so and keeps the last valid pose), move the parameter sliders (the file's\n"
      "formulas are evaluated again), play or scrub the input, undo; the coupler curves of the point outputs, the\n"
      "transfer functions to 2nd order and the transmission angle charted, dead centres and singular points marked.\n"
      "Export the edited mechanism as YAML (koppel reads it back to the same numbers), the scheme as SVG or PNG.\n"
      "Scripting: window.koppel.ready (a Promise), sweep(from, to, step, order) -> {columns, rows} as\n"
      "`koppel analyze --format json`, set(name, value), toYaml().\n"
      "The page is written also when the file's sweep does not reach every sample; the exit code is then 1.\n"
      "Example: koppel edit catalog/entries/slider-crank-offset.yaml -o editor.html");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE (the page starts from it)");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write the page to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
