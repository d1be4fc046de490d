#include "koppel/solver/assembly.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/structure.hpp"
#include "koppel/solver/singular.hpp"

#include <Eigen/SVD>

#include <cmath>
#include <cstdio>

namespace koppel {
namespace {

// An assembled pose with a pivot gauge above this is taken as regular without an SVD.
constexpr double kRegularPivotRatio = 1e-3;
// Singular values of J_c S below this fraction of the largest count as zero for the rank: far
// above roundoff (1e-16), far below the smallest singular value of a regular pose of a real
// mechanism (1e-3 and up).
constexpr double kRankThreshold = 1e-9;
// A joint's share of the left null space below this fraction of the largest counts as zero.
constexpr double kJointShare = 1e-6;

std::string FormatInput(const Mechanism& m, double input) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%s = %.10g", m.drive.input_name.c_str(), m.InputIsAngle() ? RadToDeg(input) : input);
  return std::string(buffer) + (m.InputIsAngle() ? " deg" : "");
}

bool Regular(PositionSolver& solver, const Eigen::VectorXd& q) {
  return solver.PivotRatio() > kRegularPivotRatio || ReciprocalCondition(solver.system(), q) >= kSingularRowRcond;
}

std::string JointList(const Mechanism& m, const std::vector<int>& joints) {
  std::string names;
  for (int j : joints) names += (names.empty() ? "" : ", ") + m.joints[j].name;
  return names;
}

}  // namespace

Assembly AssembleRegular(const Mechanism& m, PositionSolver& solver, const ContinuationOptions& options) {
  Assembly a;
  a.input = m.hint.input;
  a.q.resize(solver.NumCoordinates());
  const SolveReport report = solver.Assemble(a.q);
  if (report.ok() && Regular(solver, a.q)) return a;
  if (!report.ok() && report.status != SolveStatus::kSingular) {
    a.error = "cannot assemble at " + FormatInput(m, a.input) + ": " + report.message;
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
      if (share[k] > kJointShare * largest) r.redundant.push_back(static_cast<int>(k));
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
