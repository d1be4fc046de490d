// koppel synth path: path generation from an atlas (path_synthesis.hpp).
#include "commands.hpp"
#include "common.hpp"

#include "koppel/api/path_synthesis.hpp"
#include "koppel/api/design_file.hpp"
#include "koppel/core/angles.hpp"
#include "model_loading.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <cmath>

namespace koppel::cli {
namespace synth_path_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string points, atlas, top = "10", candidates, dir, out, threads, format = "csv", design, units, timing_step, starts, seed;
  bool open = false;
};

// POINTS.csv (koppel/api/path_synthesis.hpp); every bad line reported.
TimedPathPoints ReadPoints(const std::string& path) {
  try {
    return ReadPathPointsFile(path);
  } catch (const InputError& e) {
    for (const Diagnostic& d : e.diagnostics()) std::cerr << d.ToString() << "\n";
    throw Exit{kExitBadInput};
  }
}

// A design as a mechanism file in --dir, its comment saying where it came from.
void WriteDesign(const Args& args, const PathDesign& l, size_t i) {
  const std::string name = fmt::format("path-{}", i + 1);
  const std::string origin = args.atlas.empty()
                                 ? fmt::format("{}", l.fit.substr(0, 200))
                                 : fmt::format("atlas curve {} of seed {}, polished by the fit through this mechanism: {}", l.atlas_index,
                                               l.atlas_seed, l.fit.substr(0, 200));
  const std::string command = args.atlas.empty() ? args.points + (args.timing_step.empty() ? "" : " --timing-step " + args.timing_step)
                                                 : args.points + " --atlas " + args.atlas;
  const std::string comment = fmt::format(
      "Linkage {} of koppel synth path {}: its coupler point P passes the points with an RMS distance of {:.6g}\n"
      "(sum of squared distances {:.6g}; the crank at {:.6g} deg from the frame line A0 -> B0 at the first point;\n"
      "{}). Grashof type {}.{}",
      i + 1, command, l.error, l.sse, RadToDeg(l.phi_1), origin, l.grashof,
      l.cognate_of >= 0 ? fmt::format("\nA Roberts cognate of linkage {}: the same coupler curve from another four-bar.", l.cognate_of + 1) : "");
  WriteOutput((std::filesystem::path(args.dir) / (name + ".yaml")).string(), PathDesignYaml(l, name, comment, args.units));
}

// The timing (a phi column, --timing-step) and the global search's flags, each refused where the
// search it would steer does not run.
void ReadTiming(const Args& args, const TimedPathPoints& read, PathSpec* request) {
  request->timing = read.phi;
  if (!args.timing_step.empty()) request->timing_step = DegToRad(ParseNumberFlag("--timing-step", args.timing_step));
  if (!args.starts.empty()) request->starts = ParseCountFlag("--starts", args.starts, 1, kMaxTimedStarts);
  if (!args.seed.empty()) request->seed = static_cast<std::uint64_t>(ParseCountFlag("--seed", args.seed, 0, 2'000'000'000));
  const bool timed = !request->timing.empty() || request->timing_step;
  if (timed && !args.atlas.empty()) {
    Complain("--atlas: not read when the timing is prescribed (" +
             std::string(request->timing.empty() ? "--timing-step" : "the phi column of " + args.points) +
             "): the timed search is global; leave --atlas out");
    throw Exit{kExitBadInput};
  }
  const bool global = args.atlas.empty();
  if (global && !args.candidates.empty()) {
    Complain("--candidates: atlas curves are searched with --atlas only; --starts sets the global search's work");
    throw Exit{kExitBadInput};
  }
  if (!global && (!args.starts.empty() || !args.seed.empty())) {
    Complain(std::string(args.starts.empty() ? "--seed" : "--starts") + ": only the global search (without --atlas) draws random starts");
    throw Exit{kExitBadInput};
  }
}

void Run(const Args& args) {
  CheckFormat(args.format);
  if (!args.units.empty()) Checked([&] { CheckLengthUnit(args.units, "units"); return 0; });  // before the search: exit 2
  PathSpec request;
  const TimedPathPoints read = ReadPoints(args.points);
  request.points = read.points;
  ReadTiming(args, read, &request);
  const bool timed = !request.timing.empty() || request.timing_step, global = args.atlas.empty();
  request.open = args.open;
  request.top = ParseCountFlag("--top", args.top, 1, 1000);
  if (!args.candidates.empty()) request.candidates = ParseCountFlag("--candidates", args.candidates, 1, 10000);
  if (!args.threads.empty()) request.threads = ParseCountFlag("--threads", args.threads, 0, kMaxThreads);
  if (!args.design.empty()) request.space = Checked([&] { return ReadDesignFile(args.design); });  // file:line, exit 2
  if (const std::string why = PathSpecProblem(request); !why.empty()) {
    Complain(args.points + ": " + why);
    throw Exit{kExitBadInput};
  }
  const PathDesigns result = SynthesisePathFromAtlas(request, args.atlas);
  if (!result.ok) {
    Complain(args.points + ": " + result.message);
    throw Exit{result.invalid_request ? kExitBadInput : kExitFailed};
  }
  MixedTable t;
  t.columns = {"rank", "error", "A0_x", "A0_y", "B0_x", "B0_y", "crank", "coupler", "rocker", "frame", "K_along", "K_left", "grashof", "cognate_of",
               "sse", "phi_1", "mu_min"};
  if (!args.dir.empty()) MakeOutputDirectory(args.dir);
  for (size_t i = 0; i < result.designs.size(); ++i) {
    const PathDesign& l = result.designs[i];
    // a Roberts cognate of a better row: that row's rank; else empty (null in JSON)
    const MixedTable::Cell cognate_of = l.cognate_of >= 0 ? MixedTable::Cell(static_cast<double>(l.cognate_of + 1)) : MixedTable::Cell();
    t.rows.push_back({static_cast<double>(i + 1), l.error, l.a0.x(), l.a0.y(), l.b0.x(), l.b0.y(), l.crank, l.coupler, l.rocker, l.frame,
                      l.coupler_point.x(), l.coupler_point.y(), l.grashof, cognate_of, l.sse, RadToDeg(l.phi_1),
                      l.mu_min ? MixedTable::Cell(RadToDeg(*l.mu_min)) : MixedTable::Cell()});
    if (!args.dir.empty()) WriteDesign(args, l, i);
  }
  WriteOutput(args.out, t.Text(args.format));
  if (global)
    std::cerr << fmt::format("koppel synth path: {} points, timing {}; {} random starts, {} inside the design space; best sse {:.6g} "
                             "(RMS distance {:.3g}); {} designs dropped by the re-analysis, {} outside the design space, {} repeats of a better design\n",
                             request.points.size(), timed ? "prescribed" : "free", result.starts, result.admitted_starts, result.designs.front().sse, result.designs.front().error,
                             result.failed_reanalysis, result.outside_space, result.duplicates);
  else
    std::cerr << fmt::format("koppel synth path: {} points, {} atlas curves; best RMS distance {:.3g}; {} repeats of a better design dropped\n",
                             request.points.size(), result.atlas_curves, result.designs.front().error, result.duplicates);
}

}  // namespace
}  // namespace synth_path_command

void AddPathSubcommand(CLI::App& synth) {
  using namespace synth_path_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = synth.add_subcommand(
      "path",
      "Path generation from an atlas (koppel atlas build): four-bars whose coupler point passes the points of POINTS.csv\n"
      "(header x,y; in order along the path, closed unless --open). The nearest atlas curves by their normalised Fourier\n"
      "descriptors (position, rotation, scale, start and sense free; mirror images too) are laid onto the points,\n"
      "pre-polished in closed form, and the best --top are polished by the least-squares fit through the real mechanism\n"
      "with each point's crank angle free. One CSV row per linkage, best first: rank, error (the RMS distance of the\n"
      "points from the polished coupler curve, in the points' unit), the pivots, crank A0A, coupler AB, rocker B0B,\n"
      "frame A0B0, the coupler point K in the coupler's frame (along A -> B, and left of it), the Grashof type, and\n"
      "cognate_of: the rank of the better row whose Roberts cognate this is (the same curve from another four-bar),\n"
      "sse (the sum of the squared distances), phi_1 (the crank's angle in deg from the frame line A0 -> B0 at the first point)\n"
      "and mu_min (the smallest transmission angle in deg over a full turn for a crank, else over the points' stretch).\n"
      "Each row is a distinct design: one found again from another atlas curve (the same joints where K passes the\n"
      "first point, to 1e-4 of the points' size, either pivot as the crank's) is dropped and the next candidate polished.\n"
      "--open matches an open stretch against the arcs of rocker-driven four-bars. -o DIR writes each as a mechanism file.\n"
      "--design FILE.yaml states the design space (every key optional): lengths: [min, max] (every link, the frame too),\n"
      "ratio: max (longest / shortest link), pivots: {x: [a, b], y: [c, d]} (both frame pivots), input: crank (the input\n"
      "turns fully), coupler_point: [min, max] (K's coordinates), mu_min: deg (the least transmission angle), and in the\n"
      "global search A0: [x, y], frame_angle: deg (fixed).\n"
      "No linkage outside it is returned; when none is left, exit 1 names the constraint the best one broke.\n"
      "Without --atlas the search is global: --starts random four-bars inside the design space, polished in closed form\n"
      "with each point's crank angle free (or prescribed), the best re-analysed by driving the mechanism through the points\n"
      "in order (a branch or order defect drops the design). A closed path's last point may repeat its first.\n"
      "Prescribed timing (global search only): a third column phi in POINTS.csv (header x,y,phi: each point's crank angle\n"
      "in deg from the frame line A0 -> B0, rising or falling) or --timing-step DEG (equal steps, the first angle free).\n"
      "Examples: koppel atlas build --count 100000 -o atlas.bin\n"
      "          koppel synth path tests/data/path-points.csv --atlas atlas.bin --top 5 -o linkages\n"
      "          koppel synth path tests/data/benchmarks/cabrera-18-points.csv --timing-step 20 --design tests/data/benchmarks/cabrera-18-points.yaml --top 3");
  cmd->add_option("points", args->points, "POINTS.csv (header x,y)")->required();
  cmd->add_option("--atlas", args->atlas, "The atlas file (the timing free); without it the search is global");
  cmd->add_option("--top", args->top, "Linkages to return (default 10)");
  cmd->add_option("--candidates", args->candidates, "Atlas curves pre-polished (default max(100, 10 top))");
  cmd->add_flag("--open", args->open, "The points are an open stretch, not a closed path");
  OutputDirectory(cmd->add_option("-o,--dir", args->dir, "Write each linkage as a mechanism file into this directory"));
  OutputFile(cmd->add_option("--output-file", args->out, "Write the table to this file instead of stdout"));
  cmd->add_option("--format", args->format, "The table as csv (default) or json ({\"columns\", \"rows\"}; grashof a string, cognate_of null when none)");
  cmd->add_option("--threads", args->threads, "Threads (default: one per core; at most 256, kMaxThreads)");
  cmd->add_option("--units", args->units, "The length unit of the mechanism files -o writes: each says `units: {length: UNIT}`\n"
                                           "(m, dm, cm, mm, um, km, in, ft; default: none). The points are in that unit.");
  cmd->add_option("--design", args->design, "The design space: a YAML file (lengths, ratio, pivots, input, coupler_point, mu_min, A0, frame_angle)");
  cmd->add_option("--timing-step", args->timing_step, "Prescribed timing: the crank turns by DEG from point to point (the first angle free)");
  cmd->add_option("--starts", args->starts, "The global search's random starts (default 4000)");
  cmd->add_option("--seed", args->seed, "The global search's seed (default 1): the same seed, the same designs");
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
