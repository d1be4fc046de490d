// koppel synth motion: Burmester motion generation (burmester.hpp, motion_synthesis.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include "koppel/api/motion_synthesis.hpp"
#include "koppel/api/design_file.hpp"

#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <iostream>

namespace koppel::cli {
namespace synth_motion_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string poses, dir, out, curves, require, crank_turn = "90", grid, samples = "18", top, threads, format = "csv", units, design;
  std::vector<std::string> circle_points;
};

[[noreturn]] void BadFlags(const std::string& message) {
  Complain(message);
  throw Exit{kExitBadInput};
}

// The request from the flags; which flags belong to how many poses (motion_dyads.hpp).
MotionSpec Spec(const Args& args, std::vector<MotionPose> poses) {
  const size_t n = poses.size();
  MotionSpec spec;
  spec.poses = std::move(poses);
  for (const std::string& c : args.circle_points) {
    const std::vector<double> xy = ParseNumberListFlag("--circle-point", c, 2, "X,Y");
    spec.circle_points.emplace_back(xy[0], xy[1]);
  }
  if (!args.grid.empty()) {
    if (n != 3) BadFlags("--grid is for three poses (a family of dyads from a grid of circle points)");
    spec.grid = ParseCountFlag("--grid", args.grid, 1, 100);
  }
  if (n == 5 && !spec.circle_points.empty()) BadFlags("five poses fix the dyads (the Ball-Burmester points): no --circle-point");
  if ((n == 2 || n == 3) && spec.circle_points.empty() && spec.grid == 0)
    BadFlags(n == 2 ? "two poses: give the circle points (--circle-point X,Y, twice for a four-bar)"
                    : "three poses: give --circle-point X,Y (twice for a four-bar) or --grid N");
  if (n == 4) spec.curve_samples = ParseCountFlag("--samples", args.samples, 1, 1000);
  if (n == 2) spec.crank_turn = ParseNumberFlag("--crank-turn", args.crank_turn);
  if (!args.require.empty() && args.require != "crank") BadFlags("--require: only 'crank' (the input turns fully)");
  spec.require_crank = args.require == "crank";
  if (!args.design.empty()) spec.space = Checked([&] { return ReadDesignFile(args.design); });  // file:line, exit 2
  if (!args.threads.empty()) spec.threads = ParseCountFlag("--threads", args.threads, 0, kMaxThreads);
  spec.units = args.units;
  return spec;
}

// The four-poses curves as a CSV: one row per sample.
void WriteCurves(const Args& args, const std::vector<MotionPose>& poses) {
  if (poses.size() != 4) BadFlags("--curves is for four poses (the centre-point and circle-point curves)");
  const BurmesterCurveTable curves = Checked([&] { return MotionCurves(poses); });
  if (curves.status != DesignStatus::kOk) {
    Complain(args.poses + ": " + curves.message);
    throw Exit{kExitFailed};
  }
  WriteOutput(args.curves, Table{curves.table.columns, curves.table.rows}.ToCsv());
}

// One row per four-bar (the best `shown`), each also a mechanism file with -o DIR.
void WriteDesigns(const Args& args, const MotionReport& report, size_t shown) {
  MixedTable table;
  table.columns = {"A0_x", "A0_y", "A_x", "A_y", "B_x", "B_y", "B0_x", "B0_y", "grashof", "branch_defect", "order_defect", "mu_min"};
  if (!args.dir.empty()) MakeOutputDirectory(args.dir);
  for (size_t i = 0; i < shown; ++i) {
    const Design& d = report.designs[i];
    std::vector<MixedTable::Cell> row;
    for (const char* name : {"A0_x", "A0_y", "A_x", "A_y", "B_x", "B_y", "B0_x", "B0_y"}) row.emplace_back(d.Get(name));
    row.emplace_back(d.message);  // the Grashof type
    for (const char* name : {"branch_defect", "order_defect", "mu_min"}) row.emplace_back(d.Get(name));
    table.rows.push_back(std::move(row));
    if (!args.dir.empty()) WriteOutput((std::filesystem::path(args.dir) / (d.model->name() + ".yaml")).string(), d.yaml);
  }
  WriteOutput(args.out, table.Text(args.format));
}

void Run(const Args& args) {
  CheckFormat(args.format);
  std::vector<MotionPose> poses = Checked([&] { return ReadMotionPoses(args.poses); });  // bad input: its diagnostics, exit 2
  const size_t n = poses.size();
  const MotionSpec spec = Spec(args, std::move(poses));
  const int top = args.top.empty() ? 0 : ParseCountFlag("--top", args.top, 1, 1'000'000);
  if (!args.curves.empty()) WriteCurves(args, spec.poses);
  const MotionReport report = Checked([&] { return SynthesiseMotionReport(spec, args.poses); });
  if (report.status == DesignStatus::kInvalidRequest)  // the work, estimated before it starts
    BadFlags(fmt::format("{}: {} dyads make {:.3g} four-bars to re-analyse, more than the limit of {:.0f} ({}, about 2.5 ms each; see "
                         "docs/limits.md): fewer dyads",
                         n == 3 ? "--grid/--circle-point" : "--samples", report.dyads, report.four_bars, kMotionFourBars.value, kMotionFourBars.name));
  if (!report.paired) {  // no dyad: the notes say why
    for (const std::string& note : report.notes) Complain(args.poses + ": " + note);
    throw Exit{kExitFailed};
  }
  // the counts: what was made, what can be built, what has a defect, what failed
  std::cerr << fmt::format("koppel synth motion: {} poses, {} dyads, {:.0f} candidate four-bars: {} without a defect, {} with a branch or "
                           "order defect, {} failed their re-analysis{}\n",
                           n, report.dyads, report.four_bars, report.defect_free, report.designs.size() - report.defect_free, report.failed,
                           spec.require_crank ? fmt::format(", {} without a crank left out", report.rejected) : "") +
                   (args.design.empty() ? "" : fmt::format("koppel synth motion: {} four-bars outside the design space left out\n", report.outside_space));
  WriteDesigns(args, report, top > 0 ? std::min<size_t>(top, report.designs.size()) : report.designs.size());
  for (const std::string& note : report.notes) Complain(args.poses + ": " + note);
  if (report.status != DesignStatus::kOk) {
    Complain(args.poses + ": " + report.message);
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace synth_motion_command

void AddMotionSubcommand(CLI::App& synth) {
  using namespace synth_motion_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = synth.add_subcommand(
      "motion",
      "Motion generation (Burmester): four-bars whose coupler carries a plane through 2 to 5 poses, given in POSES.yaml as\n"
      "`poses: [[x, y, angle_deg], ...]` (a reference point of the plane and its angle, global). A dyad is a circle point\n"
      "A of the plane (global, in the first pose) and its centre point A0; two dyads make a four-bar driven at A0.\n"
      "  2 poses: --circle-point (twice); the centre point on the bisector where the crank turns by --crank-turn (90 deg).\n"
      "  3 poses: --circle-point: its centre point (the circumcentre of its three positions); --grid N: a family of dyads\n"
      "    from an N x N grid of circle points over the poses.\n"
      "  4 poses: --curves FILE writes the centre-point and circle-point curves (CSV); the dyads are --circle-point (it\n"
      "    must lie on the circle-point curve) or --samples N lines through a pole (up to two dyads each).\n"
      "  5 poses: the Ball-Burmester points (at most four real ones, from the resultant of two circular cubics).\n"
      "Every pair of dyads (either one driven) is re-analysed by the solver: the coupler's point and angle must meet every pose\n"
      "to 1e-9 of the four-bar's size. One CSV row per four-bar, those without a defect first, each part by mu_min (largest\n"
      "first): pivots and circle points in the\n"
      "first pose, the Grashof type, branch defect (poses on different assembly branches, or not reachable driving the\n"
      "crank), order defect (driven one way, the crank meets the poses out of order), mu_min [deg] over the travel from the\n"
      "first pose to the last. --require crank keeps the four-bars whose input turns fully; -o DIR writes each as a\n"
      "mechanism file (four-bar-1.yaml, ...; the comment gives the drivable range). stderr counts the candidates, those with\n"
      "a defect and those that failed their re-analysis (not listed). Exit 1 when no four-bar without a defect results.\n"
      "--design FILE.yaml leaves out the four-bars outside a design space (see synth path: lengths, ratio, pivots, input,\n"
      "coupler_point: the plane's reference point in the coupler's frame, mu_min: over the travel).\n"
      "Example: koppel synth motion tests/data/motion-three-poses.yaml --circle-point 1,0.2 --circle-point 3.1,2.4 -o designs");
  cmd->add_option("poses", args->poses, "POSES.yaml")->required();
  cmd->add_option("--circle-point", args->circle_points, "A circle point X,Y (first pose, global); repeat for more");
  cmd->add_option("--grid", args->grid, "Three poses: dyads from an N x N grid of circle points");
  cmd->add_option("--samples", args->samples, "Four poses: lines through the pole the dyads are picked on (default 18)");
  OutputFile(cmd->add_option("--curves", args->curves, "Four poses: write the Burmester curves to this CSV file"));
  cmd->add_option("--crank-turn", args->crank_turn, "Two poses: the crank's turn between them [deg] (default 90)");
  cmd->add_option("--require", args->require, "crank: keep only four-bars whose input turns fully");
  cmd->add_option("--design", args->design, "The design space: a YAML file (lengths, ratio, pivots, input, coupler_point, mu_min)");
  cmd->add_option("--units", args->units, "The length unit of the poses and of the mechanism files -o writes: each says\n"
                                           "`units: {length: UNIT}`, the table labels lengths with it (m, dm, cm, mm, um, km, in, ft; default: none)");
  cmd->add_option("--top", args->top, "Print (and write) only the best N");
  OutputDirectory(cmd->add_option("-o,--dir", args->dir, "Write each four-bar as a mechanism file into this directory"));
  OutputFile(cmd->add_option("--output-file", args->out, "Write the table to this file instead of stdout"));
  cmd->add_option("--format", args->format, "The table as csv (default) or json ({\"columns\", \"rows\"}; grashof a string)");
  cmd->add_option("--threads", args->threads, "Threads for the re-analyses (default: one per core; at most 256, kMaxThreads)");
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
