// koppel atlas build|merge: the coupler-curve atlas of path synthesis (atlas.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "progress_bar.hpp"

#include "koppel/api/atlas.hpp"

#include <fmt/core.h>

#include <chrono>
#include <iostream>

namespace koppel::cli {
namespace atlas_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string count, seed = "1", shard, out, threads, format;
  std::vector<std::string> inputs;
  bool quiet = false;
};

std::uint64_t WholeNumber(const std::string& flag, const std::string& text, std::uint64_t hi) {
  std::size_t used = 0;
  std::uint64_t v = 0;
  try {
    v = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || v > hi || text[0] == '-') {
    Complain(fmt::format("{}: expected a whole number from 0 to {}, found '{}'", flag, hi, text));
    throw Exit{kExitBadInput};
  }
  return v;
}

void RequireOutput(const Args& args) {
  if (args.out.empty() || args.out == "-") {
    Complain("-o ATLAS is required (the atlas is a binary file)");
    throw Exit{kExitBadInput};
  }
}

// The atlas is binary (-o); with --format, a summary of what was written goes to stdout as the
// other commands' quantity,value,unit tables (csv or json). Without it stdout stays empty.
void CheckSummaryFormat(const Args& args) {
  if (!args.format.empty()) CheckFormat(args.format);
}
void PrintSummary(const Args& args, const Summary& s) {
  if (!args.format.empty()) WriteOutput("", args.format == "json" ? JsonText(s.ToJson()) : s.ToCsv());
}

void Build(const Args& args) {
  RequireOutput(args);
  CheckSummaryFormat(args);
  AtlasBuildSpec o;
  o.count = WholeNumber("--count", args.count, AtlasCurveLimit());
  o.seed = WholeNumber("--seed", args.seed, UINT64_MAX);
  if (!args.shard.empty()) {
    const auto slash = args.shard.find('/');
    if (slash == std::string::npos) {
      Complain("--shard: expected k/n (0 <= k < n), found '" + args.shard + "'");
      throw Exit{kExitBadInput};
    }
    o.shard = static_cast<int>(WholeNumber("--shard", args.shard.substr(0, slash), 1'000'000));
    o.shards = static_cast<int>(WholeNumber("--shard", args.shard.substr(slash + 1), 1'000'000));
  }
  if (!args.threads.empty()) o.threads = static_cast<int>(WholeNumber("--threads", args.threads, kMaxThreads));
  if (const std::string why = AtlasBuildProblem(o); !why.empty()) {
    Complain(why);
    throw Exit{kExitBadInput};
  }
  // the whole shard is held in memory: refused up front with the figure, not bad_alloc later
  if (const Outcome fits = AtlasBuildFits(o); !fits) {
    Complain("--count " + args.count + (args.shard.empty() ? "" : " --shard " + args.shard) + ": " + fits.error());
    throw Exit{kExitBadInput};
  }
  const auto start = std::chrono::steady_clock::now();
  AtlasImage atlas;
  {
    ProgressBar bar("koppel atlas build", !args.quiet);
    atlas = BuildAtlasImage(o, bar.Callback());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  WriteOutput(args.out, atlas.bytes);
  Summary summary;
  summary.Add("curves", static_cast<double>(atlas.curves), "");
  summary.Add("closed", static_cast<double>(atlas.closed), "");
  summary.Add("rocker_arcs", static_cast<double>(atlas.curves - atlas.closed), "");
  summary.Add("seconds", seconds, "s");
  PrintSummary(args, summary);
  if (!args.quiet)
    std::cerr << fmt::format("koppel atlas build: {} curves ({} closed, {} rocker arcs) of seed {}, shard {}/{}, in {:.2f} s\n", atlas.curves,
                             atlas.closed, atlas.curves - atlas.closed, o.seed, o.shard, o.shards, seconds);
}

void Merge(const Args& args) {
  RequireOutput(args);
  CheckSummaryFormat(args);
  if (args.inputs.empty()) {
    Complain("atlas merge: name the atlases to merge");
    throw Exit{kExitBadInput};
  }
  const Expected<AtlasImage> merged = MergeAtlasFiles(args.inputs);
  if (!merged) {
    Complain("atlas merge: " + merged.error());
    throw Exit{kExitBadInput};
  }
  WriteOutput(args.out, merged->bytes);
  Summary summary;
  summary.Add("curves", static_cast<double>(merged->curves), "");
  summary.Add("atlases", static_cast<double>(args.inputs.size()), "");
  PrintSummary(args, summary);
  if (!args.quiet) std::cerr << fmt::format("koppel atlas merge: {} curves from {} atlases\n", merged->curves, args.inputs.size());
}

}  // namespace
}  // namespace atlas_command

void AddAtlasCommand(CLI::App& app) {
  using namespace atlas_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("atlas", "The coupler-curve atlas of path synthesis (koppel synth path): build it, merge shards.");
  cmd->require_subcommand(1);
  CLI::App* build = cmd->add_subcommand(
      "build",
      "Draws N four-bars from the documented space (docs/synthesis.md, 'Path generation': link ratios log-uniform in [1/5, 5],\n"
      "coupler points over a box around the coupler, Grashof and non-Grashof alike) and stores each coupler curve's\n"
      "normalised Fourier descriptor with its dimensions. Entry i of seed S is the same whoever draws it: --shard k/n\n"
      "draws the k-th of n equal parts of the N (k from 0), so n machines or jobs build the parts and `atlas merge` joins\n"
      "them into the very atlas one `build` would write. Uses every core (--threads).\n"
      "Example: koppel atlas build --count 100000 -o atlas.bin");
  build->add_option("--count", args->count, "Curves in the whole atlas (every shard together)")->required();
  build->add_option("--seed", args->seed, "Seed of the draws (default 1)");
  build->add_option("--shard", args->shard, "k/n: build only the k-th of n parts (0 <= k < n)");
  OutputFile(build->add_option("-o,--output", args->out, "The atlas file to write")->required());
  build->add_option("--threads", args->threads, "Threads (default: one per core; at most 256, kMaxThreads)");
  build->add_flag("--quiet", args->quiet, "No summary on stderr");
  build->add_option("--format", args->format, "csv or json: also print a summary (curves, closed, rocker_arcs, seconds) on stdout");
  build->callback([args] { Build(*args); });
  CLI::App* merge = cmd->add_subcommand("merge",
                                        "Joins atlases (the shards of one build, or builds of different seeds) into one, ordered by seed and\n"
                                        "index; refuses a curve that appears twice.\n"
                                        "Examples: koppel atlas build --count 20000 --shard 0/2 -o part0.bin\n"
                                        "          koppel atlas build --count 20000 --shard 1/2 -o part1.bin\n"
                                        "          koppel atlas merge part0.bin part1.bin -o merged.bin");
  merge->add_option("atlases", args->inputs, "The atlas files")->required();
  OutputFile(merge->add_option("-o,--output", args->out, "The merged atlas file")->required());
  merge->add_flag("--quiet", args->quiet, "No summary on stderr");
  merge->add_option("--format", args->format, "csv or json: also print a summary (curves, atlases) on stdout");
  merge->callback([args] { Merge(*args); });
}

}  // namespace koppel::cli
