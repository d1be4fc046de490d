// koppel synth motion: Burmester motion generation (burmester.hpp, motion_synthesis.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/catalog/synthesis_spec.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/synthesis/motion_dyads.hpp"
#include "koppel/synthesis/motion_synthesis.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <iostream>

namespace koppel::cli {
namespace synth_motion_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string poses, dir, out, curves, require, crank_turn = "90", grid, samples = "18", top, threads, format = "csv";
  std::vector<std::string> circle_points;
};

Eigen::Vector2d ParsePoint(const std::string& flag, const std::string& text) {
  const std::vector<double> xy = ParseNumberListFlag(flag, text, 2, "X,Y");
  return {xy[0], xy[1]};
}

int Whole(const std::string& flag, const std::string& text, int lo, int hi) {
  const double v = ParseNumberFlag(flag, text);
  if (v != std::floor(v) || v < lo || v > hi) {
    Complain(fmt::format("{} must be a whole number from {} to {}", flag, lo, hi));
    throw Exit{kExitBadInput};
  }
  return static_cast<int>(v);
}

// Circle points on an n x n grid over the poses' box, enlarged by their size each way.
std::vector<Eigen::Vector2d> Grid(const std::vector<Pose>& poses, int n) {
  Eigen::Vector2d lo = poses[0].point, hi = poses[0].point;
  for (const Pose& p : poses) {
    lo = lo.cwiseMin(p.point);
    hi = hi.cwiseMax(p.point);
  }
  const double margin = PoseScale(poses);
  lo.array() -= margin;
  hi.array() += margin;
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) points.push_back(lo + Eigen::Vector2d((hi.x() - lo.x()) * (i + 0.5) / n, (hi.y() - lo.y()) * (j + 0.5) / n));
  return points;
}

// The dyads the request asks for, by the number of poses (motion_dyads.hpp).
std::vector<Dyad> Dyads(const Args& args, const std::vector<Pose>& poses) {
  const int n = static_cast<int>(poses.size());
  DyadRequest request;
  for (const std::string& c : args.circle_points) request.circle_points.push_back(ParsePoint("--circle-point", c));
  if (!args.grid.empty()) {
    if (n != 3) {
      Complain("--grid is for three poses (a family of dyads from a grid of circle points)");
      throw Exit{kExitBadInput};
    }
    for (const Eigen::Vector2d& p : Grid(poses, Whole("--grid", args.grid, 1, 100))) request.circle_points.push_back(p);
    request.skip_unsolvable = true;
  }
  if (n == 5 && !request.circle_points.empty()) {
    Complain("five poses fix the dyads (the Ball-Burmester points): no --circle-point");
    throw Exit{kExitBadInput};
  }
  if ((n == 2 || n == 3) && request.circle_points.empty()) {
    Complain(n == 2 ? "two poses: give the circle points (--circle-point X,Y, twice for a four-bar)"
                    : "three poses: give --circle-point X,Y (twice for a four-bar) or --grid N");
    throw Exit{kExitBadInput};
  }
  if (n == 4) request.curve_samples = Whole("--samples", args.samples, 1, 1000);
  if (n == 2) request.crank_turn = DegToRad(ParseNumberFlag("--crank-turn", args.crank_turn));
  const DyadChoice choice = DyadsForPoses(poses, request);
  if (!choice.message.empty()) Complain(args.poses + ": " + choice.message);
  if (choice.status == BurmesterStatus::kInvalidRequest) throw Exit{kExitBadInput};
  // five poses without a real Ball-Burmester point: no dyad, reported below
  if (!choice.ok() && n != 5) throw Exit{kExitFailed};
  return choice.dyads;
}

// The four-poses curves as a CSV: one row per sample.
void WriteCurves(const Args& args, const std::vector<Pose>& poses) {
  if (poses.size() != 4) {
    Complain("--curves is for four poses (the centre-point and circle-point curves)");
    throw Exit{kExitBadInput};
  }
  const BurmesterCurves curves = CentrePointCurve(poses, 360);
  if (!curves.ok()) {
    Complain(args.poses + ": " + curves.message);
    throw Exit{kExitFailed};
  }
  Table t;
  t.columns = {"direction", "centre_x", "centre_y", "circle_x", "circle_y"};
  for (const BurmesterCurveSample& s : curves.samples)
    t.rows.push_back({RadToDeg(s.direction), s.dyad.centre.x(), s.dyad.centre.y(), s.dyad.circle.x(), s.dyad.circle.y()});
  WriteOutput(args.curves, t.ToCsv());
}

std::string Comment(const MotionFourBar& f, int rank, const std::string& poses) {
  const bool full = f.crank_turns_fully;
  return fmt::format("Four-bar {} of koppel synth motion {} (Burmester). The coupler is the moving plane: its point P and\n"
                     "its angle theta pass through every pose (re-analysis error {:.3g}). Grashof type {}; branch defect {}; order\n"
                     "defect {}; the input phi (crank angle against +x) {}; mu_min over the poses' travel {:.6g} deg.\n"
                     "Crank angles of the poses: {} deg.",
                     rank, poses, f.pose_error, ToString(f.grashof), f.branch_defect ? "yes" : "no", f.order_defect ? "yes" : "no",
                     full ? "turns fully" : fmt::format("reaches {:.6g} .. {:.6g} deg on this branch", RadToDeg(f.drive_from), RadToDeg(f.drive_to)),
                     RadToDeg(f.mu_min), [&] {
                       std::string s;
                       for (double v : f.pose_inputs) s += fmt::format("{}{:.6g}", s.empty() ? "" : ", ", RadToDeg(v));
                       return s;
                     }());
}

void Run(const Args& args) {
  CheckFormat(args.format);
  MotionSpecFile spec = Checked([&] { return ReadMotionSpec(args.poses); });  // bad input: its diagnostics, exit 2
  MotionOptions options;
  if (!args.require.empty()) {
    if (args.require != "crank") {
      Complain("--require: only 'crank' (the input turns fully)");
      throw Exit{kExitBadInput};
    }
    options.require_crank = true;
  }
  if (!args.threads.empty()) options.threads = Whole("--threads", args.threads, 0, kMaxThreads);
  const int top = args.top.empty() ? 0 : Whole("--top", args.top, 1, 1'000'000);
  if (!args.curves.empty()) WriteCurves(args, spec.poses);
  const std::vector<Dyad> dyads = Dyads(args, spec.poses);
  // the work, estimated before it starts: every ordered pair of dyads is re-analysed
  if (const double four_bars = static_cast<double>(MotionFourBarCount(dyads.size(), options)); four_bars > kMotionFourBars.value) {
    Complain(fmt::format("{}: {} dyads make {:.3g} four-bars to re-analyse, more than the limit of {:.0f} ({}, about 2.5 ms each; see "
                         "README 'Limits'): fewer dyads",
                         spec.poses.size() == 3 ? "--grid/--circle-point" : "--samples", dyads.size(), four_bars, kMotionFourBars.value,
                         kMotionFourBars.name));
    throw Exit{kExitBadInput};
  }

  const MotionResult result = FourBarsFromDyads(spec.poses, dyads, options);
  std::cerr << fmt::format("koppel synth motion: {} poses, {} dyads, {} four-bars re-analysed through every pose{}\n", spec.poses.size(),
                           dyads.size(), result.four_bars.size(),
                           options.require_crank ? fmt::format(", {} without a crank left out", result.rejected) : "");
  MixedTable table;
  table.columns = {"A0_x", "A0_y", "A_x", "A_y", "B_x", "B_y", "B0_x", "B0_y", "grashof", "branch_defect", "order_defect", "mu_min"};
  const size_t shown = top > 0 ? std::min<size_t>(top, result.four_bars.size()) : result.four_bars.size();
  if (!args.dir.empty()) MakeOutputDirectory(args.dir);
  for (size_t i = 0; i < shown; ++i) {
    const MotionFourBar& f = result.four_bars[i];
    table.rows.push_back({f.crank.centre.x(), f.crank.centre.y(), f.crank.circle.x(), f.crank.circle.y(), f.rocker.circle.x(),
                          f.rocker.circle.y(), f.rocker.centre.x(), f.rocker.centre.y(), std::string(ToString(f.grashof)),
                          f.branch_defect ? 1.0 : 0.0, f.order_defect ? 1.0 : 0.0, RadToDeg(f.mu_min)});
    if (!args.dir.empty()) {
      const SweepDefaults sweep = f.crank_turns_fully ? SweepDefaults{RadToDeg(f.drive_from), RadToDeg(f.drive_from) + 360, 1}
                                                      : SweepDefaults{RadToDeg(f.drive_from), RadToDeg(f.drive_to), (RadToDeg(f.drive_to) - RadToDeg(f.drive_from)) / 360};
      Mechanism m = f.mechanism;
      m.name = fmt::format("four-bar-{}", i + 1);
      WriteOutput((std::filesystem::path(args.dir) / (m.name + ".yaml")).string(), WriteMechanismYaml(m, Comment(f, static_cast<int>(i + 1), args.poses), sweep));
    }
  }
  WriteOutput(args.out, table.Text(args.format));
  for (const std::string& failure : result.failures) Complain("a four-bar failed its re-analysis: " + failure);
  if (result.failed > 0) throw Exit{kExitFailed};
  if (result.four_bars.empty()) {
    Complain(dyads.empty() ? "no dyad meets the poses" : "no four-bar meets the request");
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
      "to 1e-9 of the four-bar's size. One CSV row per four-bar, by mu_min (largest first): pivots and circle points in the\n"
      "first pose, the Grashof type, branch defect (poses on different assembly branches, or not reachable driving the\n"
      "crank), order defect (driven one way, the crank meets the poses out of order), mu_min [deg] over the travel from the\n"
      "first pose to the last. --require crank keeps the four-bars whose input turns fully; -o DIR writes each as a\n"
      "mechanism file (four-bar-1.yaml, ...; the comment gives the drivable range). Exit 1 when no four-bar results.\n"
      "Example: koppel synth motion tests/data/motion-three-poses.yaml --circle-point 1,0.2 --circle-point 3.1,2.4 -o designs");
  cmd->add_option("poses", args->poses, "POSES.yaml")->required();
  cmd->add_option("--circle-point", args->circle_points, "A circle point X,Y (first pose, global); repeat for more");
  cmd->add_option("--grid", args->grid, "Three poses: dyads from an N x N grid of circle points");
  cmd->add_option("--samples", args->samples, "Four poses: lines through the pole the dyads are picked on (default 18)");
  OutputFile(cmd->add_option("--curves", args->curves, "Four poses: write the Burmester curves to this CSV file"));
  cmd->add_option("--crank-turn", args->crank_turn, "Two poses: the crank's turn between them [deg] (default 90)");
  cmd->add_option("--require", args->require, "crank: keep only four-bars whose input turns fully");
  cmd->add_option("--top", args->top, "Print (and write) only the best N");
  OutputDirectory(cmd->add_option("-o,--dir", args->dir, "Write each four-bar as a mechanism file into this directory"));
  OutputFile(cmd->add_option("--output-file", args->out, "Write the table to this file instead of stdout"));
  cmd->add_option("--format", args->format, "The table as csv (default) or json ({\"columns\", \"rows\"}; grashof a string)");
  cmd->add_option("--threads", args->threads, "Threads for the re-analyses (default: one per core; at most 256, kMaxThreads)");
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
