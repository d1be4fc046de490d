// Path generation from an atlas (atlas.hpp): the four-bars whose coupler curve passes nearest a
// set of points. The points' descriptor (their polygon, closed; or for an open target traced
// there and back) is looked up among the atlas's curves of the same kind (closed curves of
// cranks, or arcs of rockers) by nearest neighbours (nanoflann's k-d tree), trying the descriptor
// ambiguity, the reversed traversal and the mirror image. Each candidate is moved onto the points
// by the similarity the descriptors give, pre-polished in closed form (Ceres on the triangle
// A B B0, milliseconds), and the best `top` are polished by the least-squares fit (fit.hpp)
// through the real mechanism: every point a point target of the coupler point with its crank
// angle free (the timing free), the pivots, link lengths and the coupler point free. The error of
// a linkage is the RMS of the points' distances from its polished coupler curve (the fit's
// residuals at the optimal crank angles), in the points' unit.
//
// The result holds distinct designs: candidates from different atlas curves often polish to the
// same four-bar. Two linkages are the same design when, in the pose where each one's coupler
// point passes the first point, their joints A0 A B B0 coincide (or B0 B A A0: the same links
// driven at the other pivot) and so do their coupler points, within kSameDesign of the points'
// size (their largest distance from their centroid); a mirror image is the same design only where its joints coincide so. The worse of two is
// dropped and the next candidates polished, until `top` distinct designs or the candidates run
// out. A linkage whose joints are those of a Roberts cognate of a better one (the same coupler
// curve from another four-bar, cognates.hpp) is kept and named: cognate_of.
#pragma once

#include "koppel/synthesis/design_space.hpp"

#include "koppel/analysis/classification.hpp"
#include "koppel/core/limits.hpp"  // kMaxTimedStarts
#include "koppel/core/mechanism.hpp"
#include "koppel/synthesis/atlas.hpp"
#include "koppel/synthesis/cognates.hpp"
#include "koppel/synthesis/four_bar_design.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace koppel {

// The atlas's curves in two k-d trees (closed, open). Immutable once built: queries from any thread.
class AtlasIndex {
 public:
  explicit AtlasIndex(std::vector<AtlasEntry> entries);
  ~AtlasIndex();
  AtlasIndex(const AtlasIndex&) = delete;
  AtlasIndex& operator=(const AtlasIndex&) = delete;

  const std::vector<AtlasEntry>& entries() const;
  // The k entries of the given kind nearest `features` (squared distances ascending).
  std::vector<std::pair<std::uint32_t, float>> Nearest(const std::array<float, kAtlasFeatures>& features, bool closed, int k) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

struct PathRequest {
  std::vector<Eigen::Vector2d> points;  // in order along the path
  bool open = false;                    // an open stretch of a path (matched against rocker arcs)
  int top = 10;                         // linkages returned
  int candidates = 0;                   // atlas candidates pre-polished in closed form (0: max(100, 10 top))
  int threads = 0;                      // polishing threads (0: one per core)
  // Candidates and polished linkages outside it are dropped (never returned); when none is left,
  // the message names the constraint the best one broke.
  DesignSpace space;
  // Prescribed timing (global_path_synthesis.cpp; no atlas): each point's crank angle from the
  // frame line A0 -> B0 (radians, counter-clockwise positive, strictly monotonic, spanning less
  // than a turn), or equal increments from a free first angle. Neither: the timing is free.
  std::vector<double> timing;
  std::optional<double> timing_step;
  int starts = 0;          // the global search's random starts (0: kTimedStarts)
  std::uint64_t seed = 1;  // of the global search's starts: the same seed, the same designs
  bool Timed() const { return !timing.empty() || timing_step.has_value(); }
  bool IsValid(std::string* why) const;
};

// The global search's starts by default (about 7 s on two cores for the literature's 18-point
// closed curve with 20 deg steps, tests/data/benchmarks).
inline constexpr int kTimedStarts = 4000;

struct PathLinkage {
  double error = 0;               // RMS distance of the points from the polished curve
  double sse = 0;                 // the sum of the squared distances (the literature's objective)
  double phi_1 = 0;               // the crank's angle from the frame line A0 -> B0 where K is nearest the first point
  std::vector<double> inputs;     // the global search's: each point's crank angle from the frame line, in the order driven
  // the smallest transmission angle over the worked stretch: a full turn for a crank, else from
  // the first point to the last [rad]; nullopt where the solver cannot drive through it
  std::optional<double> mu_min;
  double descriptor_distance = 0; // of the atlas candidate from the points' descriptor
  AtlasEntry source;              // the atlas curve it came from
  bool polished = false;          // the fit ran (else the candidate as the similarity put it)
  std::string fit;                // the fit's Brief()
  FourBarGeometry geometry;       // pivots, joints and the coupler point (plane origin) where K passes nearest the first point
  double crank = 0, coupler = 0, rocker = 0, frame = 0;
  Eigen::Vector2d coupler_point = Eigen::Vector2d::Zero();  // K in the coupler's frame: along A -> B, and left of it
  GrashofType grashof = GrashofType::kNotApplicable;
  Mechanism mechanism;            // four_bar_design.hpp: output "P" is the coupler point
  int cognate_of = -1;            // index in PathResult::linkages of the better linkage it is a cognate of; -1: none
  FourBarPose Pose() const;       // `geometry` with K = its plane origin
};

// Joints and coupler points this close, relative to the points' size, are the same design.
// Measured on 36 noisy points of a crank-rocker's curve (tests/solver/synthesis): one design
// polished from different atlas curves agrees to 2.5e-6 of the points' size; the nearest two
// distinct local optima differ by 7e-3. 1e-4 lies between them with a margin of 40 both ways.
inline constexpr double kSameDesign = 1e-4;

// The same design: the poses' joints coincide in loop order or reversed, and so do their K.
bool SameFourBar(const FourBarPose& x, const FourBarPose& y, double tolerance);

// `by_error` (best first) without the linkages that repeat a better one, the others' cognate_of
// set; *dropped counts the repeats. tolerance in the points' unit.
std::vector<PathLinkage> DistinctLinkages(std::vector<PathLinkage> by_error, double tolerance, int* dropped);

enum class PathStatus { kOk, kNoCandidate, kInvalidRequest };
const char* ToString(PathStatus status);

struct PathResult {
  PathStatus status = PathStatus::kInvalidRequest;
  std::string message;
  std::vector<PathLinkage> linkages;  // distinct designs, by error, smallest first
  int duplicates = 0;                 // polished linkages dropped as repeats of a better one
  // the timed search: its starts, those that found an admissible four-bar, and polished designs
  // dropped by the re-analysis through the mechanism (a branch or order defect)
  int starts = 0, admitted_starts = 0, failed_reanalysis = 0;
  int outside_space = 0;  // polished designs outside the space its bounds could not keep (mu_min over the stretch)
  bool ok() const { return status == PathStatus::kOk; }
};

// Untimed requests (the timing free).
PathResult SynthesisePath(const AtlasIndex& atlas, const PathRequest& request);

// A global search without an atlas, the timing prescribed or free. Random four-bars inside the
// design space, each laid onto the points by the similarity its bounds leave free (with the
// timing free: at guessed angles spread over a turn, closed, or part of one, open) and polished in
// closed form within the space's bounds (Ceres), both assembly branches; with the timing free
// every point's crank angle is an unknown, and a polish that passes the points out of order (an
// order defect) is dropped. A closed path whose last point repeats its first reaches it a whole
// turn later. The best distinct designs are re-analysed by driving the real mechanism through
// the angles in order (a walk that stops short, or a coupler point away from the closed form's,
// is a branch defect: dropped). sse and error are the re-analysis's.
PathResult SynthesisePathGlobally(const PathRequest& request);

}  // namespace koppel
