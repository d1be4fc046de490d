// koppel synth path: path generation from an atlas (path_synthesis.hpp).
#include "commands.hpp"
#include "common.hpp"

#include "koppel/api/path_synthesis.hpp"
#include "koppel/catalog/design_space_file.hpp"
#include "koppel/catalog/length_units.hpp"
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
  std::string points, atlas, top = "10", candidates, dir, out, threads, format = "csv", design, units;
  bool open = false;
};

// POINTS.csv (koppel/api/path_synthesis.hpp); every bad line reported.
std::vector<Eigen::Vector2d> ReadPoints(const std::string& path) {
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
  const std::string comment = fmt::format(
      "Linkage {} of koppel synth path {} --atlas {}: its coupler point P passes the points with an RMS distance of {:.6g}\n"
      "(atlas curve {} of seed {}, polished by the fit through this mechanism: {}). Grashof type {}.{}",
      i + 1, args.points, args.atlas, l.error, l.atlas_index, l.atlas_seed, l.fit.substr(0, 200), l.grashof,
      l.cognate_of >= 0 ? fmt::format("\nA Roberts cognate of linkage {}: the same coupler curve from another four-bar.", l.cognate_of + 1) : "");
  WriteOutput((std::filesystem::path(args.dir) / (name + ".yaml")).string(), PathDesignYaml(l, name, comment, args.units));
}

void Run(const Args& args) {
  CheckFormat(args.format);
  if (!args.units.empty()) Checked([&] { return UnitOnlyLoads(args.units, "units"); });  // before the search: exit 2
  PathSpec request;
  request.points = ReadPoints(args.points);
  request.open = args.open;
  request.top = ParseCountFlag("--top", args.top, 1, 1000);
  if (!args.candidates.empty()) request.candidates = ParseCountFlag("--candidates", args.candidates, 1, 10000);
  if (!args.threads.empty()) request.threads = ParseCountFlag("--threads", args.threads, 0, kMaxThreads);
  if (!args.design.empty()) request.space = Checked([&] { return ReadDesignSpace(args.design); });  // file:line, exit 2
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
  t.columns = {"rank", "error", "A0_x", "A0_y", "B0_x", "B0_y", "crank", "coupler", "rocker", "frame", "K_along", "K_left", "grashof", "cognate_of"};
  if (!args.dir.empty()) MakeOutputDirectory(args.dir);
  for (size_t i = 0; i < result.designs.size(); ++i) {
    const PathDesign& l = result.designs[i];
    // a Roberts cognate of a better row: that row's rank; else empty (null in JSON)
    const MixedTable::Cell cognate_of = l.cognate_of >= 0 ? MixedTable::Cell(static_cast<double>(l.cognate_of + 1)) : MixedTable::Cell();
    t.rows.push_back({static_cast<double>(i + 1), l.error, l.a0.x(), l.a0.y(), l.b0.x(), l.b0.y(), l.crank, l.coupler, l.rocker, l.frame,
                      l.coupler_point.x(), l.coupler_point.y(), l.grashof, cognate_of});
    if (!args.dir.empty()) WriteDesign(args, l, i);
  }
  WriteOutput(args.out, t.Text(args.format));
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
      "cognate_of: the rank of the better row whose Roberts cognate this is (the same curve from another four-bar).\n"
      "Each row is a distinct design: one found again from another atlas curve (the same joints where K passes the\n"
      "first point, to 1e-4 of the points' size, either pivot as the crank's) is dropped and the next candidate polished.\n"
      "--open matches an open stretch against the arcs of rocker-driven four-bars. -o DIR writes each as a mechanism file.\n"
      "--design FILE.yaml states the design space (every key optional): lengths: [min, max] (every link, the frame too),\n"
      "ratio: max (longest / shortest link), pivots: {x: [a, b], y: [c, d]} (both frame pivots), input: crank (the input\n"
      "turns fully). No linkage outside it is returned; when none is left, exit 1 names the constraint the best one broke.\n"
      "Examples: koppel atlas build --count 100000 -o atlas.bin\n"
      "          koppel synth path tests/data/path-points.csv --atlas atlas.bin --top 5 -o linkages");
  cmd->add_option("points", args->points, "POINTS.csv (header x,y)")->required();
  cmd->add_option("--atlas", args->atlas, "The atlas file")->required();
  cmd->add_option("--top", args->top, "Linkages to return (default 10)");
  cmd->add_option("--candidates", args->candidates, "Atlas curves pre-polished (default max(100, 10 top))");
  cmd->add_flag("--open", args->open, "The points are an open stretch, not a closed path");
  OutputDirectory(cmd->add_option("-o,--dir", args->dir, "Write each linkage as a mechanism file into this directory"));
  OutputFile(cmd->add_option("--output-file", args->out, "Write the table to this file instead of stdout"));
  cmd->add_option("--format", args->format, "The table as csv (default) or json ({\"columns\", \"rows\"}; grashof a string, cognate_of null when none)");
  cmd->add_option("--threads", args->threads, "Threads (default: one per core; at most 256, kMaxThreads)");
  cmd->add_option("--units", args->units, "The length unit of the mechanism files -o writes: each says `units: {length: UNIT}`\n"
                                           "(m, dm, cm, mm, um, km, in, ft; default: none). The points are in that unit.");
  cmd->add_option("--design", args->design, "The design space: a YAML file (lengths, ratio, pivots, input)");
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
