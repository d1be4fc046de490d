// Path generation from an atlas (koppel synth path): the four-bars whose coupler point passes a
// set of points, best first, each a distinct design (koppel/synthesis/path_synthesis.hpp gives the
// method: descriptor look-up, closed-form pre-polish, the least-squares fit through the real
// mechanism, repeats dropped, Roberts cognates named). Lengths in the points' unit.
#pragma once

#include "koppel/catalog/path_points.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/synthesis/design_space.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace koppel {

// POINTS.csv: the header `x,y` (or `x,y,phi`: each point's crank angle in degrees from the frame
// line A0 -> B0, rising or falling), then one point a line in order along the path. InputError
// with every bad line (file:line:column). phi in radians.
TimedPathPoints ReadPathPointsFile(const std::string& path);

struct PathSpec {
  std::vector<Eigen::Vector2d> points;  // in order along the path
  bool open = false;                    // an open stretch (matched against rocker arcs)
  int top = 10;                         // linkages returned
  int candidates = 0;                   // atlas curves pre-polished (0: max(100, 10 top))
  int threads = 0;                      // 0: one per core
  DesignSpace space;                    // no linkage outside it is returned (design_space.hpp)
  // Prescribed timing (no atlas then): each point's crank angle from the frame line (radians), or
  // equal increments from a free first angle. Neither: the timing free, the atlas searched.
  std::vector<double> timing;
  std::optional<double> timing_step;
  int starts = 0;          // the global search's random starts (0: 4000)
  std::uint64_t seed = 1;  // the global search's: the same seed, the same designs
};
// Empty when the spec can be run; else why not (too few points, ...).
std::string PathSpecProblem(const PathSpec& spec);

struct PathDesign {
  double error = 0;  // RMS distance of the points from the polished coupler curve
  double sse = 0;    // the sum of the squared distances (the literature's objective)
  double phi_1 = 0;  // the crank's angle from the frame line where K passes (nearest) the first point
  std::vector<double> inputs;  // the global search's: each point's crank angle from the frame line, in order (radians)
  // the smallest transmission angle over the worked stretch (a full turn for a crank, else the
  // points' stretch) [rad]; nullopt where the solver cannot drive through it
  std::optional<double> mu_min;
  Eigen::Vector2d a0 = Eigen::Vector2d::Zero(), b0 = Eigen::Vector2d::Zero();  // the pivots
  double crank = 0, coupler = 0, rocker = 0, frame = 0;                         // A0A, AB, B0B, A0B0
  Eigen::Vector2d coupler_point = Eigen::Vector2d::Zero();  // K along A -> B, and left of it
  std::string grashof;            // the Grashof type, as ToString(GrashofType) names it
  int cognate_of = -1;            // index of the better design it is a Roberts cognate of; -1: none
  std::uint64_t atlas_seed = 0, atlas_index = 0;  // the atlas curve it came from
  std::string fit;                // the polishing fit's brief
  Mechanism mechanism;            // output "P" is the coupler point
};

struct PathDesigns {
  bool ok = false;
  bool invalid_request = false;  // not ok because of the request (bad input), not the search
  std::string message;
  std::vector<PathDesign> designs;  // distinct, by error, smallest first
  int duplicates = 0;               // polished repeats of a better design, dropped
  std::uint64_t atlas_curves = 0;   // curves in the atlas searched (0: the global search)
  // the global search: random starts, those that found a four-bar inside the design space, and
  // polished designs the re-analysis dropped (a branch defect)
  int starts = 0, admitted_starts = 0, failed_reanalysis = 0;
  int outside_space = 0;  // polished designs dropped outside the space (the transmission angle over the stretch)
};

// Reads the atlas file (io::FileError when it cannot) and searches it; with atlas_path empty, the
// global search (path_synthesis.hpp's SynthesisePathGlobally). A timed spec is searched globally
// only: an atlas it would not read is a bad request.
PathDesigns SynthesisePathFromAtlas(const PathSpec& spec, const std::string& atlas_path);

// The design as a mechanism file named `name` with `comment` at its top, its sweep one turn of
// the crank from the assembly's angle by 1 deg; where the input does not turn fully (a global
// search's design outside `input: crank`), from the first point's crank angle to the last's.
// `units`: the file's length unit, as CrankRockerSpec::units ("": none).
std::string PathDesignYaml(const PathDesign& design, const std::string& name, const std::string& comment, const std::string& units = "");

}  // namespace koppel
