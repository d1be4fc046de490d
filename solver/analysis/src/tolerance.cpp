#include "koppel/analysis/tolerance.hpp"

#include "pose_walk.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/memory.hpp"
#include "koppel/core/worker_threads.hpp"


#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace koppel {
namespace {

// SplitMix64 (Steele, Lea, Flood 2014): a small generator whose every seed gives an independent
// stream, so sample k draws from (seed, k) alone.
class Random {
 public:
  Random(std::uint64_t seed, std::uint64_t stream) : state_(seed * 0x9E3779B97F4A7C15ULL ^ (stream + 0x632BE59BD9B4E019ULL)) { Next(); }
  std::uint64_t Next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  double Uniform() { return (Next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double Symmetric() { return 2 * Uniform() - 1; }           // [-1, 1)
  double Normal() {                                          // Box–Muller, one of the pair
    const double u1 = 1 - Uniform(), u2 = Uniform();
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * kPi * u2);
  }

 private:
  std::uint64_t state_;
};

// Linear interpolation between order statistics (Hyndman and Fan type 7, R's default).
double Quantile(const std::vector<double>& sorted, double level) {
  const double h = (sorted.size() - 1) * level;
  const size_t lo = static_cast<size_t>(std::floor(h));
  const size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - lo) * (sorted[hi] - sorted[lo]);
}

// One Monte Carlo sample: the parts as made (parameters drawn) and the same parts assembled
// with each clearance joint's pin moved in its hole (DisplacePin): Newton solves the assembly,
// the output is read off the parts (OutputOnLinks), as the linear gradient reads it.
struct Sample {
  Mechanism parts, assembly;
};

Expected<Sample> DrawSample(const MechanismBuilder& builder, const std::vector<double>& nominal, const ToleranceOptions& o, long k) {
  Random random(o.seed, static_cast<std::uint64_t>(k));
  std::vector<double> p = nominal;
  for (size_t j = 0; j < p.size(); ++j) {
    const double u = o.distribution == ToleranceDistribution::kUniform ? random.Symmetric() : random.Normal() / 3;
    p[j] += o.tolerances[j] * u;
  }
  Expected<Mechanism> built = builder(p);
  if (!built) return Expected<Sample>::Error(built.error());
  Sample sample{*built, *built};
  for (size_t c = 0; c < o.clearance_joints.size(); ++c) {
    // uniform in the disc: radius c sqrt(u)
    const double r = o.clearances[c] * std::sqrt(random.Uniform()), angle = 2 * kPi * random.Uniform();
    DisplacePin(&sample.assembly, o.clearance_joints[c], Eigen::Vector2d(r * std::cos(angle), r * std::sin(angle)));
  }
  return sample;
}

struct NominalPose {
  double input = 0;
  Eigen::VectorXd q;
};

// The samples at every reached row: values[row * samples + k], NaN where sample k failed. The
// threads are the shared pool's (koppel/core/worker_threads.hpp): fewer when no more can be had.
std::vector<double> RunSamples(const MechanismBuilder& builder, const std::vector<double>& nominal, const ToleranceOptions& o,
                               const std::vector<NominalPose>& poses, const std::vector<double>& nominal_y, bool angle) {
  const long n = o.samples;
  const size_t rows = poses.size();
  std::vector<double> values(rows * n, std::numeric_limits<double>::quiet_NaN());
  std::atomic<long> next{0};
  constexpr long kChunk = 16;
  const std::thread::id caller = std::this_thread::get_id();
  auto last_report = std::chrono::steady_clock::now();
  auto work = [&] {
    for (;;) {
      const long first = next.fetch_add(kChunk);
      if (first >= n) return;
      for (long k = first; k < std::min(n, first + kChunk); ++k) {
        const Expected<Sample> sample = DrawSample(builder, nominal, o, k);
        if (!sample) continue;
        PositionSolver solver(sample->assembly);
        const ConstraintSystem parts(sample->parts);
        for (size_t row = 0; row < rows; ++row) {
          Eigen::VectorXd q = poses[row].q;
          if (!solver.Correct(poses[row].input, q).ok()) continue;
          const double y = OutputOnLinks(parts, o.output, o.component, q);
          if (std::isfinite(y)) values[row * n + k] = angle ? nominal_y[row] + WrapToHalfTurn(y - nominal_y[row]) : y;
        }
      }
      // the callback runs on the caller's thread only, about ten times a second: it need not be thread-safe
      const auto now = std::chrono::steady_clock::now();
      if (o.progress && std::this_thread::get_id() == caller && now - last_report >= std::chrono::milliseconds(100)) {
        last_report = now;
        o.progress(std::min(n, next.load()), n);
      }
    }
  };
  // more threads than chunks would find nothing to do
  RunOnThreads(static_cast<int>(std::min<long>(o.threads, std::max(1L, n / kChunk))), work);
  if (o.progress) o.progress(n, n);
  return values;
}

void Statistics(const double* values, long n, const std::vector<double>& levels, ToleranceRow* row) {
  std::vector<double> v;
  v.reserve(n);
  for (long k = 0; k < n; ++k) {
    if (std::isfinite(values[k])) v.push_back(values[k]);
  }
  row->mc_samples = static_cast<long>(v.size());
  row->mc_failed = n - row->mc_samples;
  if (v.empty()) return;
  std::sort(v.begin(), v.end());
  row->mc_min = v.front();
  row->mc_max = v.back();
  // Welford's running mean and sum of squared deviations: no sum of all values to overflow
  double mean = 0, sum = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const double delta = v[i] - mean;
    mean += delta / static_cast<double>(i + 1);
    sum += delta * (v[i] - mean);
  }
  row->mc_mean = mean;
  row->mc_std = v.size() > 1 ? std::sqrt(sum / (v.size() - 1)) : 0.0;
  if (!std::isfinite(row->mc_mean) || !std::isfinite(row->mc_std)) {
    row->ok = false;
    row->message = "the Monte Carlo samples' spread exceeds the range of double-precision numbers";
  }
  for (double level : levels) row->quantiles.push_back(Quantile(v, level));
}

// sqrt(sum x^2) without overflow or underflow of the squares (a tolerance of 1e200 gives a
// stack-up of 1e200, not infinity): each term scaled by the largest.
double Norm(const std::vector<double>& terms) {
  double largest = 0;
  for (double x : terms) largest = std::max(largest, std::abs(x));
  if (!(largest > 0) || !std::isfinite(largest)) return largest;
  double sum = 0;
  for (double x : terms) sum += (x / largest) * (x / largest);
  return largest * std::sqrt(sum);
}

// The linear stack-up of one row from its sensitivities. Each term's variance (s_j sigma_j)^2 or
// (|dy/d delta| c)^2 / 4 is its share of linear_std^2: the shares use the model linear_std does.
// A stack-up beyond the range of double (tolerances far beyond the mechanism's size) leaves the
// row without it, saying so: never an infinity in a table.
void Linear(const ToleranceOptions& o, ToleranceRow* row) {
  const double sigma_per_tolerance = o.distribution == ToleranceDistribution::kUniform ? 1 / std::sqrt(3.0) : 1.0 / 3;
  std::vector<double> parts, deviations;  // s_j T_j; the standard deviations: tolerances, then clearances
  for (size_t j = 0; j < o.tolerances.size(); ++j) {
    const double part = row->sensitivity[j] * o.tolerances[j];
    row->worst_case += std::abs(part);
    parts.push_back(part);
    deviations.push_back(part * sigma_per_tolerance);
  }
  for (size_t c = 0; c < o.clearances.size(); ++c) {
    const double part = row->clearance_gain[c] * o.clearances[c];
    row->clearance_worst_case += part;
    deviations.push_back(part / 2);  // the projection of a point uniform in a disc of radius c: c^2/4
  }
  row->rss = Norm(parts);
  row->linear_std = Norm(deviations);
  for (double d : deviations) row->share.push_back(row->linear_std > 0 ? (d / row->linear_std) * (d / row->linear_std) : 0.0);
  const bool finite = std::isfinite(row->worst_case) && std::isfinite(row->clearance_worst_case) && std::isfinite(row->linear_std);
  if (!finite) {
    row->ok = false;
    row->message = "the linear stack-up exceeds the range of double-precision numbers (a tolerance or clearance far "
                   "beyond the mechanism's size)";
  }
}

ToleranceReport Failed(std::string why) {
  ToleranceReport r;
  r.status = AnalysisStatus::kFailed;
  r.message = std::move(why);
  return r;
}

// The report's status from its rows: failed when no input has a result (not reached, or its
// stack-up overflows), partial when some have none or Monte Carlo samples did not assemble.
void SetToleranceReportStatus(ToleranceReport* report) {
  report->status = AnalysisStatus::kComplete;
  long failed_samples = 0;
  size_t failed_rows = 0;
  for (const ToleranceRow& row : report->rows) {
    failed_rows += row.ok ? 0 : 1;
    failed_samples = std::max(failed_samples, row.mc_failed);
  }
  if (failed_rows == report->rows.size()) {
    report->status = AnalysisStatus::kFailed;
    report->message = "no input has a result: " + report->rows.front().message;
  } else if (failed_rows > 0) {
    report->status = AnalysisStatus::kPartial;
    report->message = std::to_string(failed_rows) + " of " + std::to_string(report->rows.size()) + " inputs without a result (see each)";
  }
  if (failed_samples > 0) {
    report->status = AnalysisStatus::kPartial;
    report->message += std::string(report->message.empty() ? "" : "; ") + "up to " + std::to_string(failed_samples) +
                       " Monte Carlo samples per input did not assemble there (the tolerances reach past the mechanism's limits)";
  }
}

}  // namespace

bool IsToleranceSize(double value) { return value > 0 && value <= kMaxCoordinate; }

const char* ToString(ToleranceDistribution distribution) {
  return distribution == ToleranceDistribution::kUniform ? "uniform" : "normal";
}

bool ToleranceOptions::IsValid(const Mechanism& nominal, std::string* why) const {
  auto fail = [&](std::string text) {
    *why = std::move(text);
    return false;
  };
  if (output < 0 || output >= static_cast<int>(nominal.outputs.size())) return fail("no such output");
  if (component < 0 || component >= nominal.outputs[output].Components()) return fail("no such component of the output");
  if (inputs.empty()) return fail("no input to evaluate at");
  for (double t : tolerances) {
    if (!IsToleranceSize(t)) return fail(std::string("a tolerance must be ") + kToleranceSizeRule);
  }
  if (clearance_joints.size() != clearances.size()) return fail("one clearance per joint");
  for (size_t c = 0; c < clearances.size(); ++c) {
    const int j = clearance_joints[c];
    if (j < 0 || j >= static_cast<int>(nominal.joints.size())) return fail("no such joint");
    if (nominal.joints[j].type != JointType::kRevolute)
      return fail("joint '" + nominal.joints[j].name + "' is not a revolute joint: clearance is modelled for pins in holes");
    if (!IsToleranceSize(clearances[c])) return fail(std::string("a clearance must be ") + kToleranceSizeRule);
  }
  if (samples < 0 || samples > kMaxToleranceSamples)
    return fail("the number of samples must lie between 0 and " + std::to_string(kMaxToleranceSamples) + " (kMaxToleranceSamples)");
  if (static_cast<double>(samples) * static_cast<double>(inputs.size()) > static_cast<double>(kMaxToleranceValues))
    return fail(std::to_string(samples) + " samples at " + std::to_string(inputs.size()) + " inputs are more than " +
                std::to_string(kMaxToleranceValues) + " values (kMaxToleranceValues): fewer samples or inputs");
  if (threads < 0 || threads > kMaxThreads) return fail("threads must lie between 0 (one per core) and " + std::to_string(kMaxThreads) + " (kMaxThreads)");
  for (double level : quantile_levels) {
    if (!(level >= 0 && level <= 1)) return fail("quantile levels lie in [0, 1]");
  }
  why->clear();
  return true;
}

std::uint64_t ToleranceValueBytes(const ToleranceOptions& o) {
  // every value until its input's statistics, and one input's sorted copy
  const double values = static_cast<double>(std::max(0L, o.samples)) * (static_cast<double>(o.inputs.size()) + 1.0);
  return static_cast<std::uint64_t>(std::min(values * sizeof(double), 1.8e19));
}

Outcome CheckToleranceMemory(const ToleranceOptions& o, std::uint64_t usable_bytes, const std::string& source) {
  const std::uint64_t needed = ToleranceValueBytes(o);
  // half of it: the process holds its code, the mechanisms and the threads' stacks besides
  if (needed <= usable_bytes / 2) return Done();
  return Outcome::Error(std::to_string(o.samples) + " Monte Carlo samples at " + std::to_string(o.inputs.size()) + " inputs need about " +
                        FormatBytes(static_cast<double>(needed)) + " of memory, more than half the " +
                        FormatBytes(static_cast<double>(usable_bytes)) + " this process may have (" + source +
                        "): fewer samples, or the inputs in several runs");
}

ToleranceReport AnalyseTolerances(const MechanismBuilder& builder, const std::vector<double>& nominal, const ToleranceOptions& o) {
  const Expected<Mechanism> built = builder(nominal);
  if (!built) return Failed("the nominal parameters make no mechanism: " + built.error());
  const Mechanism& m = *built;
  if (o.tolerances.size() != nominal.size()) return Failed("one tolerance per parameter");
  if (std::string why; !o.IsValid(m, &why)) return Failed(why);
  Perturbations perturbed;
  if (!Perturb(builder, nominal, &perturbed)) return Failed("a parameter moved by its difference step makes no mechanism");
  const bool angle = m.OutputIsAngle(o.output);

  ToleranceReport report;
  PoseWalk walk(m);
  if (!walk.started()) return Failed(walk.error());
  std::vector<NominalPose> poses;
  std::vector<double> nominal_y;
  std::vector<size_t> reached;  // rows with a nominal pose
  for (double input : o.inputs) {
    ToleranceRow row;
    row.input = input;
    row.message = walk.To(input);
    Eigen::VectorXd q = walk.walk().q();
    // the sensitivities need the Jacobian factorised at exactly this pose
    if (row.message.empty() && !walk.solver().Correct(input, q).ok()) row.message = "the nominal pose did not converge";
    if (row.message.empty()) {
      row.ok = true;  // unless its stack-up overflows (Linear)
      PositionSolver& solver = walk.solver();
      row.nominal = solver.system().Output(o.output, o.component, q.data());
      Eigen::MatrixXd d;
      OutputSensitivity(solver, q, input, perturbed, o.output, o.component, 1, angle, &d);
      row.sensitivity.assign(d.data(), d.data() + d.size());
      for (int joint : o.clearance_joints) row.clearance_gain.push_back(ClearanceGradient(solver, q, joint, o.output, o.component).norm());
      Linear(o, &row);
    }
    if (row.ok) {
      reached.push_back(report.rows.size());
      poses.push_back({input, q});
      nominal_y.push_back(row.nominal);
    }
    report.rows.push_back(std::move(row));
  }
  if (o.samples > 0 && !poses.empty()) {
    const std::vector<double> values = RunSamples(builder, nominal, o, poses, nominal_y, angle);
    for (size_t i = 0; i < reached.size(); ++i) Statistics(values.data() + i * o.samples, o.samples, o.quantile_levels, &report.rows[reached[i]]);
  }
  SetToleranceReportStatus(&report);
  return report;
}

}  // namespace koppel
