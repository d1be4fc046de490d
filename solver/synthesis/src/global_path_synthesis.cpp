// Path synthesis without an atlas (path_synthesis.hpp's SynthesisePathGlobally): a global search by
// random starts, each polished in closed form within the design space's bounds, with the timing
// prescribed or free (then every point's crank angle an unknown, ordered along the path).
//
// Why random starts and a bounded least-squares polish, not an evolutionary method: the closed
// form of the coupler point makes one polish from a start a millisecond or two (Ceres, 10
// unknowns, automatic derivatives), and every polish ends at a local minimum inside the bounds;
// on the four test problems of tests/data/benchmarks the default 4000 starts take 3 to 10 s on
// two cores (koppel bench --filter path-). A start
// is drawn as a shape (link ratios, K, the first crank angle) and laid onto the points by the
// similarity the space leaves free (Umeyama's closed form: scale, and rotation and translation
// unless the frame angle or A0 is fixed), so every polish starts near the points' size and place.
#include "koppel/synthesis/path_synthesis.hpp"

#include "ceres_solves.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/plane.hpp"
#include "koppel/core/worker_threads.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/position.hpp"
#include "path_prepolish.hpp"  // PointsScale
#include "path_residual.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <random>

namespace koppel {
namespace {

using Complex = std::complex<double>;
constexpr double kInf = std::numeric_limits<double>::infinity();

// A shape's links, relative to the frame, are drawn log-uniform within this factor either way;
// the polish goes beyond it (the ellipse's best design has a frame 10 times its crank).
constexpr double kShapeSpread = 12;
// Draws per wanted start before the search gives up on a space that admits too few shapes.
constexpr int kDrawsPerStart = 200;
// A re-analysed coupler point this far from the closed form's (times the points' size) sits on
// another branch: the walk crossed a dead centre between two prescribed angles.
constexpr double kSameBranch = 1e-6;
// Distinct polished starts carried to the re-analysis, per design returned.
constexpr int kReanalysedPerDesign = 4;

// The prescribed timing's offsets from the first point's angle.
std::vector<double> Offsets(const PathRequest& r) {
  std::vector<double> offsets(r.points.size());
  for (size_t i = 0; i < offsets.size(); ++i) offsets[i] = r.timing.empty() ? i * *r.timing_step : r.timing[i] - r.timing[0];
  return offsets;
}

// The unknowns' bounds (lower == upper: fixed) from the design space; links stay positive.
void Bounds(const PathRequest& r, double scale, std::vector<double>* lower, std::vector<double>* upper) {
  lower->assign(kTimedUnknowns, -kInf);
  upper->assign(kTimedUnknowns, kInf);
  const DesignSpace& s = r.space;
  if (s.a0) {
    (*lower)[0] = (*upper)[0] = s.a0->x();
    (*lower)[1] = (*upper)[1] = s.a0->y();
  } else {
    if (s.pivots_x) std::tie((*lower)[0], (*upper)[0]) = *s.pivots_x;
    if (s.pivots_y) std::tie((*lower)[1], (*upper)[1]) = *s.pivots_y;
  }
  if (s.frame_angle) (*lower)[3] = (*upper)[3] = *s.frame_angle;
  for (int j : {2, 4, 5, 6}) {
    (*lower)[j] = std::max(1e-6 * scale, s.lengths ? s.lengths->first : 0.0);
    if (s.lengths) (*upper)[j] = s.lengths->second;
  }
  if (s.coupler_point)
    for (int j : {7, 8}) std::tie((*lower)[j], (*upper)[j]) = *s.coupler_point;
  if (!r.timing.empty()) (*lower)[9] = (*upper)[9] = r.timing.front();
}

TimedLimits Limits(const DesignSpace& s) {
  TimedLimits limits;
  limits.crank = s.input == InputTurn::kCrank;
  limits.ratio = s.ratio.value_or(0);
  if (s.pivots_x) limits.b0_x[0] = s.pivots_x->first, limits.b0_x[1] = s.pivots_x->second;
  if (s.pivots_y) limits.b0_y[0] = s.pivots_y->first, limits.b0_y[1] = s.pivots_y->second;
  if (s.mu_min && limits.crank) limits.cos_mu = std::cos(*s.mu_min);  // over the turn; checked again by the solver
  return limits;
}

struct Problem {
  const PathRequest* request = nullptr;
  double scale = 0;
  std::vector<double> offsets, lower, upper;
  TimedLimits limits;
  bool free = false;            // the timing free: offsets are each start's guess
  bool repeats_first = false;   // a closed path whose last point repeats its first (one turn later)
  std::vector<int> same_phase;  // per point: -1, or the point whose crank angle it shares
};

// The coupler points of u at every offset on `branch`; false where the loop does not close.
// `limits` default to the problem's.
bool CouplerPoints(const Problem& p, const double* u, int branch, const std::vector<double>& offsets, std::vector<Complex>* out,
                   const TimedLimits* limits = nullptr) {
  out->resize(offsets.size());
  for (size_t i = 0; i < offsets.size(); ++i) {
    double r[2];
    if (!TimedPointResidual{Eigen::Vector2d::Zero(), offsets[i], branch, limits ? limits : &p.limits}(u, r)) return false;
    (*out)[i] = Complex(r[0], r[1]);
  }
  return true;
}

// Lays the shape u (A0 at the origin, frame along +x) onto the points by the similarity the
// space leaves free; false when it cannot (a scale <= 0, outside a bound).
bool LayOnPoints(const Problem& p, int branch, const std::vector<double>& offsets, double* u) {
  // the shape's limits: its crank and ratio are those of the design; B0's box is not yet its
  TimedLimits shape = p.limits;
  shape.b0_x[0] = shape.b0_y[0] = -1e300;
  shape.b0_x[1] = shape.b0_y[1] = 1e300;
  std::vector<Complex> c;
  if (!CouplerPoints(p, u, branch, offsets, &c, &shape)) return false;
  const bool a0_fixed = p.lower[0] == p.upper[0] && p.lower[1] == p.upper[1];
  const bool angle_fixed = p.lower[3] == p.upper[3];
  std::vector<Complex> target(c.size());
  for (size_t i = 0; i < c.size(); ++i) target[i] = Complex(p.request->points[i].x(), p.request->points[i].y());
  Complex c_mean = 0, t_mean = 0, a0(p.lower[0], p.lower[1]);
  if (!a0_fixed) {
    for (size_t i = 0; i < c.size(); ++i) c_mean += c[i] / static_cast<double>(c.size()), t_mean += target[i] / static_cast<double>(c.size());
  } else {
    t_mean = a0;  // c is about A0 = 0 already
  }
  Complex cross = 0;
  double norm = 0;
  for (size_t i = 0; i < c.size(); ++i) {
    cross += std::conj(c[i] - c_mean) * (target[i] - t_mean);
    norm += std::norm(c[i] - c_mean);
  }
  if (!(norm > 0)) return false;
  Complex z = cross / norm;  // scale * e^(i angle)
  if (angle_fixed) {
    const double along = std::real(cross * std::polar(1.0, -p.lower[3])) / norm;  // the scale, the angle given
    if (!(along > 0)) return false;
    z = std::polar(along, p.lower[3]);
  }
  const double k = std::abs(z);
  if (!(k > 0)) return false;
  const Complex place = a0_fixed ? a0 : t_mean - z * c_mean;
  u[0] = place.real();
  u[1] = place.imag();
  u[3] = angle_fixed ? p.lower[3] : std::arg(z);
  for (int j : {2, 4, 5, 6, 7, 8}) u[j] *= k;
  for (int j = 0; j < kTimedUnknowns; ++j)
    if (!(u[j] >= p.lower[j] && u[j] <= p.upper[j])) return false;
  const double b0x = u[0] + u[2] * std::cos(u[3]), b0y = u[1] + u[2] * std::sin(u[3]);
  return p.limits.Admit(u, b0x, b0y) && CouplerPoints(p, u, branch, offsets, &c);
}

// A polished start: sse infinite when it found no admissible shape (or, the timing free, passed
// the points out of order).
struct Polished {
  double sse = kInf;
  std::array<double, kTimedUnknowns> u{};
  int branch = 1;
  int index = 0;
  std::vector<double> inputs;  // each point's crank angle from the frame line, in the order driven
};

// The guessed offsets of a start with the timing free: the points spread over a turn (closed) or
// a random part of one (open), in a random sense.
std::vector<double> GuessedOffsets(const Problem& p, std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0, 1);
  const size_t n = p.request->points.size(), distinct = p.repeats_first ? n - 1 : n;
  const double sense = unit(random) < 0.5 ? 1 : -1;
  const double span = p.request->open ? (0.15 + 0.85 * unit(random)) * 2 * kPi * (distinct - 1) / distinct : 2 * kPi * (distinct - 1) / distinct;
  std::vector<double> offsets(n, 0.0);
  for (size_t i = 0; i < distinct; ++i) offsets[i] = sense * span * i / (distinct - 1);
  return offsets;
}

// The polished crank angles (from the frame line) as the mechanism is driven through them: each
// point reached once, in order, within a turn (a repeated first point a whole turn after it);
// empty when the order breaks (an order defect).
std::vector<double> OrderedInputs(const Problem& p, const std::vector<double>& phases) {
  const size_t n = phases.size(), distinct = p.repeats_first ? n - 1 : n;
  const double step = AngleDifference(phases[1], phases[0]);
  const double sense = step >= 0 ? 1 : -1;
  std::vector<double> inputs = {phases[0]};
  double previous = 0;
  for (size_t i = 1; i < distinct; ++i) {
    double d = std::fmod(sense * (phases[i] - phases[0]), 2 * kPi);
    if (d < 0) d += 2 * kPi;
    if (!(d > previous)) return {};
    previous = d;
    inputs.push_back(phases[0] + sense * d);
  }
  if (p.repeats_first) inputs.push_back(phases[0] + sense * 2 * kPi);
  return inputs;
}

// Start `index` of the search: drawn from its own generator (the same designs on any number of
// threads), laid and polished.
Polished PolishStart(const Problem& p, int index) {
  std::mt19937_64 random(p.request->seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(index));
  std::uniform_real_distribution<double> unit(0, 1);
  const auto spread = [&] { return std::exp(std::log(kShapeSpread) * (2 * unit(random) - 1)); };
  Polished best;
  best.index = index;
  for (int draw = 0; draw < kDrawsPerStart; ++draw) {
    std::array<double, kTimedUnknowns> u{};
    u[2] = 1;
    u[4] = spread(), u[5] = spread(), u[6] = spread();
    u[7] = 4 * unit(random) - 2, u[8] = 4 * unit(random) - 2;
    u[9] = p.lower[9] == p.upper[9] ? p.lower[9] : 2 * kPi * unit(random);
    const int branch = unit(random) < 0.5 ? 1 : -1;
    const std::vector<double> offsets = p.free ? GuessedOffsets(p, random) : p.offsets;
    if (!LayOnPoints(p, branch, offsets, u.data())) continue;
    TimedPathProblem problem;
    problem.points = p.request->points;
    problem.offsets = offsets;
    problem.branch = branch;
    problem.limits = p.limits;
    problem.lower = p.lower;
    problem.upper = p.upper;
    std::vector<double> phases(offsets.size());
    if (p.free) {
      for (size_t i = 0; i < offsets.size(); ++i) phases[i] = u[9] + offsets[i];
      problem.phases = &phases;
      problem.same_phase = p.same_phase;
    }
    const double sse = CeresSolves().timed_path(problem, u.data());
    if (!std::isfinite(sse)) return best;
    std::vector<double> inputs(offsets.size());
    if (p.free) {
      inputs = OrderedInputs(p, phases);
      if (inputs.empty()) return best;  // an order defect: the points are not passed in order
      u[9] = inputs.front();
    } else {
      for (size_t i = 0; i < offsets.size(); ++i) inputs[i] = u[9] + offsets[i];
    }
    best = {sse, u, branch, index, inputs};
    return best;
  }
  return best;
}

// The design u on `branch` as a four-bar in the pose of the first point, its input reading the
// crank's angle from the frame line.
std::optional<FourBarGeometry> GeometryAtFirst(const double* u, int branch) {
  const Eigen::Vector2d a0(u[0], u[1]), b0 = a0 + u[2] * Eigen::Vector2d(std::cos(u[3]), std::sin(u[3]));
  const Eigen::Vector2d a = a0 + u[4] * Eigen::Vector2d(std::cos(u[3] + u[9]), std::sin(u[3] + u[9]));
  const std::optional<Eigen::Vector2d> b = FourBarJointB(a, b0, u[5], u[6], branch);
  if (!b || !((*b - a).norm() > 0)) return std::nullopt;
  const Eigen::Vector2d along = (*b - a).normalized(), left(-along.y(), along.x());
  FourBarGeometry g;
  g.a0 = a0, g.a = a, g.b = *b, g.b0 = b0;
  g.plane_origin = a + u[7] * along + u[8] * left;
  g.plane_angle = Direction(along);
  g.input = u[9];
  return g;
}

// Drives the real mechanism through the prescribed angles in order: the sum of the squared
// distances, or why the design fails (a walk stopped short, another branch).
std::optional<double> Reanalyse(const Problem& p, const Mechanism& m, const Polished& s, std::string* why) {
  PositionSolver solver(m);
  Eigen::VectorXd q(solver.NumCoordinates());
  if (!solver.Assemble(q).ok()) {
    *why = "the mechanism does not assemble at the first point";
    return std::nullopt;
  }
  std::vector<double> offsets;
  for (double input : s.inputs) offsets.push_back(input - s.u[9]);
  std::vector<Complex> closed;
  CouplerPoints(p, s.u.data(), s.branch, offsets, &closed);
  Continuation walk(solver);
  if (!walk.Start(m.hint.input, q).ok()) {
    *why = "the walk cannot start at the first point";
    return std::nullopt;
  }
  double sse = 0;
  for (size_t i = 0; i < s.inputs.size(); ++i) {
    const WalkReport report = walk.AdvanceTo(s.inputs[i], 0.05);
    if (!report.ok()) {
      *why = fmt::format("the crank cannot be driven to point {}: {}", i + 1, report.message);
      return std::nullopt;
    }
    const Eigen::Vector2d k(solver.system().Output(0, 0, walk.q().data()), solver.system().Output(0, 1, walk.q().data()));
    if (std::abs(Complex(k.x(), k.y()) - closed[i]) > kSameBranch * p.scale) {
      *why = fmt::format("a branch defect: at point {} the mechanism stands on the other branch", i + 1);
      return std::nullopt;
    }
    sse += (k - p.request->points[i]).squaredNorm();
  }
  return sse;
}

std::optional<PathLinkage> LinkageOf(const Problem& p, const Polished& s, std::string* why) {
  const std::optional<FourBarGeometry> g = GeometryAtFirst(s.u.data(), s.branch);
  if (!g) {
    *why = "the loop does not close at the first point";
    return std::nullopt;
  }
  PathLinkage l;
  l.geometry = *g;
  l.mechanism = DesignedFourBar(*g, "path-linkage");
  const std::optional<double> sse = Reanalyse(p, l.mechanism, s, why);
  if (!sse) return std::nullopt;
  l.sse = *sse;
  l.error = std::sqrt(*sse / s.inputs.size());
  l.phi_1 = p.request->timing.empty() ? std::fmod(std::fmod(s.u[9], 2 * kPi) + 2 * kPi, 2 * kPi) : s.u[9];
  l.inputs = s.inputs;
  l.polished = true;
  l.fit = fmt::format("closed-form polish from random start {} (sse {:.6g}), re-analysed through the mechanism", s.index, s.sse);
  l.crank = s.u[4], l.coupler = s.u[5], l.rocker = s.u[6], l.frame = s.u[2];
  l.coupler_point = {s.u[7], s.u[8]};
  l.grashof = ClassifyChain(l.mechanism).grashof;
  const bool turns = l.grashof == GrashofType::kCrankRocker || l.grashof == GrashofType::kDoubleCrank;
  l.mu_min = TransmissionMinimum(l.mechanism, s.inputs.front(), turns ? s.inputs.front() + 2 * kPi : s.inputs.back());
  return l;
}

// The search's problem from a valid request; false (and *why) when the points coincide.
bool ProblemOf(const PathRequest& request, Problem* p, std::string* why) {
  p->request = &request;
  p->free = !request.Timed();
  p->repeats_first = p->free && !request.open && request.points.back() == request.points.front();
  p->same_phase.assign(request.points.size(), -1);
  if (p->repeats_first) p->same_phase.back() = 0;
  p->scale = PointsScale(request.points);
  if (!(p->scale > 0)) {
    *why = "the points coincide";
    return false;
  }
  if (!p->free) p->offsets = Offsets(request);
  Bounds(request, p->scale, &p->lower, &p->upper);
  p->limits = Limits(request.space);
  return true;
}

// The best polished starts (sorted, `admitted` of them usable) re-analysed until `top` distinct
// designs inside the space; the counts and the first failure's reason into *result.
void ReanalyseBest(const Problem& p, const std::vector<Polished>& polished, int admitted, PathResult* result) {
  const PathRequest& request = *p.request;
  std::vector<PathLinkage> kept;
  std::string failure, outside_reason;
  int failed = 0, outside = 0;
  const size_t wanted = static_cast<size_t>(request.top) * kReanalysedPerDesign;
  for (int i = 0; i < admitted && kept.size() < wanted; ++i) {
    std::string why;
    std::optional<PathLinkage> l = LinkageOf(p, polished[i], &why);
    if (!l) {
      if (failed++ == 0) failure = why;
      continue;
    }
    const std::string v = request.space.mu_min && !l->mu_min
                              ? "mu_min: the solver cannot drive it through the worked stretch"
                              : request.space.Violation({l->geometry.a0, l->geometry.b0, l->crank, l->coupler, l->rocker, l->coupler_point, l->mu_min});
    if (!v.empty()) {
      if (outside++ == 0) outside_reason = v;
      continue;
    }
    kept.push_back(std::move(*l));
    if (DistinctLinkages(kept, kSameDesign * p.scale, nullptr).size() >= static_cast<size_t>(request.top)) break;
  }
  std::stable_sort(kept.begin(), kept.end(), [](const PathLinkage& a, const PathLinkage& b) { return a.sse < b.sse; });
  result->linkages = DistinctLinkages(kept, kSameDesign * p.scale, &result->duplicates);
  if (result->linkages.size() > static_cast<size_t>(request.top)) result->linkages.resize(request.top);
  result->failed_reanalysis = failed;
  result->outside_space = outside;
  if (!result->linkages.empty()) {
    result->status = PathStatus::kOk;
    return;
  }
  result->status = PathStatus::kNoCandidate;
  result->message = failed > 0 ? fmt::format("{} polished designs failed the re-analysis through the mechanism; the best: {}", failed, failure)
                               : fmt::format("{} polished designs lie outside the design space; the best broke {}", outside, outside_reason);
}

}  // namespace

PathResult SynthesisePathGlobally(const PathRequest& request) {
  PathResult result;
  if (!request.IsValid(&result.message)) return result;
  Problem p;
  if (!ProblemOf(request, &p, &result.message)) return result;
  const int starts = request.starts > 0 ? request.starts : kTimedStarts;
  std::vector<Polished> polished(starts);
  std::atomic<int> next{0};
  RunOnThreads(request.threads, [&] {
    for (int i = next++; i < starts; i = next++) polished[i] = PolishStart(p, i);
  });
  std::sort(polished.begin(), polished.end(), [](const Polished& a, const Polished& b) { return a.sse != b.sse ? a.sse < b.sse : a.index < b.index; });
  const int admitted = static_cast<int>(std::count_if(polished.begin(), polished.end(), [](const Polished& s) { return std::isfinite(s.sse); }));
  result.starts = starts;
  result.admitted_starts = admitted;
  if (admitted == 0) {
    result.status = PathStatus::kNoCandidate;
    result.message = fmt::format("none of {} random starts ({} draws each) gives a four-bar inside the design space that {}", starts,
                                 kDrawsPerStart, p.free ? "passes the points in order" : "closes at every prescribed crank angle");
    return result;
  }
  ReanalyseBest(p, polished, admitted, &result);
  return result;
}

}  // namespace koppel
