// koppel: planar linkages from YAML files. Each subcommand is added by its own file.
#include "commands.hpp"
#include "common.hpp"

#include "koppel/core/file_error.hpp"
#include "koppel/core/memory.hpp"
#include "koppel/core/temporary_files.hpp"
#include "koppel/koppel.hpp"  // Version

#include <algorithm>
#include <exception>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <thread>

#include <malloc.h>

namespace {

using AddCommand = void (*)(CLI::App&);

// Every command, in the order of `koppel --help`.
constexpr struct {
  const char* name;
  AddCommand add;
} kCommands[] = {
    {"analyze", koppel::cli::AddAnalyzeCommand},     {"catalog", koppel::cli::AddCatalogCommand},
    {"deadcentres", koppel::cli::AddDeadCentresCommand}, {"curve", koppel::cli::AddCurveCommand},
    {"proportional", koppel::cli::AddProportionalCommand}, {"cognates", koppel::cli::AddCognatesCommand},
    {"synth", koppel::cli::AddSynthCommand},         {"range", koppel::cli::AddRangeCommand},
    {"classify", koppel::cli::AddClassifyCommand},   {"plot", koppel::cli::AddPlotCommand},
    {"draw", koppel::cli::AddDrawCommand},           {"view", koppel::cli::AddViewCommand},
    {"edit", koppel::cli::AddEditCommand},
    {"forces", koppel::cli::AddForcesCommand},       {"simulate", koppel::cli::AddSimulateCommand},
    {"atlas", koppel::cli::AddAtlasCommand},         {"bench", koppel::cli::AddBenchCommand},
    {"export", koppel::cli::AddExportCommand},       {"animate", koppel::cli::AddAnimateCommand},
    {"curvature", koppel::cli::AddCurvatureCommand}, {"poles", koppel::cli::AddPolesCommand},
    {"tolerance", koppel::cli::AddToleranceCommand},
};

// The commands the command line can reach: `koppel NAME ...` only NAME, `koppel --version` none,
// anything else (help, no command, a misspelt one) all. Building every command's options took
// a fifth of `koppel --version`'s 10 ms budget (issue 25); CLI11 parses a command line that
// names one command the same with only that command added.
std::unique_ptr<CLI::App> MakeApp(int argc, char** argv) {
  auto app = std::make_unique<CLI::App>(
      "koppel - planar linkages (ebene Getriebe): position analysis, transfer functions, dead centres,\n"
      "coupler curves, a catalog of documented mechanisms and synthesis.\n"
      "Mechanisms are YAML files (see docs/mechanism-file.md), or a catalog id where no such file is\n"
      "(koppel analyze crank-rocker: the catalog's entry; koppel catalog list shows them). Angles are in degrees at the\n"
      "command line, lengths in the file's unit. Exit codes: 0 ok, 1 a check or solve failed, 2 bad input.",
      "koppel");
  app->require_subcommand(1);
  app->set_version_flag("--version", std::string("koppel ") + koppel::Version(), "Print koppel's version and exit");
  app->set_help_all_flag("--help-all", "Print help for every subcommand");
  const std::string first = argc > 1 ? argv[1] : "";
  if (argc == 2 && first == "--version") return app;
  for (const auto& command : kCommands) {
    if (first == command.name) {
      command.add(*app);
      return app;
    }
  }
  for (const auto& command : kCommands) command.add(*app);
  return app;
}

int Run(int argc, char** argv) {
  // `koppel --version` alone, as CLI11 prints it (set_version_flag above), without the exception
  // CLI11 throws for it, whose unwinding searches the executable's unwind tables: 6 % of the
  // instructions and 5 of the 143 page faults of a start-up that has nothing else to do (issue
  // 25). `--version` with anything else still goes through CLI11.
  if (argc == 2 && std::string_view(argv[1]) == "--version") {
    std::cout << "koppel " << koppel::Version() << '\n';
    return koppel::cli::kExitOk;
  }
  const std::unique_ptr<CLI::App> owned = MakeApp(argc, argv);
  CLI::App& app = *owned;
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
  } catch (const std::bad_alloc&) {
    // what was asked needs more memory than there is: a fact about the run, not a bug
    const koppel::MemoryLimit memory = koppel::UsableMemory();
    koppel::cli::Complain("out of memory: the run needed more than the " + koppel::FormatBytes(static_cast<double>(memory.bytes)) +
                          " this process may have (" + memory.source + "); ask for less (fewer samples, a coarser step, a smaller size)");
    return koppel::cli::kExitFailed;
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
  // glibc gives each new thread a heap arena of its own, up to 8 per core, each reserving 64 MB
  // of address space: 187 threads of a Monte Carlo run under `ulimit -v 1200000` ran out of
  // memory that way with a megabyte in use. One arena per core serves threads that compute.
  mallopt(M_ARENA_MAX, std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
  return koppel::cli::FinishStandardOutput(Run(argc, argv));
}
