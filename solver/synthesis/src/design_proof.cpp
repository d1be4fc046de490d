#include "design_proof.hpp"

#include "koppel/analysis/dead_centres.hpp"
#include "koppel/analysis/extremes.hpp"
#include "koppel/core/angles.hpp"

#include <cmath>

namespace koppel {
namespace {

// The search resolution of the full turn: one degree brackets every dead centre of a
// crank-rocker or slider-crank (they are at least a few degrees apart), Newton refines to 1e-12.
constexpr double kTurnStep = DegToRad(1);

SweepOptions FullTurn(double from) {
  SweepOptions turn;
  turn.from = from;
  turn.to = from + 2 * kPi;
  turn.step = kTurnStep;
  return turn;
}

double Mod2Pi(double a) { return std::fmod(std::fmod(a, 2 * kPi) + 2 * kPi, 2 * kPi); }

CrankReanalysis Failed(CrankReanalysis& r, std::string message) {
  r.status = AnalysisStatus::kFailed;
  r.message = std::move(message);
  return r;
}

}  // namespace

CrankReanalysis ReanalyseCrank(const Mechanism& m, int stroke_output, int mu_output, double quiet_input) {
  CrankReanalysis r;
  const DeadCentreReport dc = FindDeadCentres(m, stroke_output, 0, FullTurn(quiet_input));
  if (!dc.sweep.complete()) {
    return Failed(r, "the solver cannot drive the crank through a full turn: " + dc.sweep.message);
  }
  if (!dc.classified || dc.points.size() != 2) {
    return Failed(r, "the solver finds " + std::to_string(dc.points.size()) + " dead centres, not one extended and one folded");
  }
  r.phi0 = Mod2Pi(dc.phi_a - dc.phi_i);
  r.turn = m.OutputIsAngle(stroke_output) ? AngleDifference(dc.s_a, dc.s_i) : dc.s_a - dc.s_i;
  // mu_min over the turn (extremes.hpp: a stationary point at the crank along the frame)
  const OutputExtremes mu = FindOutputExtremes(m, mu_output, 0, FullTurn(quiet_input));
  if (!mu.sweep.complete()) {
    return Failed(r, "the solver cannot drive the crank through a full turn: " + mu.sweep.message);
  }
  if (!Usable(mu.status)) {
    return Failed(r, "the solver finds no smallest transmission angle over the turn: " + mu.message);
  }
  r.mu_min = mu.minimum.value;
  r.mu_min_at = std::remainder(mu.minimum.input, 2 * kPi);
  r.status = AnalysisStatus::kComplete;
  return r;
}

}  // namespace koppel
