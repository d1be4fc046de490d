// koppel::Model: one mechanism, loaded from a mechanism file (README "Mechanism files"), with its
// parameters, a current pose, and the analyses the CLI runs on it.
//
// Units (the same as in the mechanism files and at the CLI, so a table here equals the table of
// `koppel analyze`): the drive input in degrees for an R drive, in the file's length unit for a
// P drive; an output's value in degrees for an angle (R joint, link angle, direction,
// transmission angle) and in length units otherwise; its k-th transfer function d^k y / d x^k
// with angles in radians and the input x in radians (R drive) or length (P drive).
// Frame: x right, y up, angles counter-clockwise positive (see koppel/core/mechanism.hpp).
//
// Failure behaviour: bad input (a file that does not read, an unknown parameter or output, a
// range that cannot be sampled) throws koppel::InputError, naming the file, line and field where
// there is one; the model is then unchanged. Outcomes are values: every result carries a status
// (AnalysisStatus: not run, complete, partial, failed), a message and Brief(). A value that
// cannot be computed (a transfer function above the order a singular pose allows) is NaN, and
// the row's valid_order says so; no other NaN is ever returned.
// A Model is immutable: no method changes it (With gives a new one), so it may be shared between
// threads, and copies share its file. A pose and the walk that moves it live beside it, in a
// Workspace (koppel/api/workspace.hpp).
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/api/instant_geometry.hpp"
#include "koppel/api/tolerance.hpp"
#include "koppel/core/diagnostic.hpp"  // InputError, Diagnostic
#include "koppel/core/loads.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/branch_point_action.hpp"  // BranchPointAction: the words, without the solver

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace koppel {

// The highest transfer-function order a sweep or pose computes (the solver's kMaxOrder).
inline constexpr int kMaxTransferOrder = 8;

// Parameter overrides: name -> formula over the file's parameters ("0.8", "l1/2").
using ParameterValues = std::vector<std::pair<std::string, std::string>>;
// Overrides written "NAME=VALUE" (the CLI's --set); InputError for one without a name or value.
ParameterValues ParseParameterValues(const std::vector<std::string>& assignments);

// A singular position met on the way (koppel/solver/singular.hpp explains the kinds).
struct SingularPosition {
  std::string kind;                 // "limit" (dead centre of the drive) or "branch-point"
  double input = 0;                 // [deg for an R drive, length for a P drive]
  double rcond = 0;                 // reciprocal condition of the scaled Jacobian there
  std::vector<std::string> joints;  // the joints that carry it
  std::string action;               // branch points: "continue", "stop" or "switch"
};

// A part of a requested range the drive cannot reach on the branch: [from, to] in sweep order.
struct InputGap {
  double from = 0, to = 0;
};

// What a sweep met on its way, without its rows: every analysis built on a sweep (a coupler
// curve, dead centres, proportionality, forces) passes it on, so that the reader learns of the
// singular points and gaps behind its numbers.
struct SweepRecord {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // partial: some samples are beyond the branch
  std::string message;                              // why samples are missing
  std::vector<std::string> notes;
  std::vector<SingularPosition> singular_points;
  std::vector<InputGap> gaps;
  InputGap reached;                     // the inputs the sweep reached [deg | length]
  std::vector<double> singular_inputs;  // inputs of the samples at a singular pose [deg | length]
  bool complete() const { return status == AnalysisStatus::kComplete; }
};

// A range of the drive's input, from..to by step [deg | length].
struct SweepSpan {
  double from = 0, to = 360, step = 1;
};

// The outputs and transfer functions at the samples of a sweep, laid out as `koppel analyze`:
// the input, then per output y (y_x, y_y for a point) the columns y, y_d1, ..., y_d<order>, then
// `singular` (1 where the pose is a singular position).
struct SweepTable {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // partial: some samples are beyond the branch
  std::string message;                              // why samples are missing
  std::vector<std::string> notes;
  int order = 0;
  std::vector<std::string> columns, units;  // units: "deg", length_unit() ("mm"), "rad/rad^2", "1", ...
  int rows = 0;
  std::vector<double> values;               // rows x columns.size(), row after row
  std::vector<int> valid_order;             // per row: orders above this are NaN there
  std::vector<SingularPosition> singular_points;
  std::vector<InputGap> gaps;
  // What the walk met (for koppel analyze's report and JSON), and its own outcome word:
  // "complete", "partial", "not assemblable", ... (record.status is complete when every sample
  // was reached, while `status` is partial also when an output has no number in some cells).
  SweepRecord record;
  std::string sweep_status;

  int ColumnIndex(const std::string& name) const;  // -1 when there is none
  // The column called `name`; InputError for a name the table does not have.
  std::vector<double> Column(const std::string& name) const;
  double At(int row, int column) const { return values[static_cast<size_t>(row) * columns.size() + column]; }
  std::string Brief() const;
};

// One pose: a single row of the sweep layout at the current input.
struct PoseResult {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // complete: the pose was found
  std::string message;
  double input = 0;  // [deg | length]
  std::vector<std::string> columns;
  std::vector<double> values;  // one row; empty unless complete
  int valid_order = 0;
  bool singular = false;
  // The value of column `name` ("s", "s_d3", "K_x"); InputError for an unknown column.
  double Get(const std::string& name) const;
  std::string Brief() const;
};

struct DeadCentrePoint {
  std::string kind;  // "extended" (Strecklage), "folded" (Decklage) or "unclassified"
  double input = 0;  // [deg | length]
  double value = 0;  // the output there [deg | length]
  double second = 0; // its 2nd-order transfer function there: < 0 a maximum, > 0 a minimum
};

// The least or largest value of an output over the searched range, and where it is.
struct OutputExtremePoint {
  std::string at;    // "stationary" (a stationary point), "fold" (a transmission angle's 90 deg), "range end"
  double input = 0;  // [deg | length]
  double value = 0;  // [deg | length]
};

// The dead centres of a scalar output and, where they pair up, the stroke (koppel deadcentres).
struct DeadCentres {
  AnalysisStatus status = AnalysisStatus::kNotRun;
  std::string message;
  std::vector<DeadCentrePoint> points;  // in input order
  bool has_stroke = false;
  // input_a / input_i: the drive at the extended / folded dead centre; value_a / value_i: the
  // output there; stroke = |value_a - value_i|; forward_angle: the crank's turn from input_a to
  // input_i (R drive, [deg]); phase_ratio = forward_angle / (360 - forward_angle); time_ratio: the
  // slow stroke's duration over the fast one's at a constant crank speed, max(phase_ratio,
  // 1 / phase_ratio) >= 1 (R drive; 0 for a P drive, as phase_ratio).
  double input_a = 0, input_i = 0, value_a = 0, value_i = 0, stroke = 0, forward_angle = 0, phase_ratio = 0, time_ratio = 0;
  // The output's least and largest value over the range, from the same search (a transmission
  // angle's mu_min and mu_max; koppel deadcentres --summary); false when they could not be had
  // (extremes_message says why).
  bool has_extremes = false;
  OutputExtremePoint minimum, maximum;
  std::string extremes_message;
  std::vector<double> unresolved;  // [deg | length]: sign changes of y' not refined (a dead centre may be missing)
  std::vector<SingularPosition> singular_points;
  std::vector<InputGap> gaps;
  // What koppel deadcentres prints besides: the output searched and whether it is a transmission
  // angle (its summary is then its extremes, not a stroke); whether input_a / input_i come from
  // the crank-coupler line-up (else from the maximum and minimum); the search's own message
  // (unresolved sign changes; empty when it has none); the extremes' status; what the sweep met.
  std::string output;
  bool transmission_angle = false;
  bool classified = false;
  std::string search_message;
  AnalysisStatus extremes_status = AnalysisStatus::kNotRun;
  SweepRecord sweep;
  std::string Brief() const;
};

// One assembly branch's drivable interval (koppel range).
struct BranchInterval {
  int branch = 0;     // 0: the branch the file's assembly hint chooses
  double from = 0, to = 0;  // [deg | length]; a full turn: 0 .. period
  std::string from_kind, to_kind;  // "limit", "branch-point", "full-turn", "bound", "failed"
  double period = 0;  // full turn: the input after which the pose repeats (360 k deg); else 0
  std::vector<SingularPosition> singular_points;
  std::string message;
};

struct Ranges {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // failed: not assemblable, or a walk failed
  std::string message;
  bool walked = false;  // false: no branch could be walked (not assemblable); `message` says why
  std::vector<std::string> notes;
  std::vector<BranchInterval> branches;
  std::string Brief() const;
};

// What a sweep does at a branch point (see --at-branch-point): the kernel's own choice, so that
// the words and their meaning are written once (koppel/solver/singular.hpp).
using AtBranchPoint = BranchPointAction;
// The action a word names ("continue", "stop", "switch"; empty: continue). InputError naming the
// field `at_branch_point` for any other word. The CLI's --at-branch-point and the Python
// module's at_branch_point= both read it here.
AtBranchPoint ParseAtBranchPoint(const std::string& word);

class MechanismSource;  // koppel/catalog/mechanism_source.hpp: the parsed file, private to the API
struct MechanismFile;    // koppel/catalog/mechanism_file.hpp: a file evaluated

class Model {
 public:
  // Reads a mechanism file, or the catalog entry when `path` is no file but a catalog id
  // ("crank-rocker", ResolveMechanismName); `set` overrides parameters as --set does. Throws
  // InputError. Load, Parse, FromMechanism and With admit only a mechanism of mobility 1 (one
  // drive), as every command does (tools/api/src/admission.hpp): InputError otherwise.
  static Model Load(const std::string& path, const ParameterValues& set = {});
  // The same from the text of a mechanism file; `name` stands for the file in messages.
  static Model Parse(const std::string& yaml, const std::string& name = "<string>", const ParameterValues& set = {});
  // A mechanism built in code or returned by a synthesis (no parameters; sweep 0..360 by 1).
  // Throws InputError when the mechanism is not consistent (CheckConsistency).
  static Model FromMechanism(const Mechanism& mechanism);

  Model(const Model&) = default;
  Model& operator=(const Model&) = default;
  Model(Model&&) noexcept = default;
  Model& operator=(Model&&) noexcept = default;
  ~Model();

  const std::string& name() const;    // the file's `name`
  const std::string& title() const;
  const std::string& path() const;    // the file read, or the name given to Parse
  const Mechanism& mechanism() const; // the model, radians inside (koppel/core/mechanism.hpp)
  // What admitting the mechanism noted (an overconstrained linkage that moves all the same).
  const std::vector<std::string>& notes() const;
  // The label of the file's length unit, as tables give it: "mm" for `units: {length: mm}`,
  // "length" when the file names none (Loads::LengthUnit).
  std::string length_unit() const;
  // The masses, loads, gravity and length unit the file gives (koppel/core/loads.hpp; none when
  // it gives none).
  const Loads& loads() const;
  std::string input_name() const;     // "phi"
  bool input_is_angle() const;        // R drive (degrees here) or P drive (length)
  std::vector<std::string> output_names() const;
  bool output_is_angle(const std::string& output) const;  // InputError for an unknown output
  // The file's default sweep [deg | length].
  double sweep_from() const;
  double sweep_to() const;
  double sweep_step() const;
  // The range a command sweeps: what is given, the file's sweep for what is not (the one rule
  // of every --from/--to/--step) [deg | length].
  SweepSpan Span(std::optional<double> from = {}, std::optional<double> to = {}, std::optional<double> step = {}) const;

  // Every parameter after evaluation, in file order.
  std::vector<std::pair<std::string, double>> parameters() const;
  // The model with one parameter overridden (a formula over the others) on top of every override
  // so far: the file read once is evaluated anew (not read again). InputError for an unknown
  // name, a mechanism that no longer reads or that is no longer admitted.
  Model With(const std::string& name, const std::string& formula) const;
  Model With(const std::string& name, double value) const;

  // The sweep of `koppel analyze`: from the assembly outward along the hint's branch.
  SweepTable Sweep(double from, double to, double step, int order = 2, AtBranchPoint at_branch_point = AtBranchPoint::kContinue) const;
  SweepTable Sweep(int order = 2) const;  // over the file's default sweep
  // The same, each row handed to `each_row` (the table so far, without values; the row's index;
  // its columns.size() values) as it is made instead of kept: `values` stays empty. For a table
  // too long to hold twice (koppel analyze writes 360 001 rows as text).
  using SweepRowSink = std::function<void(const SweepTable& table, int row, const double* values)>;
  SweepTable Sweep(double from, double to, double step, int order, AtBranchPoint at_branch_point, const SweepRowSink& each_row) const;

  // The dead centres of scalar output `output` (empty: the first) over from..to by step, the
  // search resolution [deg | length]; unset: the file's sweep range, step 1 (as the CLI).
  // The search follows the hint's branch as Sweep does, through branch points as `at_branch_point` says.
  DeadCentres FindDeadCentres(const std::string& output = "", std::optional<double> from = {}, std::optional<double> to = {},
                              std::optional<double> step = {}, AtBranchPoint at_branch_point = AtBranchPoint::kContinue) const;
  // The drivable interval of the hint's branch, or of every branch koppel finds.
  Ranges DrivableRanges(bool all_branches = false, AtBranchPoint at_branch_point = AtBranchPoint::kContinue) const;
  // The singular positions a sweep over the file's range meets.
  std::vector<SingularPosition> SingularPositions() const;

  // The instantaneous geometry at `input` [deg | length] on the hint's branch (koppel curvature):
  // the pole, inflection circle and Ball point of the link that carries `point` (as the CLI names
  // points: a point output, "link.point", or a point name one link has), and the radius and centre
  // of curvature of that point's path. InputError for an unknown point.
  CurvatureReport Curvature(const std::string& point, double input) const;
  // The instant centres of every pair of links at `input` (koppel poles).
  PolesReport Poles(double input) const;
  // The fixed and moving centrodes of `link` against `reference` ("": the frame) over from..to
  // by step, the moving one also carried to the pose at `at`. InputError for an unknown link.
  CentrodesReport Centrodes(const std::string& link, const std::string& reference, double from, double to, double step, double at) const;
  // Tolerances, clearances and Monte Carlo of one output (koppel tolerance). InputError for an
  // unknown output, parameter or joint, a clearance on a slide, a tolerance that is not positive.
  ToleranceResult Tolerances(const ToleranceRequest& request) const;

  // The mechanism as a mechanism file that Parse reads back: the text the model was read from
  // with every parameter set since (Load's `set`, With) rewritten in place, every other byte as
  // the user wrote it (EditMechanismText, koppel/catalog/document_edit.hpp); a mechanism made in
  // code (the editor page's) written anew, numbers with 17 digits.
  std::string ToYaml() const;

 private:
  struct Impl;
  // `file`: source.Evaluate(set), already evaluated
  static Model FromEvaluated(MechanismSource source, const ParameterValues& set, MechanismFile file);
  friend struct ModelAccess;  // the API's own sources reach the file read (model_impl.hpp)
  explicit Model(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;  // never changed once made: copies share it
};

}  // namespace koppel
