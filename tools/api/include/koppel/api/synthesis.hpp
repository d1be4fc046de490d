// The syntheses of `koppel synth` as functions: each returns a Design whose mechanism is a Model,
// ready to analyse. Angles in degrees, lengths in any one unit (as at the CLI).
//
// Failure behaviour: a malformed request (an angle out of its range, a negative length, a
// function that is not finite at a precision point) throws koppel::InputError; an outcome is a
// value: DesignStatus kOk (proved by the solver's re-analysis, see the synthesis headers),
// kNoDesign (no mechanism of the kind satisfies the request: the message says why),
// kBoundaryOptimum (no best design: it degenerates) or kReanalysisFailed (the solver did not
// confirm the closed form: nothing is reported). Only an ok design carries a model; only an ok
// design carries figures, except a function generator that was designed but fails its check
// (SynthesiseFunction: its lengths, so that the reader sees what failed).
#pragma once

#include "koppel/api/model.hpp"
#include "koppel/synthesis/design_space.hpp"
#include "koppel/synthesis/design_status.hpp"

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace koppel {

struct DesignFigure {
  std::string name;  // the CLI's summary names: "l1", "mu_min", "beta", ...
  double value = 0;
  std::string unit;  // "deg", "1", "length" or the unit the request names ("mm")
};

// A table of numbers a design comes with (function generation: its structural error curve).
struct DesignTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

struct Design {
  DesignStatus status = DesignStatus::kNotRun;
  std::string message;
  std::vector<DesignFigure> figures;  // as `koppel synth ...` prints them, in its order
  std::optional<Model> model;         // the designed mechanism
  // The designed mechanism as a mechanism file: a comment that says how it was designed, and its
  // drivable range as the file's sweep (what `koppel synth ... -o` writes); empty without a model.
  std::string yaml;
  DesignTable curve;  // empty unless the synthesis has one
  bool ok() const { return status == DesignStatus::kOk; }
  // The figure called `name`; InputError when the design has none of that name.
  double Get(const std::string& name) const;
  std::string Brief() const;
};

// Dead-centre synthesis of a crank-rocker (seed 002, koppel synth deadcentre crank-rocker):
// phi0 the crank's turn from the folded to the extended dead centre, psi0 the rocker's swing
// meanwhile [deg]; beta [deg] or lambda = l1/l2 choose the design of the family (neither: the one
// with the largest smallest transmission angle); frame = A0B0; the crank runs counter-clockwise
// (clockwise: the mirror image). Model: input phi, outputs psi and mu. `units` names the length
// unit the yaml says and the length figures are labelled with; InputError listing the known
// units for another name.
struct CrankRockerSpec {
  double phi0 = 0, psi0 = 0;
  bool same_sense = true;  // the rocker turns the crank's way from folded to extended
  std::optional<double> beta, lambda;
  double frame = 1;
  bool clockwise = false;
  std::string units;  // the design's length unit (m, dm, cm, mm, um, km, in, ft: length_units.hpp); empty: none
  // without beta and lambda: the best mu_min inside it (BestCrankRockerInSpace); with either, a
  // design outside it is kNoDesign naming the constraint. A0 at the origin, B0 at (frame, 0).
  DesignSpace space;
};
Design SynthesiseCrankRocker(const CrankRockerSpec& spec);

// Dead-centre synthesis of a slider-crank (seed 000's conventions): phi0 [deg] and the stroke;
// the offset |e| or beta [deg] (neither: the largest smallest transmission angle).
// Model: input phi, outputs s and mu.
struct SliderCrankSpec {
  double phi0 = 0, stroke = 0;
  std::optional<double> offset, beta;
  std::string units;  // as CrankRockerSpec::units
};
Design SynthesiseSliderCrank(const SliderCrankSpec& spec);

// Meyer zur Capellen straight-line linkage (seed 003) from lambda, or from the coupler angle
// kappa [deg], and the inflection-circle diameter D. Model: the double rocker, output K; its yaml
// sweeps the double rocker's own input range, a hundredth of a degree inside its limit positions.
// Figures: lambda, D, phi0, kappa, l1..l4, k, contact_points (of K's path with its tangent; 6: a
// six-point tangent) and, where the cognate exists, its crank-rocker's crank_rocker_l1..l4 and
// crank_rocker_AK (MzcCrankRocker).
struct MzcSpec {
  std::optional<double> lambda, kappa;
  double diameter = 1;
  std::string units;  // as CrankRockerSpec::units
};
Design SynthesiseMzc(const MzcSpec& spec);
// The crank-rocker of a Meyer zur Capellen double rocker (SynthesiseMzc's design): its Roberts
// cognate about K whose crank turns with the double rocker's coupler (seed 003). Figures l1 (the
// crank), l2, l3, l4 (the frame), AK [length]. InputError for a design that is not ok.
Design MzcCrankRocker(const Design& double_rocker, const std::string& units = "");  // units: as MzcSpec::units

// Function generation (koppel synth function): a four-bar (rocker angle) or slider-crank
// (slider displacement) whose output follows y = f(x) while the crank follows x, mapped linearly
// onto input_from..input_to [deg] and output_from..output_to [deg | length]; `points` Chebyshev
// precision points, or the x values in `at`. Figures: the link lengths, the largest structural
// error (error_max, [deg | length]) over the range and at the precision points.
struct FunctionSpec {
  std::string type = "four-bar";  // or "slider-crank"
  std::function<double(double)> f;
  double x_from = 0, x_to = 1;
  double input_from = 0, input_to = 90;
  double output_from = 0, output_to = 90;
  int points = 3;
  std::vector<double> at;
  double frame = 1;
  std::string units;  // as CrankRockerSpec::units
  // a four-bar generator (A0 at the origin, B0 at (frame, 0)) outside it is kNoDesign, its
  // figures shown and the message naming the constraint it breaks; mu_min over the input range
  DesignSpace space;
};
// A design that was made but fails (it does not run through the whole input range, or the
// solver's mechanism misses a precision point: another branch) is kNoDesign with its lengths as
// figures, and error_max and the curve only where they describe it (not for a missed point); the
// message says which. curve: the structural error over the range, columns x, crank [deg],
// desired, generated, error [deg | length]. yaml: the mechanism file (ok designs).
Design SynthesiseFunction(const FunctionSpec& spec);
// The same from a function spec file (koppel synth function SPEC.yaml; README "synth function"):
// the file's function formula, ranges and points. InputError naming the file and line for a spec
// that does not read or a request that is malformed.
// `units`: as CrankRockerSpec::units.
Design SynthesiseFunctionFile(const std::string& path, const std::string& units = "", const DesignSpace& space = {});

// Least-squares fitting of any mechanism file to targets (koppel synth fit): `problem` is a fit
// problem file (catalog/include/koppel/catalog/fit_problem.hpp: the mechanism, the free
// parameters with bounds and starts, the targets); `threads` for the starts (0: the file's, or
// one per core). Figures: every free parameter (unit "parameter"), per target
// `target<i>_<name>_residual` [deg | length] and `target<i>_input` for a free input, `cost`,
// `starts_at_best`. kOk only when every target is within its tolerance and the design assembles
// over `require`; otherwise kNoDesign, the message naming what was missed. The model is the
// problem's mechanism file read with the fitted values, so its other parameters stay formulas.
// A problem file that does not read throws InputError naming the file and line.
struct FitSpec {
  std::string problem;
  int threads = 0;
};
Design SynthesiseFit(const FitSpec& spec);

// Motion generation (koppel synth motion, Burmester): four-bars whose coupler carries a plane
// through 2 to 5 poses, each pose the plane's reference point P (x, y [length]) and its angle
// [deg, counter-clockwise]. The dyads by the number of poses: five fix them (Ball–Burmester
// points: give no circle points); four give the centre-point curve sampled along
// `curve_samples` lines unless circle points are given; three and two need circle points (global,
// in the first pose), two also the crank's turn between the poses. Every pair of dyads is tried
// with either one driven, and each four-bar is re-analysed by the solver through every pose.
struct MotionPose {
  double x = 0, y = 0, angle = 0;
};
struct MotionSpec {
  std::vector<MotionPose> poses;
  std::vector<std::pair<double, double>> circle_points;
  double crank_turn = 90;    // [deg], two poses only
  int curve_samples = 18;    // four poses without circle points
  int grid = 0;              // three poses: also the circle points of an n x n grid (MotionGrid), those without a centre point left out
  bool require_crank = false;  // keep only four-bars whose input turns fully
  DesignSpace space;         // four-bars outside it are left out (design_space.hpp; K: the plane's reference point)
  int threads = 0;           // 0: one per core
  std::string units;         // as CrankRockerSpec::units: the four-bars' files and length figures
};
// The four-bars by mu_min, largest first. Each Design: figures A0_x, A0_y, A_x, A_y, B_x, B_y,
// B0_x, B0_y (A0 A driven; A and B in the first pose), mu_min [deg] over the travel from the
// first pose to the last, branch_defect, order_defect, crank_turns_fully (0/1), pose_error
// [length], pose<i>_input (the crank angle at pose i [deg]); message: the Grashof type; model:
// input phi at A0, outputs P, theta, psi, mu. status kOk with at least one four-bar; kNoDesign
// when no dyad or no four-bar meets the request (message: why); kReanalysisFailed when a
// four-bar did not pass its re-analysis (a defect of the synthesis: nothing is reported).
// InputError for a malformed request (pose count, circle points where none belong, ...).
// (Designs: several designs from one request, with the request's status; also FindCognates.)
struct Designs {
  DesignStatus status = DesignStatus::kNotRun;
  std::string message;
  std::vector<std::string> notes;  // what the reader should know about a design (FindCognates)
  std::vector<Design> designs;
  bool ok() const { return status == DesignStatus::kOk; }
};
Designs SynthesiseMotion(const MotionSpec& spec);

// The two Roberts–Chebyshev cognates (Ersatzgetriebe, koppel cognates) of a four-bar of revolute
// joints: four-bars whose coupler point traces the curve of `point` (a point output, "link.point"
// or a point name). designs[0], pivots A0 and C0, has a crank that turns with the original
// coupler (figures A0C0, A0A1, A1C1, C0C1, A1K, C1K [length], input_min, input_max [deg] over a
// turn of the original); designs[1], pivots C0 and B0, is driven with the original's input (C0B0,
// C0C2, C2B2, B0B2, B2K, C2K), and is proved against the original sample by sample over a turn
// (kReanalysisFailed otherwise). kNoDesign when they degenerate (the point on a coupler joint);
// InputError for a point that is not there or a mechanism that is not such a four-bar.
Designs FindCognates(const Model& original, const std::string& point);

}  // namespace koppel
