// Assembly at a regular pose, and the mobility the constraint equations actually have there.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/position.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

// Where an assembly started: at the hint, beside it (the hint's input is singular), or where the
// search over the input's period found a pose (the hint does not assemble).
enum class AssemblyStart { kHint, kBesideHint, kSearched };

struct Assembly {
  Eigen::VectorXd q;   // the assembled pose
  double input = 0.0;  // where: the hint's input, beside it, or where the search found a pose (see below)
  std::string error;   // empty on success
  std::vector<std::string> notes;
  AssemblyStart start = AssemblyStart::kHint;  // last: aggregate initialisers elsewhere list the fields above
  bool ok() const { return error.empty(); }
};

// Assembles at the mechanism's hint. When the hint's input is itself a singular position (the
// reciprocal condition of J S there is below kSingularRowRcond), the hint cannot say which of the
// branches meeting there it means; the mechanism is then assembled a window's half-width
// (options.branch_window) beside it, where the hint still describes the pose, and a note says so.
// When the hint does not assemble at all (its input lies outside every drivable range, say), the
// input's period is searched: a turn of an R drive in steps of 5 degrees, or +-4 L of a P drive in
// steps of L/8, nearest the hint's input first, each probe from the hint's pose and then from
// seeded random guesses (reproducible). The first regular pose found is the start; a note names
// its input and why (the Assembly's `input` and `start` say the same).
inline constexpr int kAssemblyProbesPerTurn = 72;
inline constexpr int kAssemblyRandomStarts = 8;
Assembly AssembleRegular(const Mechanism& mechanism, PositionSolver& solver, const ContinuationOptions& options = {});

// A drive input as the notes and errors print it: "phi = 30 deg" (an R drive, in degrees) or
// "s = 1.5" (a P drive, in the file's length), to 10 significant digits.
std::string FormatInput(const Mechanism& mechanism, double input);

// The mobility of a mechanism: the Grübler–Kutzbach count, and n - rank of the joints' equations
// at a regular assembled pose (rank by SVD of J_c S, singular values below 1e-9 of the largest
// counting as zero). A one-drive mechanism needs rank mobility 1.
struct MobilityReport {
  int gruebler = 0;
  int rank_mobility = -1;          // -1 when the mechanism could not be assembled
  std::vector<int> redundant;      // joints whose equations are dependent (left null space of J_c)
  bool assembled = false;
  std::string error;               // mobility != 1 drive: what is wrong, naming both numbers
  std::string note;                // accepted, but worth saying (overconstrained and consistent)
  bool ok() const { return error.empty(); }
};
MobilityReport CheckMobility(const Mechanism& mechanism);

}  // namespace koppel
