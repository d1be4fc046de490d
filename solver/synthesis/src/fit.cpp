// Several starts of a least-squares fit on parallel threads (each solved by Ceres in the module
// of ceres_solves.hpp), the best design chosen, its targets held to their tolerances.
#include "koppel/synthesis/fit.hpp"

#include "ceres_solves.hpp"
#include "fit_model.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/worker_threads.hpp"
#include "koppel/synthesis/mechanism_space.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <random>
#include <thread>
#include <utility>

namespace koppel {
namespace {

// Starts whose cost is within this of the best count as having reached it: relative for
// inexact problems, absolute (residuals about 1e-12) for exactly solvable ones.
constexpr double kSameCostRelative = 1e-6;
constexpr double kSameCostAbsolute = 1e-24;

bool Finite(double v) { return v > -1e299 && v < 1e299; }

// The unknowns of every start: the given one first, then uniform within the bounds (a side
// without a bound: the start value +- max(|start|, 1)), from the fixed seed, so that the starts
// do not depend on how they are spread over threads.
std::vector<std::vector<double>> StartPoints(const std::vector<FitParameter>& parameters, const std::vector<FitTarget>& targets, const FitOptions& o) {
  std::mt19937 rng(o.seed);
  std::vector<std::vector<double>> starts(o.starts);
  for (int k = 0; k < o.starts; ++k) {
    for (const FitParameter& p : parameters) {
      double v = p.start;
      if (k > 0) {
        const double reach = std::max(std::abs(p.start), 1.0);
        const double lo = Finite(p.lower) ? p.lower : p.start - reach, hi = Finite(p.upper) ? p.upper : p.start + reach;
        v = std::uniform_real_distribution<double>(lo, hi)(rng);
      }
      starts[k].push_back(v);
    }
    for (const FitTarget& t : targets) {
      if (t.input_free) starts[k].push_back(t.input);
    }
  }
  return starts;
}

struct StartOutcome {
  FitStart start;
  std::vector<double> x;          // unknowns at the solution
  std::vector<double> residuals;  // weighted, at the solution
  int iterations = 0;
  double drivable_from = 0, drivable_to = 0;
};

// The drive's reach from the assembly hint, up to the far end of the required range either way:
// whether the design assembles over [require_from, require_to], and where it stops if not.
void CheckRequiredRange(const MechanismBuilder& builder, const std::vector<double>& values, const FitOptions& o, StartOutcome* out) {
  if (o.require_to == o.require_from) {
    out->start.assembles_over_range = true;
    return;
  }
  const Expected<Mechanism> built = builder(values);
  if (!built) return;
  const Mechanism& m = *built;
  const double lo = std::min(o.require_from, o.require_to), hi = std::max(o.require_from, o.require_to);
  const double span = std::max(std::abs(hi - m.hint.input), std::abs(lo - m.hint.input));
  const InputRange reach = DrivableRange(m, span, (hi - lo) / 360);
  out->drivable_from = reach.low;
  out->drivable_to = reach.high;
  out->start.assembles_over_range = reach.low <= lo && reach.high >= hi;
}

// The stretch mu_min is held over: the required range, else a whole turn of an R drive from its
// assembly (FitOptions::space; a slide drive without a required range is refused up front).
std::pair<double, double> WorkedStretch(const Mechanism& m, const FitOptions& o) {
  if (o.require_to != o.require_from) return {std::min(o.require_from, o.require_to), std::max(o.require_from, o.require_to)};
  return {m.hint.input, m.hint.input + 2 * kPi};
}

// Which design-space constraint the start's solution breaks (FitStart::outside).
void CheckSpace(const MechanismBuilder& builder, const std::vector<double>& values, const FitOptions& o, StartOutcome* out) {
  if (o.space.Empty()) return;
  const Expected<Mechanism> built = builder(values);
  if (!built) {
    out->start.outside = "the design does not build: " + built.error();
    return;
  }
  const auto [from, to] = WorkedStretch(*built, o);
  out->start.outside = MechanismViolation(o.space, *built, from, to);
}

StartOutcome RunStart(const MechanismBuilder& builder, const TargetModel& model, const std::vector<FitParameter>& parameters,
                      const FitOptions& o, int index, std::vector<double> x) {
  StartOutcome out;
  out.start.index = index;
  const int n = static_cast<int>(parameters.size());
  // a start that does not reach every target is not handed to Ceres (which would log the failure)
  std::vector<double> at_start(model.Residuals());
  if (!model.Evaluate(x.data(), n, at_start.data(), nullptr)) {
    out.start.brief = "the mechanism does not assemble at every target at this start";
    return out;
  }
  BoundedLeastSquares problem;
  problem.residuals = model.Residuals();
  problem.unknowns = static_cast<int>(x.size());
  problem.lower.assign(x.size(), -std::numeric_limits<double>::infinity());
  problem.upper.assign(x.size(), std::numeric_limits<double>::infinity());
  for (int j = 0; j < n; ++j) {
    problem.lower[j] = parameters[j].lower;
    problem.upper[j] = parameters[j].upper;
  }
  problem.evaluate = [&model, n](const double* p, double* residuals, double* jacobian) {
    return model.Evaluate(p, n, residuals, jacobian);
  };
  problem.max_iterations = o.max_iterations;
  const LeastSquaresOutcome summary = CeresSolves().fit(problem, x.data());
  out.start.brief = summary.brief;
  out.iterations = summary.iterations;
  if (!summary.usable) return out;
  out.residuals.resize(model.Residuals());
  if (!model.Evaluate(x.data(), n, out.residuals.data(), nullptr)) return out;
  out.start.usable = true;
  out.start.cost = 0;
  for (double v : out.residuals) out.start.cost += 0.5 * v * v;
  out.x = x;
  CheckRequiredRange(builder, std::vector<double>(x.begin(), x.begin() + n), o, &out);
  CheckSpace(builder, std::vector<double>(x.begin(), x.begin() + n), o, &out);
  return out;
}

// Runs every start, on up to o.threads threads; each writes only its own slot.
std::vector<StartOutcome> RunStarts(const MechanismBuilder& builder, const TargetModel& model, const std::vector<FitParameter>& parameters,
                                    const std::vector<FitTarget>& targets, const FitOptions& o) {
  CeresSolves();  // loaded here, so that a missing module is the caller's exception, not each start's
  const std::vector<std::vector<double>> points = StartPoints(parameters, targets, o);
  std::vector<StartOutcome> outcomes(points.size());
  std::atomic<int> next{0};
  auto work = [&] {
    for (int k = next++; k < static_cast<int>(points.size()); k = next++) {
      // an exception must not end the program from a worker thread: the start is merely unusable
      try {
        outcomes[k] = RunStart(builder, model, parameters, o, k, points[k]);
      } catch (const std::exception& e) {
        outcomes[k].start.index = k;
        outcomes[k].start.brief = std::string("failed: ") + e.what();
      }
    }
  };
  RunOnThreads(std::min(o.threads > 0 ? o.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency())), o.starts), work);
  return outcomes;
}

// Designs inside the design space win over any outside it; then those that assemble over the
// required range; then the lower cost; then the earlier start.
bool Better(const StartOutcome& a, const StartOutcome& b) {
  if (a.start.outside.empty() != b.start.outside.empty()) return a.start.outside.empty();
  if (a.start.assembles_over_range != b.start.assembles_over_range) return a.start.assembles_over_range;
  return a.start.cost < b.start.cost;
}

std::string FormatResidual(const FitTargetResult& t) {
  return t.unit == FitUnit::kAngle ? fmt::format("{:.6g} deg (tolerance {:.6g} deg)", RadToDeg(t.residual), RadToDeg(t.tolerance))
                                   : fmt::format("{:.6g} (tolerance {:.6g})", t.residual, t.tolerance);
}

// Per target: its unit, its residual (unweighted), the tolerance it is held to.
void ReportTargets(const Mechanism& m, const std::vector<FitTarget>& targets, const FitOptions& o, int n, const StartOutcome& best,
                   FitReport* report) {
  int row = 0, free_index = 0;
  for (const FitTarget& t : targets) {
    FitTargetResult r;
    r.name = t.name;
    r.unit = TargetUnit(m, t);
    const std::vector<double>& res = best.residuals;
    double residual = t.point ? std::hypot(res[row], res[row + 1]) : std::abs(res[row]);
    for (int k = 1; t.straight && k < t.samples; ++k) residual = std::max(residual, std::abs(res[row + k]));
    r.residual = residual / std::abs(t.weight != 0 ? t.weight : 1);
    r.tolerance = t.tolerance > 0 ? t.tolerance : r.unit == FitUnit::kAngle ? o.angle_tolerance : o.length_tolerance;
    r.met = r.residual <= r.tolerance;
    r.input = t.input_free ? best.x[n + free_index++] : t.input;
    report->targets.push_back(r);
    row += t.straight ? t.samples : t.point ? 2 : 1;
  }
}

}  // namespace

const char* ToString(FitUnit unit) { return unit == FitUnit::kAngle ? "angle" : "length"; }

const char* ToString(FitStatus status) {
  switch (status) {
    case FitStatus::kNotRun: return "not run";
    case FitStatus::kConverged: return "converged";
    case FitStatus::kAboveTolerance: return "above tolerance";
    case FitStatus::kNotAssembling: return "does not assemble over the required range";
    case FitStatus::kNoUsableStart: return "no usable start";
    case FitStatus::kOutsideSpace: return "outside the design space";
    case FitStatus::kInvalidOptions: return "invalid options";
  }
  return "not run";
}

bool FitOptions::IsValid(std::string* why) const {
  std::string problem;
  if (starts < 1 || starts > 100000) problem = "starts must be between 1 and 100000";
  else if (max_iterations < 0) problem = "max_iterations must not be negative";
  else if (threads < 0 || threads > kMaxThreads)
    problem = "threads must be 0 (one per core) to " + std::to_string(kMaxThreads) + " (kMaxThreads)";
  else if (!(std::isfinite(require_from) && std::isfinite(require_to))) problem = "the required range must be finite";
  else if (!(length_tolerance > 0 && angle_tolerance > 0)) problem = "the tolerances must be positive";
  else if (std::string space_why; !space.IsValid(&space_why)) problem = "design space: " + space_why;
  if (why) *why = problem;
  return problem.empty();
}

std::string FitReport::Brief() const {
  std::string text = fmt::format("{}: cost {:.3g}", ToString(status), cost);
  if (best_start >= 0) text += fmt::format(", start {} ({} of {} starts reached it)", best_start + 1, starts_at_best, starts.size());
  if (!message.empty()) text += "; " + message;
  return text;
}

namespace {

// Why the design space cannot be checked on this fit's mechanism (built at the given start; the
// free parameters change sizes, not which outputs it has or how it is driven); empty when it can.
std::string SpaceUncheckable(const MechanismBuilder& builder, const std::vector<FitParameter>& parameters, const FitOptions& options) {
  if (options.space.Empty()) return "";
  std::vector<double> start;
  for (const FitParameter& p : parameters) start.push_back(p.start);
  const Expected<Mechanism> built = builder(start);
  if (!built) return "";  // the starts say so, each in its own report
  if (std::string why = UncheckableSpace(options.space, *built); !why.empty()) return why;
  if (options.space.mu_min && !built->InputIsAngle() && options.require_to == options.require_from)
    return "mu_min: a slide drive has no whole turn to hold it over; give the worked stretch as `require:`";
  return "";
}

// The verdict on the fitted design: every target within its tolerance, and the required range.
void SetFitVerdict(const Mechanism& fitted, const FitOptions& options, FitReport* report) {
  std::string missed;
  int n_missed = 0;
  for (size_t i = 0; i < report->targets.size(); ++i) {
    const FitTargetResult& t = report->targets[i];
    if (t.met) continue;
    ++n_missed;
    missed += fmt::format("{}target {} '{}' misses by {}", missed.empty() ? "" : "; ", i + 1, t.name, FormatResidual(t));
  }
  if (n_missed > 0) {
    report->status = FitStatus::kAboveTolerance;
    report->message = fmt::format("{} of {} targets above tolerance: {}", n_missed, report->targets.size(), missed);
  } else if (!report->assembles_over_range) {
    report->status = FitStatus::kNotAssembling;
    const bool angle = fitted.InputIsAngle();
    auto in_unit = [angle](double v) { return angle ? RadToDeg(v) : v; };
    report->message = fmt::format("the design does not assemble over the required range {:.6g} .. {:.6g}{}: its drive reaches {:.6g} .. {:.6g}",
                                  in_unit(options.require_from), in_unit(options.require_to), angle ? " deg" : "", in_unit(report->drivable_from),
                                  in_unit(report->drivable_to));
  } else {
    report->status = FitStatus::kConverged;
  }
}

}  // namespace

FitReport Fit(const MechanismBuilder& builder, const std::vector<FitParameter>& parameters, const std::vector<FitTarget>& targets,
              const FitOptions& options) {
  FitReport report;
  std::string why;
  if (!options.IsValid(&why) || targets.empty()) {
    report.status = FitStatus::kInvalidOptions;
    report.message = targets.empty() ? "no targets" : why;
    return report;
  }
  if (std::string why_not = SpaceUncheckable(builder, parameters, options); !why_not.empty()) {
    report.status = FitStatus::kInvalidOptions;
    report.message = "design space: " + why_not;
    return report;
  }
  const TargetModel model(builder, targets);
  const int n = static_cast<int>(parameters.size());
  const std::vector<StartOutcome> outcomes = RunStarts(builder, model, parameters, targets, options);
  const StartOutcome* best = nullptr;
  for (const StartOutcome& o : outcomes) {
    report.starts.push_back(o.start);
    if (o.start.usable && (!best || Better(o, *best))) best = &o;
  }
  if (!best) {
    report.status = FitStatus::kNoUsableStart;
    report.message = "no start gave a design that assembles at every target";
    return report;
  }
  if (!best->start.outside.empty()) {
    report.status = FitStatus::kOutsideSpace;
    report.best_start = best->start.index;
    report.cost = best->start.cost;
    report.message = fmt::format("no start gave a design inside the design space; the best (start {}, cost {:.3g}) breaks {}", best->start.index + 1,
                                 best->start.cost, best->start.outside);
    return report;
  }
  for (const StartOutcome& o : outcomes) {
    if (o.start.usable && o.start.outside.empty() && o.start.assembles_over_range == best->start.assembles_over_range &&
        o.start.cost <= best->start.cost * (1 + kSameCostRelative) + kSameCostAbsolute)
      ++report.starts_at_best;
  }
  report.best_start = best->start.index;
  report.cost = best->start.cost;
  report.iterations = best->iterations;
  report.values.assign(best->x.begin(), best->x.begin() + n);
  report.assembles_over_range = best->start.assembles_over_range;
  report.drivable_from = best->drivable_from;
  report.drivable_to = best->drivable_to;
  const Expected<Mechanism> built = builder(report.values);
  if (!built) {  // it was built for this start's evaluation: a builder that changed its mind
    report.status = FitStatus::kNoUsableStart;
    report.message = "the fitted values no longer build the mechanism: " + built.error();
    return report;
  }
  const Mechanism& fitted = *built;
  ReportTargets(fitted, targets, options, n, *best, &report);
  SetFitVerdict(fitted, options, &report);
  return report;
}

}  // namespace koppel
