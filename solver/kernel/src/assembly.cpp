#include "koppel/solver/assembly.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/structure.hpp"
#include "koppel/solver/singular.hpp"

#include <Eigen/SVD>

#include <cmath>
#include <cstdio>
#include <random>

namespace koppel {
namespace {

// Singular values of J_c S below this fraction of the largest count as zero for the rank: far
// above roundoff (1e-16), far below the smallest singular value of a regular pose of a real
// mechanism (1e-3 and up).
constexpr double kRankThreshold = 1e-9;
// A joint's share of the left null space below this fraction of the largest counts as zero.
constexpr double kRedundantJointShare = 1e-6;

bool Regular(PositionSolver& solver, const Eigen::VectorXd& q) {
  return solver.PivotRatio() > kRegularPivotRatio || ReciprocalCondition(solver.system(), q) >= kSingularRowRcond;
}

std::string JointList(const Mechanism& m, const std::vector<int>& joints) {
  std::string names;
  for (int j : joints) names += (names.empty() ? "" : ", ") + m.joints[j].name;
  return names;
}

// A P drive's search: +-kSlideSpan L around the hint's input in steps of L / kSlideProbesPerL.
constexpr double kSlideSpan = 4.0;
constexpr int kSlideProbesPerL = 8;
// The seed of the search's random guesses: fixed, so that every run starts where the last did.
constexpr unsigned kSearchSeed = 1;

// Probe inputs of the search, nearest the hint's input first: hint, hint + step, hint - step, ...
std::vector<double> SearchProbes(const Mechanism& m, double scale) {
  const bool angle = m.InputIsAngle();
  const double step = angle ? 2 * kPi / kAssemblyProbesPerTurn : scale / kSlideProbesPerL;
  const int each_way = angle ? kAssemblyProbesPerTurn / 2 : static_cast<int>(kSlideSpan * kSlideProbesPerL);
  std::vector<double> probes{m.hint.input};
  for (int k = 1; k <= each_way; ++k) {
    probes.push_back(m.hint.input + k * step);
    if (!angle || k < each_way) probes.push_back(m.hint.input - k * step);  // +-180 deg is one probe
  }
  return probes;
}

// The search of AssembleRegular when the hint does not assemble: true with a regular pose in q.
bool SearchPeriod(const Mechanism& m, PositionSolver& solver, double* input, Eigen::VectorXd& q, bool* from_hint) {
  const double scale = solver.system().length_scale();
  const std::vector<double> probes = SearchProbes(m, scale);
  const Eigen::VectorXd hint = solver.HintGuess();
  for (double probe : probes) {
    Eigen::VectorXd x = hint;
    if (solver.AssembleFrom(probe, x).ok() && Regular(solver, x)) {
      *input = probe;
      q = x;
      *from_hint = true;
      return true;
    }
  }
  std::mt19937 random(kSearchSeed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const int n = solver.NumCoordinates();
  for (double probe : probes) {
    for (int s = 0; s < kAssemblyRandomStarts; ++s) {
      // about the hint's pose: links within 2 L of where the hint puts them, at any angle
      Eigen::VectorXd x(n);
      for (int i = 0; i < n; ++i) x(i) = i % 3 == 2 ? kPi * unit(random) : hint(i) + 2.0 * scale * unit(random);
      if (solver.AssembleFrom(probe, x).ok() && Regular(solver, x)) {
        *input = probe;
        q = x;
        *from_hint = false;
        return true;
      }
    }
  }
  return false;
}

}  // namespace

std::string FormatInput(const Mechanism& m, double input) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%s = %.10g", m.drive.input_name.c_str(), m.InputIsAngle() ? RadToDeg(input) : input);
  return std::string(buffer) + (m.InputIsAngle() ? " deg" : "");
}

Assembly AssembleRegular(const Mechanism& m, PositionSolver& solver, const ContinuationOptions& options) {
  Assembly a;
  a.input = m.hint.input;
  a.q.resize(solver.NumCoordinates());
  const SolveReport report = solver.Assemble(a.q);
  if (report.ok() && Regular(solver, a.q)) return a;
  if (!report.ok() && report.status != SolveStatus::kSingular) {
    double input = a.input;
    bool from_hint = true;
    if (SearchPeriod(m, solver, &input, a.q, &from_hint)) {
      a.notes.push_back("the assembly hint does not assemble at " + FormatInput(m, a.input) + " (" + report.message +
                        "); searching " + (m.InputIsAngle() ? "a turn of the input" : "the input around it") +
                        ", koppel assembled at " + FormatInput(m, input) + " from " +
                        (from_hint ? "the hint's pose" : "a seeded random guess") +
                        " and follows that branch (give the assembly hint at a drivable input to choose)");
      a.input = input;
      a.start = AssemblyStart::kSearched;
      return a;
    }
    a.error = "cannot assemble at " + FormatInput(m, a.input) + ": " + report.message + "; nor at any input of " +
              (m.InputIsAngle() ? "a turn (every 5 deg)" : "+-4 L around it") +
              ", from the hint's pose or seeded random guesses";
    return a;
  }
  const double shift = options.branch_window * (m.InputIsAngle() ? 1.0 : solver.system().length_scale());
  for (double side : {+1.0, -1.0}) {
    Eigen::VectorXd q(solver.NumCoordinates());
    if (!solver.AssembleAt(a.input + side * shift, q).ok() || !Regular(solver, q)) continue;
    a.notes.push_back("the assembly input " + FormatInput(m, a.input) +
                      " is a singular position, where the hint cannot choose between the branches that meet; koppel "
                      "assembled at " + FormatInput(m, a.input + side * shift) +
                      " and follows that branch (give the assembly hint at another input to choose)");
    a.q = q;
    a.input += side * shift;
    a.start = AssemblyStart::kBesideHint;
    return a;
  }
  a.error = "cannot assemble at " + FormatInput(m, a.input) + ": the pose there is singular and no regular pose was found beside it";
  return a;
}

MobilityReport CheckMobility(const Mechanism& m) {
  MobilityReport r;
  r.gruebler = AnalyseStructure(m).gruebler_mobility;
  PositionSolver solver(m);
  const Assembly a = AssembleRegular(m, solver);
  if (!a.ok()) {
    if (r.gruebler != 1) {
      r.error = "the Grübler–Kutzbach count gives mobility " + std::to_string(r.gruebler) +
                " but the mechanism has 1 drive, and it cannot be assembled to check whether its joint equations are redundant";
    }
    return r;
  }
  r.assembled = true;
  const Eigen::MatrixXd jc = ScaledJacobian(solver.system(), a.q, false);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jc, Eigen::ComputeFullU);
  const Eigen::VectorXd& s = svd.singularValues();
  int rank = 0;
  for (int i = 0; i < s.size(); ++i) rank += s(i) > kRankThreshold * s(0) ? 1 : 0;
  r.rank_mobility = solver.NumCoordinates() - rank;
  // joints in the left null space of J_c: their equations depend on the others
  const int rows = static_cast<int>(jc.rows());
  if (rank < rows) {
    const Eigen::MatrixXd null = svd.matrixU().rightCols(rows - rank);
    std::vector<double> share(m.joints.size(), 0.0);
    double largest = 0.0;
    for (size_t k = 0; k < m.joints.size(); ++k) {
      share[k] = null.middleRows(2 * static_cast<int>(k), 2).norm();
      largest = std::max(largest, share[k]);
    }
    for (size_t k = 0; k < m.joints.size(); ++k) {
      if (share[k] > kRedundantJointShare * largest) r.redundant.push_back(static_cast<int>(k));
    }
  }
  if (r.rank_mobility != 1) {
    r.error = "the mechanism has mobility " + std::to_string(r.rank_mobility) +
              " (rank of its joint equations at the assembly pose; the Grübler–Kutzbach count gives " +
              std::to_string(r.gruebler) + ") but 1 drive";
    if (r.rank_mobility > r.gruebler && !r.redundant.empty()) {
      r.error += "; the joint equations are dependent where the count did not predict it, in joints " + JointList(m, r.redundant);
    }
    return r;
  }
  if (r.gruebler != 1) {
    r.note = "overconstrained but consistent: the Grübler–Kutzbach count gives mobility " + std::to_string(r.gruebler) +
             ", the joint equations have rank mobility 1 because the equations of joints " + JointList(m, r.redundant) +
             " are dependent (a redundant constraint); accepted";
  }
  return r;
}

}  // namespace koppel
