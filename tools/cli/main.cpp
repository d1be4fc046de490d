// koppel: planar linkages from YAML files. Each subcommand is added by its own file.
#include "commands.hpp"
#include "common.hpp"

#include "koppel/core/file_error.hpp"
#include "koppel/core/temporary_files.hpp"
#include "koppel/koppel.hpp"  // Version

#include <exception>
#include <iostream>

namespace {

int Run(int argc, char** argv) {
  CLI::App app{
      "koppel - planar linkages (ebene Getriebe): position analysis, transfer functions, dead centres,\n"
      "coupler curves, a catalog of documented mechanisms and synthesis.\n"
      "Mechanisms are YAML files (see README.md, 'Mechanism files'), or a catalog id where no such file is\n"
      "(koppel analyze crank-rocker: the catalog's entry; koppel catalog list shows them). Angles are in degrees at the\n"
      "command line, lengths in the file's unit. Exit codes: 0 ok, 1 a check or solve failed, 2 bad input.",
      "koppel"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("koppel ") + koppel::Version(), "Print koppel's version and exit");
  app.set_help_all_flag("--help-all", "Print help for every subcommand");
  koppel::cli::AddAnalyzeCommand(app);
  koppel::cli::AddCatalogCommand(app);
  koppel::cli::AddDeadCentresCommand(app);
  koppel::cli::AddCurveCommand(app);
  koppel::cli::AddProportionalCommand(app);
  koppel::cli::AddCognatesCommand(app);
  koppel::cli::AddSynthCommand(app);
  koppel::cli::AddRangeCommand(app);
  koppel::cli::AddClassifyCommand(app);
  koppel::cli::AddPlotCommand(app);
  koppel::cli::AddDrawCommand(app);
  koppel::cli::AddViewCommand(app);
  koppel::cli::AddEditCommand(app);
  koppel::cli::AddForcesCommand(app);
  koppel::cli::AddSimulateCommand(app);
  koppel::cli::AddAtlasCommand(app);
  koppel::cli::AddBenchCommand(app);
  koppel::cli::AddExportCommand(app);
  koppel::cli::AddAnimateCommand(app);
  koppel::cli::AddCurvatureCommand(app);
  koppel::cli::AddPolesCommand(app);
  koppel::cli::AddToleranceCommand(app);
  // parse flags -> claim the outputs -> the command reads its inputs and works: a target that may
  // not be written is refused before anything is read or computed
  app.parse_complete_callback(koppel::cli::ClaimOutputs);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 returns 0 for --help; usage errors are bad input (2).
    const int code = app.exit(e);
    return code == 0 ? 0 : koppel::cli::kExitBadInput;
  } catch (const koppel::cli::Exit& e) {
    return e.code;
  } catch (const koppel::io::FileError& e) {
    koppel::cli::Complain(e.what());
    return e.kind() == koppel::io::FileError::Kind::kWriteFailed ? koppel::cli::kExitFailed : koppel::cli::kExitBadInput;
  } catch (const std::exception& e) {
    koppel::cli::Complain(std::string("internal error: ") + e.what());
    return koppel::cli::kExitFailed;
  }
  return koppel::cli::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  // SIGINT, SIGTERM, SIGHUP remove a half-written output's temporary file; SIGPIPE keeps its
  // default: a reader that closes the pipe early (| head) ends koppel quietly, as any filter
  koppel::io::RemoveTemporaryFilesOnSignals();
  return koppel::cli::FinishStandardOutput(Run(argc, argv));
}
