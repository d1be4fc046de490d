#include "koppel/synthesis/path_synthesis.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/plane.hpp"
#include "koppel/synthesis/fit.hpp"

#include "path_prepolish.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/worker_threads.hpp"

#include <fmt/core.h>
#include <nanoflann.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <thread>

namespace koppel {

// The features of one kind of curve as nanoflann's dataset (rows of the entries' descriptors).
struct FeatureRows {
  const std::vector<AtlasEntry>* entries = nullptr;
  std::vector<std::uint32_t> rows;  // entry index of each row
  size_t kdtree_get_point_count() const { return rows.size(); }
  float kdtree_get_pt(size_t row, size_t dim) const { return (*entries)[rows[row]].descriptor[dim]; }
  template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
};
using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, FeatureRows>, FeatureRows, kAtlasFeatures, std::uint32_t>;

struct AtlasIndex::Impl {
  std::vector<AtlasEntry> entries;
  FeatureRows closed, open;
  std::unique_ptr<Tree> closed_tree, open_tree;
};

AtlasIndex::AtlasIndex(std::vector<AtlasEntry> entries) : impl_(std::make_unique<Impl>()) {
  impl_->entries = std::move(entries);
  impl_->closed.entries = impl_->open.entries = &impl_->entries;
  for (std::uint32_t i = 0; i < impl_->entries.size(); ++i) (impl_->entries[i].closed ? impl_->closed : impl_->open).rows.push_back(i);
  // leaves of 16: the usual balance of tree depth against brute force at the leaves
  const nanoflann::KDTreeSingleIndexAdaptorParams params(16);
  if (!impl_->closed.rows.empty()) impl_->closed_tree = std::make_unique<Tree>(kAtlasFeatures, impl_->closed, params);
  if (!impl_->open.rows.empty()) impl_->open_tree = std::make_unique<Tree>(kAtlasFeatures, impl_->open, params);
}

AtlasIndex::~AtlasIndex() = default;

const std::vector<AtlasEntry>& AtlasIndex::entries() const { return impl_->entries; }

std::vector<std::pair<std::uint32_t, float>> AtlasIndex::Nearest(const std::array<float, kAtlasFeatures>& features, bool closed, int k) const {
  const Tree* tree = closed ? impl_->closed_tree.get() : impl_->open_tree.get();
  const FeatureRows& rows = closed ? impl_->closed : impl_->open;
  if (!tree || k < 1) return {};
  std::vector<std::uint32_t> found(k);
  std::vector<float> distance(k);
  const size_t n = tree->knnSearch(features.data(), k, found.data(), distance.data());
  std::vector<std::pair<std::uint32_t, float>> result;
  for (size_t i = 0; i < n; ++i) result.push_back({rows.rows[found[i]], distance[i]});
  return result;
}

namespace {

using Complex = std::complex<double>;

// Samples of an atlas curve for placing a candidate on the points.
constexpr int kCandidateSamples = 720;
// Rounds of re-timing in the pre-polish (each a closed-form fit of a few milliseconds).
constexpr int kRetimings = 4;
// A polished design within this of the points (times the points' scale) fits them exactly: the
// kernel's Newton tolerance is 1e-13 L.
constexpr double kExactFit = 1e-12;
// With a design space, the candidates inside it are looked for among the kMaxSpacePool nearest
// curves, or this many times the candidates wanted when that is more (laying 20 000 curves is
// about 3 s on two cores): the nearest 2 000 of 200 000 curves held no linkage of the
// literature's ellipse within lengths [0, 80] that stayed inside once pre-polished.
constexpr int kSpacePoolFactor = 20;
constexpr int kMaxSpacePool = 20'000;

// One way of reading the points: mirrored or not, with its descriptor.
struct Reading {
  bool mirror = false;
  CurveDescriptor descriptor;
};

// Which atlas entry, read which way.
struct Candidate {
  std::uint32_t entry = 0;
  float distance = 0;
  Reading reading;
};



// The four-bar of the fit's unknowns: A0, B0, a, b, c, K (in the coupler frame), at crank angle
// phi on `branch`.
struct Placement {
  double phi = 0;
  int branch = 1;
  std::optional<FourBarGeometry> Geometry(const std::vector<double>& v) const {
    const Eigen::Vector2d a0(v[0], v[1]), b0(v[2], v[3]);
    const Eigen::Vector2d a = a0 + v[4] * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    const std::optional<Eigen::Vector2d> b = FourBarJointB(a, b0, v[5], v[6], branch);
    if (!b || !((*b - a).norm() > 0) || !(v[4] > 0)) return std::nullopt;
    const Eigen::Vector2d u = (*b - a).normalized(), left(-u.y(), u.x());
    FourBarGeometry g;
    g.a0 = a0;
    g.a = a;
    g.b = *b;
    g.b0 = b0;
    g.plane_origin = a + v[7] * u + v[8] * left;
    g.plane_angle = Direction(u);
    return g;
  }
};

// A candidate laid onto the points, pre-polished in closed form.
struct Placed {
  Placement placement;
  std::vector<double> unknowns, inputs;
  double error = std::numeric_limits<double>::infinity();
};

// The design space as bounds on the fit's unknowns (A0, B0, the three moving links); the frame's
// length and the ratio are checked on the result. Empty without a space.
std::vector<std::pair<double, double>> UnknownBounds(const DesignSpace& space) {
  if (space.Empty()) return {};
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::pair<double, double>> b(9, {-inf, inf});
  for (int j : {0, 2}) if (space.pivots_x) b[j] = *space.pivots_x;
  for (int j : {1, 3}) if (space.pivots_y) b[j] = *space.pivots_y;
  for (int j : {4, 5, 6}) if (space.lengths) b[j] = *space.lengths;
  for (int j : {7, 8}) if (space.coupler_point) b[j] = *space.coupler_point;
  return b;
}

// The timing is where free-timing fits get stuck: gives each point the crank angle of its nearest
// point on the polished curve and polishes again, while that helps.
void RetimePlacement(const PathRequest& request, Placed* out) {
  for (int round = 0; round < kRetimings; ++round) {
    std::vector<double> unknowns = out->unknowns, inputs = out->inputs;
    for (size_t i = 0; i < inputs.size(); ++i) {
      double best = std::numeric_limits<double>::infinity();
      for (int j = 0; j < kCandidateSamples; ++j) {
        const double phi = out->placement.phi + 2 * kPi * j / kCandidateSamples - kPi;
        Eigen::Vector2d p;
        if (!CouplerPointAt(unknowns, out->placement.branch, phi, &p)) continue;
        if ((p - request.points[i]).squaredNorm() < best) {
          best = (p - request.points[i]).squaredNorm();
          inputs[i] = phi;
        }
      }
    }
    const std::vector<std::pair<double, double>> bounds = UnknownBounds(request.space);
    const double error = PrePolish(request.points, out->placement.branch, &unknowns, &inputs, bounds.empty() ? nullptr : &bounds);
    if (!(error < 0.99 * out->error)) break;
    out->error = error;
    out->unknowns = unknowns;
    out->inputs = inputs;
  }
}

// An atlas curve and the similarity that lays it onto the points (then the mirror, if read so).
struct Laid {
  AtlasCurve curve;
  CurveDescriptor own;
  Complex rho;
  const Candidate* c = nullptr;
  Eigen::Vector2d operator()(const Eigen::Vector2d& p) const {
    const CurveDescriptor& q = c->reading.descriptor;
    const Complex z = q.centre + rho * (Complex(p.x(), p.y()) - own.centre);
    return c->reading.mirror ? Eigen::Vector2d(z.real(), -z.imag()) : Eigen::Vector2d(z.real(), z.imag());
  }
  double scale() const { return std::abs(rho); }
};

std::optional<Laid> Lay(const AtlasIndex& atlas, const Candidate& c) {
  Laid laid;
  laid.c = &c;
  if (!TraceAtlasCurve(atlas.entries()[c.entry], kCandidateSamples, &laid.curve) || !DescribeCurve(laid.curve.coupler_point, &laid.own))
    return std::nullopt;
  const CurveDescriptor& q = c.reading.descriptor;
  laid.rho = std::polar(q.scale / laid.own.scale, laid.own.turn - q.turn);
  return laid;
}

// The design space's verdict on a candidate as the similarity lays it, before any polish (which
// moves it little): empty inside, else the constraint it breaks; "no curve" when it cannot be laid.
std::string SpaceViolation(const AtlasIndex& atlas, const Candidate& c, const DesignSpace& space) {
  const std::optional<Laid> laid = Lay(atlas, c);
  if (!laid) return "no curve";
  const AtlasEntry& e = atlas.entries()[c.entry];
  const double k = laid->scale();
  return space.Violation({(*laid)({0, 0}), (*laid)({1, 0}), k * e.crank, k * e.coupler, k * e.rocker, std::nullopt, std::nullopt});
}

std::optional<Placed> Place(const AtlasIndex& atlas, const Candidate& c, const PathRequest& request) {
  const std::optional<Laid> laid = Lay(atlas, c);
  if (!laid) return std::nullopt;
  const AtlasCurve& curve = laid->curve;
  const Laid& place = *laid;
  const Eigen::Vector2d a0 = place({0, 0}), b0 = place({1, 0});
  std::vector<Eigen::Vector2d> k(kCandidateSamples);
  for (int i = 0; i < kCandidateSamples; ++i) k[i] = place(curve.coupler_point[i]);
  auto nearest = [&](const Eigen::Vector2d& p) {
    int best = 0;
    for (int i = 1; i < kCandidateSamples; ++i)
      if ((k[i] - p).squaredNorm() < (k[best] - p).squaredNorm()) best = i;
    return best;
  };
  // assembled where the first point is (closed), or mid-way between the limit positions (open)
  const int hint = request.open ? kCandidateSamples / 4 : nearest(request.points[0]);
  const Eigen::Vector2d a = place(curve.a[hint]), b = place(curve.b[hint]), kh = k[hint];
  const Eigen::Vector2d u = (b - a).normalized(), left(-u.y(), u.x());
  Placed out;
  out.placement.phi = Direction(a - a0);
  out.placement.branch = FourBarBranch(a, b, b0) >= 0 ? 1 : -1;
  out.unknowns = {a0.x(), a0.y(), b0.x(), b0.y(), (a - a0).norm(), (b - a).norm(), (b - b0).norm(), (kh - a).dot(u), (kh - a).dot(left)};
  for (const Eigen::Vector2d& p : request.points) {
    const double phi = Direction(place(curve.a[nearest(p)]) - a0);
    out.inputs.push_back(out.placement.phi + AngleDifference(phi, out.placement.phi));
  }
  // a candidate laid outside the design space is not pre-polished: its start breaks the bounds
  const std::vector<std::pair<double, double>> bounds = UnknownBounds(request.space);
  if (!request.space.Violation({{out.unknowns[0], out.unknowns[1]}, {out.unknowns[2], out.unknowns[3]}, out.unknowns[4], out.unknowns[5],
                                out.unknowns[6], Eigen::Vector2d(out.unknowns[7], out.unknowns[8]), std::nullopt}).empty())
    return std::nullopt;
  out.error = PrePolish(request.points, out.placement.branch, &out.unknowns, &out.inputs, bounds.empty() ? nullptr : &bounds);
  if (!std::isfinite(out.error)) return std::nullopt;
  RetimePlacement(request, &out);
  // the crank angles stay within a turn of the assembly's (the fit walks there by continuation)
  for (double& phi : out.inputs) phi = out.placement.phi + AngleDifference(phi, out.placement.phi);
  return out;
}

// The final polish by the fit through the real mechanism, from the pre-polished start.
// The fit's unknowns from the pre-polished start: the link lengths kept positive, and within the
// design space's bounds where one is given (the start lies inside them).
std::vector<FitParameter> PolishParameters(const Placed& placed, const PathRequest& request, double scale) {
  std::vector<FitParameter> parameters;
  const char* names[] = {"A0_x", "A0_y", "B0_x", "B0_y", "crank", "coupler", "rocker", "K_along", "K_left"};
  const std::vector<std::pair<double, double>> bounds = UnknownBounds(request.space);
  for (int j = 0; j < 9; ++j) {
    FitParameter p{names[j], placed.unknowns[j]};
    if (j >= 4 && j <= 6) p.lower = std::min(1e-6 * scale, p.start);
    if (static_cast<size_t>(j) < bounds.size()) {
      p.lower = std::max(p.lower, bounds[j].first);
      p.upper = std::min(p.upper, bounds[j].second);
    }
    parameters.push_back(p);
  }
  return parameters;
}

std::optional<PathLinkage> Polish(const Placed& placed, const Candidate& c, const AtlasEntry& entry, const PathRequest& request, double scale) {
  const Placement placement = placed.placement;
  const std::vector<FitParameter> parameters = PolishParameters(placed, request, scale);
  std::vector<FitTarget> targets;
  for (size_t i = 0; i < request.points.size(); ++i) {
    FitTarget t;
    t.name = fmt::format("point {}", i + 1);
    t.output = 0;
    t.point = true;
    t.position = request.points[i];
    t.input_free = true;
    t.input = placed.inputs[i];
    targets.push_back(t);
  }
  const MechanismBuilder builder = [placement](const std::vector<double>& v) -> Expected<Mechanism> {
    const std::optional<FourBarGeometry> g = placement.Geometry(v);
    if (!g) return Expected<Mechanism>::Error("the loop does not close at the assembly's crank angle");
    return DesignedFourBar(*g, "path-linkage");
  };
  FitOptions options;
  options.starts = 1;
  options.threads = 1;
  options.length_tolerance = 1e-9 * scale;  // only the report's verdict: the error is what counts
  const FitReport fit = Fit(builder, parameters, targets, options);
  if (fit.values.empty()) return std::nullopt;
  // the pose where K passes nearest the first point (the fit moved its crank angle there on the
  // assembly's branch): the same pose for the same design, whichever candidate it came from
  Placement at_first = placement;
  if (!fit.targets.empty()) at_first.phi = fit.targets.front().input;
  std::optional<FourBarGeometry> g = at_first.Geometry(fit.values);
  if (!g) g = placement.Geometry(fit.values);
  if (!g) return std::nullopt;
  PathLinkage l;
  double sum = 0;
  for (const FitTargetResult& t : fit.targets) sum += t.residual * t.residual;
  l.error = std::sqrt(sum / fit.targets.size());
  l.sse = sum;
  l.phi_1 = AngleDifference(at_first.phi, Direction(g->b0 - g->a0));
  l.descriptor_distance = std::sqrt(c.distance);
  l.source = entry;
  l.polished = true;
  l.fit = fit.Brief();
  l.geometry = *g;
  l.mechanism = DesignedFourBar(*g, "path-linkage");
  l.crank = fit.values[4];
  l.coupler = fit.values[5];
  l.rocker = fit.values[6];
  l.frame = (g->b0 - g->a0).norm();
  l.coupler_point = {fit.values[7], fit.values[8]};
  l.grashof = ClassifyChain(l.mechanism).grashof;
  // the worked stretch: a full turn for a crank, else the fit's crank angles from least to most
  const bool turns = l.grashof == GrashofType::kCrankRocker || l.grashof == GrashofType::kDoubleCrank;
  double low = at_first.phi, high = at_first.phi;
  for (const FitTargetResult& t : fit.targets) low = std::min(low, t.input), high = std::max(high, t.input);
  l.mu_min = turns ? TransmissionMinimum(l.mechanism, at_first.phi, at_first.phi + 2 * kPi) : TransmissionMinimum(l.mechanism, low, high);
  return l;
}

// Runs job(i) for i < n on `threads` threads.
void OnEveryCore(size_t n, int threads_wanted, const std::function<void(size_t)>& job) {
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i = next++; i < n; i = next++) job(i);
  };
  RunOnThreads(threads_wanted, work);
}

// The candidates in `order` polished from `next` on, `count` of them, on every core.
void PolishBatch(const AtlasIndex& atlas, const PathRequest& request, double scale, const std::vector<Candidate>& candidates,
                 const std::vector<std::optional<Placed>>& placed, const std::vector<size_t>& order, size_t next, size_t count,
                 std::vector<PathLinkage>* polished) {
  std::vector<std::optional<PathLinkage>> batch(count);
  OnEveryCore(count, request.threads, [&](size_t i) {
    const Candidate& c = candidates[order[next + i]];
    batch[i] = Polish(*placed[order[next + i]], c, atlas.entries()[c.entry], request, scale);
  });
  for (auto& l : batch)
    if (l) polished->push_back(std::move(*l));
}

}  // namespace

FourBarPose PathLinkage::Pose() const { return {geometry.a0, geometry.a, geometry.b, geometry.b0, geometry.plane_origin}; }

bool SameFourBar(const FourBarPose& x, const FourBarPose& y, double tolerance) {
  auto close = [&](const Eigen::Vector2d& p, const Eigen::Vector2d& q) { return (p - q).norm() <= tolerance; };
  if (!close(x.k, y.k)) return false;
  const bool in_order = close(x.a0, y.a0) && close(x.a, y.a) && close(x.b, y.b) && close(x.b0, y.b0);
  const bool reversed = close(x.a0, y.b0) && close(x.a, y.b) && close(x.b, y.a) && close(x.b0, y.a0);
  return in_order || reversed;
}

std::vector<PathLinkage> DistinctLinkages(std::vector<PathLinkage> by_error, double tolerance, int* dropped) {
  std::vector<PathLinkage> kept;
  int repeats = 0;
  for (PathLinkage& l : by_error) {
    const FourBarPose pose = l.Pose();
    const bool repeat = std::any_of(kept.begin(), kept.end(), [&](const PathLinkage& k) { return SameFourBar(pose, k.Pose(), tolerance); });
    if (repeat) {
      ++repeats;
      continue;
    }
    l.cognate_of = -1;
    for (size_t i = 0; i < kept.size() && l.cognate_of < 0; ++i)
      if (const auto cognates = CognatePoses(kept[i].Pose()))
        for (const FourBarPose& c : *cognates)
          if (SameFourBar(pose, c, tolerance)) l.cognate_of = static_cast<int>(i);
    kept.push_back(std::move(l));
  }
  if (dropped) *dropped = repeats;
  return kept;
}

const char* ToString(PathStatus status) {
  switch (status) {
    case PathStatus::kOk: return "ok";
    case PathStatus::kNoCandidate: return "no candidate";
    case PathStatus::kInvalidRequest: return "invalid request";
  }
  return "?";
}

namespace {

// Empty when the request's timing can be run; else why not.
std::string TimingProblem(const PathRequest& r) {
  if (!r.timing.empty() && r.timing_step) return "the timing is prescribed twice: a phi column and a timing step";
  if (r.Timed() && r.open) return "open: a prescribed timing says where each point is reached; open or closed changes nothing";
  if (r.starts < 0 || r.starts > kMaxTimedStarts) return fmt::format("starts must be 0 (the default, {}) to {}", kTimedStarts, kMaxTimedStarts);
  if (!r.timing.empty()) {
    if (r.timing.size() != r.points.size()) return fmt::format("{} crank angles for {} points", r.timing.size(), r.points.size());
    for (size_t i = 0; i < r.timing.size(); ++i)
      if (!std::isfinite(r.timing[i])) return fmt::format("the crank angle of point {} is not a finite number", i + 1);
    const double sense = r.timing[1] > r.timing[0] ? 1 : -1;
    for (size_t i = 1; i < r.timing.size(); ++i)
      if (!(sense * (r.timing[i] - r.timing[i - 1]) > 0))
        return fmt::format("the crank angles must rise (or fall) from point to point: point {} at {:.6g} deg after {:.6g} deg", i + 1,
                           RadToDeg(r.timing[i]), RadToDeg(r.timing[i - 1]));
    if (std::abs(r.timing.back() - r.timing.front()) >= 2 * kPi)
      return fmt::format("the crank angles span {:.6g} deg: less than a turn, each point's angle reached once", RadToDeg(std::abs(r.timing.back() - r.timing.front())));
  }
  if (r.timing_step) {
    if (!std::isfinite(*r.timing_step) || *r.timing_step == 0) return "the timing step must be a finite, non-zero angle";
    if (std::abs(*r.timing_step) * (r.points.size() - 1) >= 2 * kPi)
      return fmt::format("a timing step of {:.6g} deg over {} points spans a turn or more: each point's angle is reached once",
                         RadToDeg(*r.timing_step), r.points.size());
  }
  return "";
}

}  // namespace

bool PathRequest::IsValid(std::string* why) const {
  std::string problem;
  if (points.size() < 4) problem = "at least four points";
  else if (points.size() > 10'000) problem = "at most 10000 points";
  else if (top < 1 || top > 1000) problem = "top must be between 1 and 1000";
  else if (candidates < 0 || candidates > 10'000) problem = "candidates must be between 0 and 10000";
  else if (std::string space_problem; !space.IsValid(&space_problem)) problem = "design space: " + space_problem;
  // the work, estimated before it starts: each of the top linkages is fitted over every point
  else if (static_cast<long>(top) * static_cast<long>(points.size()) > kMaxPathPointFits)
    problem = "top " + std::to_string(top) + " linkages fitted over " + std::to_string(points.size()) + " points ask for " +
              std::to_string(static_cast<long>(top) * static_cast<long>(points.size())) + " point fits, more than the limit of " +
              std::to_string(kMaxPathPointFits) + " (kMaxPathPointFits, about 9 ms each): a smaller top (--top)";
  else if (threads < 0 || threads > kMaxThreads)
    problem = "threads must be 0 (one per core) to " + std::to_string(kMaxThreads) + " (kMaxThreads)";
  for (const Eigen::Vector2d& p : points)
    if (problem.empty() && !p.allFinite()) problem = "every point must be finite";
  if (problem.empty()) problem = TimingProblem(*this);
  if (why) *why = problem;
  return problem.empty();
}

namespace {

// The readings of the points: mirrored or not, traversed either way, both sides of the ambiguity.
std::vector<Reading> ReadingsOfPathPoints(const PathRequest& request) {
  std::vector<Reading> readings;
  for (bool mirror : {false, true}) {
    for (bool reverse : {false, true}) {
      std::vector<Eigen::Vector2d> path = request.points;
      if (mirror)
        for (auto& p : path) p.y() = -p.y();
      if (reverse) std::reverse(path.begin(), path.end());
      if (request.open)  // there and back, like the atlas's arcs
        for (size_t i = request.points.size() - 1; i-- > 1;) path.push_back(path[i]);
      CurveDescriptor d;
      if (!DescribeCurve(path, &d)) continue;
      readings.push_back({mirror, d});
      readings.push_back({mirror, OtherBranchOfAmbiguity(d)});
    }
  }
  return readings;
}

// The `wanted` atlas entries nearest to any reading (each with its best reading), nearest first.
std::vector<Candidate> NearestAtlasCandidates(const AtlasIndex& atlas, const PathRequest& request,
                                              const std::vector<Reading>& readings, int wanted) {
  std::map<std::uint32_t, Candidate> best;
  for (const Reading& r : readings) {
    std::array<float, kAtlasFeatures> f;
    for (int i = 0; i < kAtlasFeatures; ++i) f[i] = static_cast<float>(r.descriptor.features[i]);
    for (const auto& [entry, distance] : atlas.Nearest(f, !request.open, wanted)) {
      auto it = best.find(entry);
      if (it == best.end() || distance < it->second.distance) best[entry] = {entry, distance, r};
    }
  }
  std::vector<Candidate> candidates;
  for (const auto& [entry, c] : best) candidates.push_back(c);
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
  if (candidates.size() > static_cast<size_t>(wanted)) candidates.resize(wanted);
  return candidates;
}

// The `wanted` nearest curves whose linkage, laid onto the points, lies inside the design space,
// looked for among many more (laying a curve is a trace, some 50 us; pre-polishing one is 14 ms);
// *broke: the constraint the nearest one outside broke.
std::vector<Candidate> CandidatesInSpace(const AtlasIndex& atlas, const PathRequest& request, const std::vector<Reading>& readings,
                                         int wanted, std::string* broke) {
  const std::vector<Candidate> pool = NearestAtlasCandidates(atlas, request, readings, std::max(kMaxSpacePool, kSpacePoolFactor * wanted));
  std::vector<std::string> verdicts(pool.size());
  OnEveryCore(pool.size(), request.threads, [&](size_t i) { verdicts[i] = SpaceViolation(atlas, pool[i], request.space); });
  std::vector<Candidate> inside;
  for (size_t i = 0; i < pool.size() && inside.size() < static_cast<size_t>(wanted); ++i) {
    if (verdicts[i].empty()) inside.push_back(pool[i]);
    else if (broke->empty() && verdicts[i] != "no curve") *broke = verdicts[i];
  }
  return inside;
}

// The pre-polished candidates to polish, best first. One outside the design space (its frame, its
// ratio or its input: the bounds kept the rest) is not polished; the constraint the best of those
// broke goes to *broke, should nothing be left. Exact fits in closed form (errors at roundoff)
// keep the atlas's order, nearest first: their errors' order is roundoff, which any change of
// the kernel's arithmetic reshuffles.
std::vector<size_t> PolishOrder(const std::vector<std::optional<Placed>>& placed, const DesignSpace& space, double scale, std::string* broke) {
  std::vector<size_t> order;
  double best_broken = 0;
  for (size_t i = 0; i < placed.size(); ++i) {
    if (!placed[i]) continue;
    const std::vector<double>& v = placed[i]->unknowns;
    const std::string violation = space.Violation({{v[0], v[1]}, {v[2], v[3]}, v[4], v[5], v[6], Eigen::Vector2d(v[7], v[8]), std::nullopt});
    if (violation.empty()) {
      order.push_back(i);
    } else if (broke->empty() || placed[i]->error < best_broken) {
      *broke = violation;
      best_broken = placed[i]->error;
    }
  }
  const auto rank = [&](size_t i) { return placed[i]->error < kExactFit * scale ? 0.0 : placed[i]->error; };
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return rank(a) < rank(b); });
  return order;
}

// The polish may carry a linkage out of the design space: dropped, never returned.
void DropOutsideSpace(const DesignSpace& space, std::vector<PathLinkage>* polished, std::string* broke) {
  polished->erase(std::remove_if(polished->begin(), polished->end(), [&](const PathLinkage& l) {
                    const std::string violation =
                        space.mu_min && !l.mu_min ? "mu_min: the solver cannot drive it through the worked stretch"
                                                  : space.Violation({l.geometry.a0, l.geometry.b0, l.crank, l.coupler, l.rocker, l.coupler_point, l.mu_min});
                    if (!violation.empty() && broke->empty()) *broke = violation + " (after the polish)";
                    return !violation.empty();
                  }),
                  polished->end());
}

// Empty when the atlas can search the request; else why not (a timing, a fixed A0 or frame angle).
std::string AtlasRequestProblem(const PathRequest& request) {
  if (request.Timed()) return "a prescribed timing is searched without an atlas (SynthesisePathGlobally)";
  if (const std::string why = request.space.Unsupported("the atlas's search", true, false); !why.empty())
    return "design space: " + why + "; the atlas lays its curves where they fit best";
  return "";
}

}  // namespace

PathResult SynthesisePath(const AtlasIndex& atlas, const PathRequest& request) {
  PathResult result;
  if (!request.IsValid(&result.message) || !(result.message = AtlasRequestProblem(request)).empty()) return result;
  const double scale = PointsScale(request.points);
  const std::vector<Reading> readings = scale > 0 ? ReadingsOfPathPoints(request) : std::vector<Reading>{};
  if (readings.empty()) {
    result.message = scale > 0 ? "the points have no extent along a path" : "the points coincide";
    return result;
  }
  const int wanted = request.candidates > 0 ? request.candidates : std::max(100, 10 * request.top);
  std::string broke;  // the constraint the nearest candidate outside the design space broke
  const std::vector<Candidate> candidates = request.space.Empty() ? NearestAtlasCandidates(atlas, request, readings, wanted)
                                                                  : CandidatesInSpace(atlas, request, readings, wanted, &broke);
  if (candidates.empty() && !request.space.Empty()) {
    result.status = PathStatus::kNoCandidate;
    result.message = fmt::format("none of the {} nearest atlas curves gives a linkage inside the design space; the nearest broke {}",
                                 std::max(kMaxSpacePool, kSpacePoolFactor * wanted), broke.empty() ? "nothing (no curve could be laid)" : broke);
    return result;
  }
  // every candidate pre-polished in closed form; the best `top` polished through the mechanism
  std::vector<std::optional<Placed>> placed(candidates.size());
  OnEveryCore(candidates.size(), request.threads, [&](size_t i) { placed[i] = Place(atlas, candidates[i], request); });
  const std::vector<size_t> order = PolishOrder(placed, request.space, scale, &broke);
  // the best `top` polished through the mechanism; where some repeat a better design, the next
  // ones too (twice as many as are missing, to need few rounds), until `top` distinct designs
  const size_t top = static_cast<size_t>(request.top);
  std::vector<PathLinkage> polished;
  for (size_t next = 0, missing = top; missing > 0 && next < order.size();) {
    const size_t count = std::min(order.size() - next, next == 0 ? top : 2 * missing);
    PolishBatch(atlas, request, scale, candidates, placed, order, next, count, &polished);
    next += count;
    DropOutsideSpace(request.space, &polished, &broke);
    // exact fits (errors at roundoff) keep the order of their atlas candidates: their errors'
    // order is roundoff, which any change of the kernel's arithmetic reshuffles
    const auto rank_error = [&](const PathLinkage& l) { return l.error < kExactFit * scale ? 0.0 : l.error; };
    std::stable_sort(polished.begin(), polished.end(),
                     [&](const PathLinkage& a, const PathLinkage& b) { return rank_error(a) < rank_error(b); });
    result.linkages = DistinctLinkages(polished, kSameDesign * scale, &result.duplicates);
    missing = top - std::min(top, result.linkages.size());
  }
  if (result.linkages.size() > top) result.linkages.resize(top);
  if (result.linkages.empty()) {
    result.status = PathStatus::kNoCandidate;
    result.message = !broke.empty() ? fmt::format("none of the {} nearest atlas curves gives a linkage inside the design space; the "
                                                  "best broke {}", candidates.size(), broke)
                                    : fmt::format("none of the {} nearest atlas curves could be polished onto the points", candidates.size());
    return result;
  }
  result.status = PathStatus::kOk;
  return result;
}

}  // namespace koppel
